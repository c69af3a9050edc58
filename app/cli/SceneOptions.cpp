#include "cli/SceneOptions.h"

#include "cli/ValueChecks.h"

#include <charconv>
#include <cmath>
#include <sstream>
#include <string_view>

#include "core/Error.h"

namespace fm::cli {

namespace {

double parseDouble(std::string_view text, const std::string& option) {
    double value = 0.0;
    const auto result = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || result.ec != std::errc() || result.ptr != text.data() + text.size() ||
        !std::isfinite(value))
        throw Error(option + ": \"" + std::string(text) + "\" is not a finite number");
    return value;
}

// "WxH" -> two numbers.
glm::dvec2 parsePair(const std::string& text, const std::string& option) {
    const auto x = text.find_first_of("xX");
    if (x == std::string::npos)
        throw Error(option + ": expected WIDTHxHEIGHT, got \"" + text + "\"");
    const std::string_view all = text;
    return {parseDouble(all.substr(0, x), option), parseDouble(all.substr(x + 1), option)};
}

}  // namespace

void addSceneOptions(CLI::App* cmd, SceneOptions& o) {
    auto* pose = cmd->add_option("--pose", o.pose,
                                 "Six parameters x,y,z,az,el,rot: CT offset from the isocenter "
                                 "(mm, LPS), source azimuth -180..180 and elevation -90..90, film "
                                 "rotation -90..90 (deg). Default 0,0,0,0,0,0 (AP view). See "
                                 "docs/geometry.md")
                     ->check(kPoseText);
    auto* geometry = cmd->add_option("--geometry", o.geometry,
                                     "Projection geometry JSON file (source, detector) in the "
                                     "volume's world mm, instead of --pose");
    pose->excludes(geometry);
    geometry->excludes(pose);
    cmd->add_option("--size", o.size, "Film pixels WxH for --pose (default 256x256)");
    cmd->add_option("--film", o.film, "Film size WxH in mm for --pose (default 700x700)");
    cmd->add_option("--distance", o.distance,
                    "Source-isocenter and isocenter-film distance in mm for --pose: D (both) "
                    "or S,F (default 500)");
    cmd->add_option("--downsample", o.downsample,
                    "Coarser detector: integer factor, same film area (default 1)")
        ->capture_default_str();
}

SceneSetup sceneSetupFrom(const SceneOptions& o) {
    SceneSetup setup = defaultSceneSetup();
    if (!o.size.empty()) {
        const glm::dvec2 px = parsePair(o.size, "--size");
        if (px.x != std::floor(px.x) || px.y != std::floor(px.y) || px.x < 1 || px.y < 1 ||
            px.x > 16384 || px.y > 16384)
            throw Error("--size: film pixels must be whole numbers 1..16384, got \"" + o.size +
                        "\"");
        setup.filmPixels = glm::ivec2(px);
    }
    if (!o.film.empty()) setup.filmSizeMm = parsePair(o.film, "--film");
    if (!o.distance.empty()) {
        const auto comma = o.distance.find(',');
        const std::string_view all = o.distance;
        if (comma == std::string::npos) {
            setup.sourceToIsocenterMm = setup.isocenterToFilmMm = parseDouble(all, "--distance");
        } else {
            setup.sourceToIsocenterMm = parseDouble(all.substr(0, comma), "--distance");
            setup.isocenterToFilmMm = parseDouble(all.substr(comma + 1), "--distance");
        }
    }
    validateSceneSetup(setup);
    return setup;
}

Pose poseFrom(const SceneOptions& o) {
    return o.pose.empty() ? Pose{} : parsePose(o.pose);
}

ProjectionGeometry geometryFrom(const SceneOptions& o, const glm::dvec3& volumeCenter) {
    ProjectionGeometry g;
    if (o.usesGeometryFile()) {
        // A geometry file fixes everything: scene options would be silently ignored.
        if (!o.size.empty() || !o.film.empty() || !o.distance.empty())
            throw Error("--size, --film and --distance apply to --pose, not to --geometry");
        g = readGeometryFile(o.geometry);
    } else {
        g = sceneGeometry(poseFrom(o), sceneSetupFrom(o), volumeCenter);
    }
    if (o.downsample != 1) g = g.downsampled(o.downsample);
    return g;
}

std::string describeGeometrySource(const SceneOptions& o) {
    std::ostringstream out;
    if (o.usesGeometryFile()) {
        out << "geometry file " << o.geometry;
    } else {
        const SceneSetup s = sceneSetupFrom(o);
        out << "pose " << formatPose(poseFrom(o)) << " (source-isocenter " << s.sourceToIsocenterMm
            << " mm, isocenter-film " << s.isocenterToFilmMm << " mm, film " << s.filmSizeMm.x
            << " x " << s.filmSizeMm.y << " mm, " << s.filmPixels.x << " x " << s.filmPixels.y
            << " px)";
    }
    if (o.downsample != 1) out << ", detector downsampled by " << o.downsample;
    return out.str();
}

}  // namespace fm::cli

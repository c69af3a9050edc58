#include "geometry/Pose.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string_view>
#include <vector>

#include <glm/gtc/constants.hpp>

#include "core/Error.h"
#include "core/WorldLimits.h"
#include "geometry/StrictJson.h"

namespace fm {

namespace {

// Largest film side in pixels (the same limit as the JSON geometry).
constexpr int kMaxFilmPixels = 16384;

constexpr const char* kPoseNames[6] = {"x offset", "y offset",  "z offset",
                                       "azimuth",  "elevation", "rotation"};

using json_detail::formatNumber;

std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
    return s;
}

double parseNumber(std::string_view field, const std::string& name, const std::string& text) {
    field = trim(field);
    std::string_view digits = field;
    if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
    double value = 0.0;
    const auto result = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (digits.empty() || result.ec != std::errc() || result.ptr != digits.data() + digits.size())
        throw Error("pose \"" + text + "\": " + name + " \"" + std::string(field) +
                    "\" is not a number");
    if (!std::isfinite(value)) throw Error("pose \"" + text + "\": " + name + " must be finite");
    return value;
}

void checkRange(double value, double limit, const char* name) {
    if (!std::isfinite(value)) throw Error(std::string("pose ") + name + " must be finite");
    if (value < -limit || value > limit)
        throw Error(std::string("pose ") + name + " " + formatNumber(value) + " deg is outside -" +
                    formatNumber(limit) + ".." + formatNumber(limit));
}

}  // namespace

void validatePose(const Pose& pose) {
    for (int i = 0; i < 3; ++i) {
        if (!std::isfinite(pose.offset[i]))
            throw Error(std::string("pose ") + kPoseNames[i] + " must be finite");
        if (std::abs(pose.offset[i]) > kMaxWorldMm)
            throw Error(std::string("pose ") + kPoseNames[i] + " " + formatNumber(pose.offset[i]) +
                        " mm is beyond " + formatNumber(kMaxWorldMm) + " mm");
    }
    checkRange(pose.azimuthDeg, kAzimuthLimitDeg, "azimuth");
    checkRange(pose.elevationDeg, kElevationLimitDeg, "elevation");
    checkRange(pose.rotationDeg, kRotationLimitDeg, "rotation");
}

Pose parsePose(const std::string& text) {
    std::vector<std::string_view> fields;
    std::string_view rest = text;
    while (true) {
        const auto comma = rest.find(',');
        fields.push_back(rest.substr(0, comma));
        if (comma == std::string_view::npos) break;
        rest.remove_prefix(comma + 1);
    }
    if (fields.size() != 6)
        throw Error("pose \"" + text + "\": expected 6 comma-separated numbers x,y,z,az,el,rot " +
                    "(mm, mm, mm, deg, deg, deg), got " + std::to_string(fields.size()));
    std::array<double, 6> values{};
    for (int i = 0; i < 6; ++i) values[i] = parseNumber(fields[i], kPoseNames[i], text);
    const Pose pose = Pose::fromArray(values);
    validatePose(pose);
    return pose;
}

std::string formatPose(const Pose& pose) {
    const auto a = pose.toArray();
    std::string out;
    for (int i = 0; i < 6; ++i) {
        if (i > 0) out += ',';
        out += formatNumber(a[i]);
    }
    return out;
}

SceneSetup defaultSceneSetup() {
    SceneSetup s;
    // Equal distances as in 2011 (magnification 2 at the isocenter), 1 m source to film.
    s.sourceToIsocenterMm = 500.0;
    s.isocenterToFilmMm = 500.0;
    s.filmPixels = {256, 256};
    // The knee phantom fills its 281 mm field from top to bottom with tissue about 130 mm
    // across; its near surface is magnified up to ~2.3x (500 + 500 over ~440 mm), i.e. up to
    // ~640 mm on the film. 700 mm holds it with margin: 2.73 mm film pixels, 1.37 mm at the
    // isocenter (finer than the phantom's 1.7-2.0 mm voxels).
    s.filmSizeMm = {700.0, 700.0};
    return s;
}

void validateSceneSetup(const SceneSetup& setup) {
    // Positive, finite and at most kMaxWorldMm (core/WorldLimits.h): 1e308 is finite but its
    // arithmetic is not.
    auto positive = [](double v) { return std::isfinite(v) && v > 0.0 && v <= kMaxWorldMm; };
    const std::string range = " must be positive and at most " + formatNumber(kMaxWorldMm) +
                              " mm, got ";
    if (!positive(setup.sourceToIsocenterMm))
        throw Error("scene source-to-isocenter distance" + range +
                    formatNumber(setup.sourceToIsocenterMm) + " mm");
    if (!positive(setup.isocenterToFilmMm))
        throw Error("scene isocenter-to-film distance" + range +
                    formatNumber(setup.isocenterToFilmMm) + " mm");
    for (int i = 0; i < 2; ++i) {
        const char* axis = i == 0 ? "width" : "height";
        if (setup.filmPixels[i] < 1 || setup.filmPixels[i] > kMaxFilmPixels)
            throw Error(std::string("scene film ") + axis + " must be 1.." +
                        std::to_string(kMaxFilmPixels) + " pixels, got " +
                        std::to_string(setup.filmPixels[i]));
        if (!positive(setup.filmSizeMm[i]))
            throw Error(std::string("scene film ") + axis + range +
                        formatNumber(setup.filmSizeMm[i]) + " mm");
    }
}

SceneFrame sceneFrame(double azimuthDeg, double elevationDeg, double rotationDeg) {
    // Anatomical axes in LPS: the default source direction (anterior), patient left, superior.
    const glm::dvec3 anterior{0.0, -1.0, 0.0};
    const glm::dvec3 left{1.0, 0.0, 0.0};
    const glm::dvec3 superior{0.0, 0.0, 1.0};
    const double az = glm::radians(azimuthDeg);
    const double el = glm::radians(elevationDeg);
    const double rot = glm::radians(rotationDeg);
    const double ca = std::cos(az), sa = std::sin(az);
    const double ce = std::cos(el), se = std::sin(el);
    // Spherical basis: s (radial), eAz (increasing azimuth), eEl (increasing elevation).
    // eAz depends on azimuth only and eEl stays a unit vector at el = +-90, so the film axes
    // are defined everywhere, poles included.
    const glm::dvec3 s = ce * ca * anterior + ce * sa * left + se * superior;
    const glm::dvec3 eAz = -sa * anterior + ca * left;
    const glm::dvec3 eEl = -se * ca * anterior - se * sa * left + ce * superior;
    // Unrotated film: columns along eAz (image right), rows along -eEl (image down). Seen from
    // the source this is the beam's-eye view; u x v = -s points along the beam.
    const glm::dvec3 right = eAz;
    const glm::dvec3 down = -eEl;
    const double cr = std::cos(rot), sr = std::sin(rot);
    SceneFrame f;
    f.sourceDirection = s;
    f.filmU = cr * right + sr * down;
    f.filmV = -sr * right + cr * down;
    return f;
}

ProjectionGeometry sceneGeometry(const Pose& pose, const SceneSetup& setup,
                                 const glm::dvec3& volumeCenter) {
    for (int i = 0; i < 3; ++i)
        if (!std::isfinite(pose.offset[i]) || std::abs(pose.offset[i]) > kMaxWorldMm)
            throw Error(std::string("pose ") + kPoseNames[i] + " must be finite, within " +
                        formatNumber(kMaxWorldMm) + " mm");
    if (!std::isfinite(pose.azimuthDeg) || !std::isfinite(pose.elevationDeg) ||
        !std::isfinite(pose.rotationDeg))
        throw Error("pose angles must be finite");
    for (int i = 0; i < 3; ++i)
        if (!std::isfinite(volumeCenter[i]) || std::abs(volumeCenter[i]) > kMaxWorldMm)
            throw Error("volume centre must be finite, within " + formatNumber(kMaxWorldMm) +
                        " mm");
    validateSceneSetup(setup);

    const SceneFrame f = sceneFrame(pose.azimuthDeg, pose.elevationDeg, pose.rotationDeg);
    // The CT centre sits at isocenter + offset; the volume stays put, so the isocenter moves.
    const glm::dvec3 isocenter = volumeCenter - pose.offset;
    ProjectionGeometry g;
    g.source = isocenter + setup.sourceToIsocenterMm * f.sourceDirection;
    const glm::dvec3 filmCenter = isocenter - setup.isocenterToFilmMm * f.sourceDirection;
    DetectorGeometry& d = g.detector;
    d.size = setup.filmPixels;
    d.spacing = setup.filmSizeMm / glm::dvec2(setup.filmPixels);
    d.u = f.filmU;
    d.v = f.filmV;
    d.origin = filmCenter - 0.5 * (d.size.x - 1) * d.spacing.x * d.u -
               0.5 * (d.size.y - 1) * d.spacing.y * d.v;
    return g;
}

Pose poseOfSceneCamera(const ProjectionGeometry& camera, const SceneSetup& setup,
                       const glm::dvec3& volumeCenter) {
    validateSceneSetup(setup);
    const DetectorGeometry& d = camera.detector;
    // u x v = -s: the film's normal points along the beam, away from the source.
    const glm::dvec3 s = -glm::normalize(glm::cross(d.u, d.v));
    Pose pose;
    pose.elevationDeg = glm::degrees(std::asin(std::clamp(s.z, -1.0, 1.0)));
    // s = cos(el) cos(az) A + cos(el) sin(az) L + sin(el) Sup with A = -y, L = x.
    pose.azimuthDeg = std::hypot(s.x, s.y) > 1e-12 ? glm::degrees(std::atan2(s.x, -s.y)) : 0.0;
    const SceneFrame unturned = sceneFrame(pose.azimuthDeg, pose.elevationDeg, 0.0);
    // filmU = cos(rot) right + sin(rot) down, with right and down the unturned film's u and v.
    pose.rotationDeg = glm::degrees(std::atan2(glm::dot(d.u, unturned.filmV), glm::dot(d.u, unturned.filmU)));
    const glm::dvec3 isocenter = camera.source - setup.sourceToIsocenterMm * s;
    pose.offset = volumeCenter - isocenter;
    return pose;
}

}  // namespace fm

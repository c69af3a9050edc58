// `fluoromatch geometry`: the projection geometry JSON for six pose parameters, a checked,
// rewritten copy of a geometry file, or a camera calibration (MayaCam 2.0/1.0, JointTrack) as
// geometry. Both modes of `drr` go through the same code path, so the JSON printed here is
// exactly what `drr --pose` renders. `--out cam.txt` writes a MayaCam 2.0 file instead. With
// --slice: the slice geometry of the MRI slice mode (docs/mri.md), what `slice --pose` samples.
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>

#include "camera/CameraFile.h"
#include "cli/CommandRegistry.h"
#include "cli/SceneOptions.h"
#include "cli/SliceCli.h"
#include "core/Error.h"
#include "geometry/ProjectionGeometry.h"
#include "io/AtomicFile.h"
#include "source/VolumeSource.h"

namespace {

struct GeometryArgs {
    fm::cli::SceneOptions scene;
    std::string volume = fm::kDefaultVolumeSpec;
    std::string center;  // "x,y,z": volume centre given directly
    std::string camera;     // calibration file
    std::string imageSize;  // "WxH" for calibrations without a size (JointTrack)
    std::string out;
    bool slice = false;
    fm::cli::SliceGridArgs grid;  // --size comes from the scene options
};

glm::ivec2 parseImageSize(const std::string& text) {
    const auto x = text.find('x');
    try {
        if (x == std::string::npos) throw fm::Error("");
        std::size_t used1 = 0, used2 = 0;
        const int w = std::stoi(text.substr(0, x), &used1);
        const int h = std::stoi(text.substr(x + 1), &used2);
        if (used1 != x || used2 != text.size() - x - 1 || w < 1 || h < 1) throw fm::Error("");
        return {w, h};
    } catch (const std::exception&) {
        throw fm::Error("--image-size: expected WxH in pixels (e.g. 1024x1024), got \"" + text + "\"");
    }
}

bool wantsMayaCam(const std::string& out) {
    const std::string ext = std::filesystem::path(out).extension().string();
    return ext == ".txt" || ext == ".TXT";
}

glm::dvec3 parseCenter(const std::string& text) {
    // Reuse the pose parser's strict number handling: "x,y,z" + three zero angles.
    try {
        return fm::parsePose(text + ",0,0,0").offset;
    } catch (const fm::Error&) {
        throw fm::Error("--center: expected three numbers x,y,z (mm), got \"" + text + "\"");
    }
}

fm::ProjectionGeometry geometryOfScene(const GeometryArgs& a) {
    glm::dvec3 center{0.0};
    if (!a.scene.usesGeometryFile()) {
        if (!a.center.empty()) {
            center = parseCenter(a.center);
        } else {
            const fm::Volume v = fm::loadVolume(a.volume);
            center = v.center();
        }
    }
    return fm::cli::geometryFrom(a.scene, center);
}

void runSliceGeometry(const GeometryArgs& a) {
    if (a.scene.usesGeometryFile() || !a.scene.film.empty() || !a.scene.distance.empty() ||
        a.scene.downsample != 1 || !a.camera.empty())
        throw fm::Error("--slice takes --pose, --size, --spacing and --thickness; --geometry, "
                        "--camera, --film, --distance and --downsample belong to the X-ray scene");
    fm::cli::SliceGridArgs grid = a.grid;
    grid.size = a.scene.size;
    const fm::Pose pose = fm::cli::poseFrom(a.scene);
    fm::SliceSetup setup;
    glm::dvec3 center{0.0};
    if (!a.center.empty()) {
        center = parseCenter(a.center);
        setup = fm::cli::sliceSetupFrom(grid);
    } else {
        const fm::Volume v = fm::loadVolume(a.volume);
        center = v.center();
        setup = fm::cli::sliceSetupFrom(grid, v);
    }
    const std::string json = fm::sliceGeometryToJson(fm::sliceGeometry(pose, setup, center));
    if (a.out.empty()) {
        std::cout << json;
        return;
    }
    fm::io::writeFileAtomically(a.out, json);
    std::fprintf(stderr, "wrote %s (slice at pose %s)\n", a.out.c_str(), fm::formatPose(pose).c_str());
}

void runGeometry(const GeometryArgs& a) {
    if (a.slice) return runSliceGeometry(a);
    if (!a.grid.spacing.empty() || a.grid.thickness != 0.0)
        throw fm::Error("--spacing and --thickness need --slice (the X-ray scene has --film)");
    if (!a.imageSize.empty() && a.camera.empty())
        throw fm::Error("--image-size applies to --camera only");
    fm::ProjectionGeometry g;
    std::string source;
    if (!a.camera.empty()) {
        std::optional<glm::ivec2> size;
        if (!a.imageSize.empty()) size = parseImageSize(a.imageSize);
        const fm::CameraReadResult r = [&] {
            try {
                return fm::readCameraFile(a.camera, size);
            } catch (const fm::CalibrationNeedsImageSize&) {
                throw fm::Error(a.camera + ": a JointTrack calibration holds no image size: give "
                                           "the radiographs' size with --image-size WxH");
            }
        }();
        for (const auto& w : r.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
        if (size) fm::checkImageSize(r.camera, a.camera, size->x, size->y, "--image-size");
        g = fm::toProjectionGeometry(r.camera, a.camera);
        source = r.format + " calibration " + a.camera;
    } else {
        g = geometryOfScene(a);
        source = fm::cli::describeGeometrySource(a.scene);
    }
    if (!a.out.empty() && wantsMayaCam(a.out)) {
        fm::writeMayaCam2(a.out, fm::cameraFromGeometry(g, source));
        std::fprintf(stderr, "wrote %s (MayaCam 2.0, from %s)\n", a.out.c_str(), source.c_str());
        return;
    }
    const std::string json = fm::geometryToJson(g);
    if (a.out.empty()) {
        std::cout << json;
        return;
    }
    fm::io::writeFileAtomically(a.out, std::vector<std::uint8_t>(json.begin(), json.end()));
    std::fprintf(stderr, "wrote %s (%s)\n", a.out.c_str(), source.c_str());
}

FM_REGISTER_COMMAND("geometry", 30, [](CLI::App& app) {
    auto* cmd = app.add_subcommand(
        "geometry",
        "Print the projection geometry JSON (source, detector in world mm) for a pose, or check "
        "and rewrite a geometry file");
    auto args = std::make_shared<GeometryArgs>();
    fm::cli::addSceneOptions(cmd, args->scene);
    auto* volume = cmd->add_option("--volume", args->volume,
                                   "Volume whose centre the scene is built around (CT file, "
                                   "DICOM folder or phantom:NAME)")
                       ->capture_default_str();
    auto* center = cmd->add_option("--center", args->center,
                                   "Volume centre x,y,z in mm instead of loading --volume");
    center->excludes(volume);
    // A geometry file fixes source and detector in world mm: a volume centre would be
    // ignored, so naming one with --geometry is refused rather than silently dropped.
    if (auto* geometryFile = cmd->get_option_no_throw("--geometry")) {
        volume->excludes(geometryFile);
        center->excludes(geometryFile);
    }
    auto* camera = cmd->add_option("--camera", args->camera,
                                   "Camera calibration (MayaCam 2.0 .txt, MayaCam 1.0 .csv, "
                                   "JointTrack JT_INTCALIB, geometry JSON) to print as geometry");
    for (const char* other : {"--pose", "--geometry", "--size", "--film", "--distance"})
        if (auto* o = cmd->get_option_no_throw(other)) camera->excludes(o);
    camera->excludes(volume);
    camera->excludes(center);
    cmd->add_option("--image-size", args->imageSize,
                    "Image size WxH of the radiographs, for calibrations that hold none "
                    "(JointTrack); checked against the file's otherwise");
    cmd->add_option("--out", args->out,
                    "Write the JSON to this file instead of printing it; a .txt name writes a "
                    "MayaCam 2.0 calibration (Autoscoper) instead");
    cmd->add_flag("--slice", args->slice,
                  "The MRI slice mode: print the slice geometry (origin, u, v, spacing, size, "
                  "thickness) of --pose instead (see docs/mri.md)");
    fm::cli::addSliceGridOptions(cmd, args->grid, false);
    cmd->callback([args] { runGeometry(*args); });
    return cmd;
});

}  // namespace

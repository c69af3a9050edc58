// `fluoromatch geometry`: the projection geometry JSON for six pose parameters (or a checked,
// rewritten copy of a geometry file). Both modes of `drr` go through the same code path, so the
// JSON printed here is exactly what `drr --pose` renders.
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>

#include "cli/CommandRegistry.h"
#include "cli/SceneOptions.h"
#include "core/Error.h"
#include "geometry/ProjectionGeometry.h"
#include "io/AtomicFile.h"
#include "volume/VolumeSource.h"

namespace {

struct GeometryArgs {
    fm::cli::SceneOptions scene;
    std::string volume = fm::kDefaultVolumeSpec;
    std::string center;  // "x,y,z": volume centre given directly
    std::string out;
};

glm::dvec3 parseCenter(const std::string& text) {
    // Reuse the pose parser's strict number handling: "x,y,z" + three zero angles.
    try {
        return fm::parsePose(text + ",0,0,0").offset;
    } catch (const fm::Error&) {
        throw fm::Error("--center: expected three numbers x,y,z (mm), got \"" + text + "\"");
    }
}

void runGeometry(const GeometryArgs& a) {
    glm::dvec3 center{0.0};
    if (!a.scene.usesGeometryFile()) {
        if (!a.center.empty()) {
            center = parseCenter(a.center);
        } else {
            const fm::Volume v = fm::loadVolume(a.volume);
            center = v.center();
        }
    }
    const fm::ProjectionGeometry g = fm::cli::geometryFrom(a.scene, center);
    const std::string json = fm::geometryToJson(g);
    if (a.out.empty()) {
        std::cout << json;
        return;
    }
    fm::io::writeFileAtomically(a.out, std::vector<std::uint8_t>(json.begin(), json.end()));
    std::fprintf(stderr, "wrote %s (%s)\n", a.out.c_str(),
                 fm::cli::describeGeometrySource(a.scene).c_str());
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
    cmd->add_option("--out", args->out, "Write the JSON to this file instead of printing it");
    cmd->callback([args] { runGeometry(*args); });
    return cmd;
});

}  // namespace

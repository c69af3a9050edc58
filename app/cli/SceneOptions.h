#pragma once
// Command-line options shared by the commands that need a projection geometry (drr, geometry):
// either the 2011 six-parameter scene (--pose plus optional --size/--film/--distance) or a
// general geometry file (--geometry g.json). Both end in one fm::ProjectionGeometry.
#include <memory>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>
#include <glm/glm.hpp>

#include "geometry/Pose.h"
#include "geometry/ProjectionGeometry.h"

namespace fm::cli {

struct SceneOptions {
    std::string pose;      // "x,y,z,az,el,rot"; empty = not given
    std::string geometry;  // JSON file; empty = not given
    std::string size;      // "WxH" film pixels
    std::string film;      // "WxH" film size in mm
    std::string distance;  // "D" (both) or "S,F": source-isocenter, isocenter-film (mm)
    int downsample = 1;

    bool usesGeometryFile() const { return !geometry.empty(); }
};

// Adds --pose, --geometry, --size, --film, --distance and --downsample to `cmd`.
void addSceneOptions(CLI::App* cmd, SceneOptions& options);

// The scene set-up after --size/--film/--distance. Throws fm::Error on malformed values.
SceneSetup sceneSetupFrom(const SceneOptions& options);

// The pose from --pose (all zeros, the AP view, when not given).
Pose poseFrom(const SceneOptions& options);

// The geometry the options describe. `volumeCenter` is used by the six-parameter scene only
// (the volume stays where its file puts it). Throws fm::Error when scene options are mixed
// with --geometry.
ProjectionGeometry geometryFrom(const SceneOptions& options, const glm::dvec3& volumeCenter);

// One line describing where the geometry came from (for the console).
std::string describeGeometrySource(const SceneOptions& options);

}  // namespace fm::cli

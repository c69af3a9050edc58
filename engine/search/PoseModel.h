#pragma once
// How the six pose parameters become a projection geometry, in the volume's world frame.
//   scene model: the 2011 scene (sceneGeometry): the usual case, reference DRRs and the app.
//   fixed-geometry model: a calibrated reference image comes with its own ProjectionGeometry
//     (g.json). The pose then moves that camera rigidly exactly as the scene moves its camera
//     between the zero pose and `pose`: the zero pose reproduces g.json, and every parameter
//     keeps its meaning (offset in mm, azimuth/elevation/rotation in degrees about the CT centre).
#include <functional>

#include "geometry/Pose.h"
#include "geometry/ProjectionGeometry.h"

namespace fm {

using PoseModel = std::function<ProjectionGeometry(const Pose&)>;

PoseModel scenePoseModel(const SceneSetup& setup, const glm::dvec3& volumeCenter);

// Throws fm::Error if `geometry` is invalid.
PoseModel fixedGeometryPoseModel(const ProjectionGeometry& geometry, const SceneSetup& setup,
                                 const glm::dvec3& volumeCenter);

// A sub-detector: the pixels [col0, col0+cols) x [row0, row0+rows) of `g`, as a geometry of its
// own (origin moved to the first pixel). Rendering it gives exactly those pixels of the full
// DRR. Throws fm::Error if the rectangle is empty or leaves the detector.
ProjectionGeometry cropDetector(const ProjectionGeometry& g, int col0, int row0, int cols,
                                int rows);

}  // namespace fm

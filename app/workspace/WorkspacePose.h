#pragma once
// The six pose controls of the workspace: one object's pose as six numbers in a camera's frame
// or in the world, through the engine's ObjectPoseParameterization (one formula for both):
//   camera  x, y: where the object's pivot (the centre of its bounds) sits along the film's u
//           and v axes, from the source (mm); depth: its distance from the source along the
//           view (mm); about u, about v, about view: rotations (deg) about axes through the
//           pivot parallel to u, v and the view, relative to the reference orientation,
//           composed R = R_view R_u R_v (JointTrack's 3-1-2 order).
//   world   x, y, z: the pivot in the world (mm); about x, about y, about z: rotations about the
//           world axes through the pivot, composed R = R_z R_x R_y.
// The world is "a camera" whose source is the world origin, film axes world x and y and view
// +z (worldAxesCamera): the same numbers are then the world's.
#include <array>

#include "geometry/ProjectionGeometry.h"
#include "scene/ObjectPoseParameterization.h"
#include "state/AppState.h"
#include "track/TrialScene.h"
#include "workspace/WorkspaceState.h"

namespace fm::app {

// The world's axes as a camera frame (source at the origin, u = x, v = y, view = +z).
ProjectionGeometry worldAxesCamera();

// The parameterization of `object`'s pose in `frame` (camera `camera`), angles 0 at `reference`.
ObjectPoseParameterization controlParameterization(const Scene& scene, int object, PoseFrame frame,
                                                   int camera, const RigidTransform& reference);

// Names, units and slider ranges: translations +-100 mm around `centre` (rounded to 10 mm),
// angles -180..180 deg.
std::array<ParameterSpec, 6> controlSpecs(PoseFrame frame, const std::array<double, 6>& centre);

// Rebases `controls` on `pose` (the reference; angles 0; ranges centred there).
void rebaseControls(PoseControls& controls, const Scene& scene, int object, int frameIndex,
                    PoseFrame frame, int camera, const RigidTransform& pose);

// The pose the controls' values give.
RigidTransform poseFromControls(const PoseControls& controls, const Scene& scene);

}  // namespace fm::app

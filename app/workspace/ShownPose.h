#pragma once
// Where the workspace shows an object in a frame. WorkspaceState::poses holds only the poses
// that were set (a keyframe, an edit, Solve, Track, a load): those are saved and plotted. A
// frame without one shows the object where the nearest earlier set pose put it (else the nearest
// later one, else its placement), derived here and never stored, so playing through untracked
// frames leaves their .tra rows NaN.
#include <optional>
#include <vector>

#include "scene/RigidTransform.h"
#include "workspace/WorkspaceState.h"

namespace fm::app {

std::optional<RigidTransform> shownPose(const WorkspaceState& state, int frame, int object);
std::vector<std::optional<RigidTransform>> shownPoses(const WorkspaceState& state, int frame);
// True when `object` has a pose of its own in `frame` (not one carried over).
bool hasSetPose(const WorkspaceState& state, int frame, int object);

}  // namespace fm::app

#pragma once
// Where tracking starts a frame: from the poses already found (or given) for other frames.
//   previous     the pose of the nearest tracked frame before this one (in tracking order)
//   extrapolate  constant velocity from the two before (translation linear in the frame number,
//                rotation at constant angular velocity); previous if only one is known
//   keyframes    interpolation between the keyframes around the frame (translation linear,
//                rotation by slerp of quaternions); the nearest keyframe outside their span
// Poses are worldFromVolume (any volume frame, the same for all).
#include <map>
#include <optional>
#include <string>

#include "scene/RigidTransform.h"

namespace fm {

enum class InitMode { Previous, Extrapolate, Keyframes };

// "previous", "extrapolate" or "keyframes"; fm::Error otherwise.
InitMode parseInitMode(const std::string& text);
const char* toString(InitMode mode);

// Rigid interpolation between a (s = 0) and b (s = 1): translation linear, rotation along the
// shortest arc (s outside [0, 1] extrapolates along the same arc).
RigidTransform interpolate(const RigidTransform& a, const RigidTransform& b, double s);

// The start pose of `frame`. `tracked` holds frame -> pose of the frames done so far;
// `keyframes` the user's keyframes; `backwards` when tracking runs towards lower frames (so
// "before" means higher frame numbers). Empty when nothing is known to start from.
std::optional<RigidTransform> initialGuess(InitMode mode, int frame,
                                           const std::map<int, RigidTransform>& tracked,
                                           const std::map<int, RigidTransform>& keyframes,
                                           bool backwards);

}  // namespace fm

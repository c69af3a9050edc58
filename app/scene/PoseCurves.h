#pragma once
// The six curves of a bone's pose over a trial's frames, for the trial view's plot, so that
// jumps are visible: the .tra pose (Autoscoper's volume frame, what Autoscoper plots) as
// x, y, z (mm) and yaw, pitch, roll (deg) with R = Rz(yaw) Ry(pitch) Rx(roll)
// (xyzyprFromTransform). NaN where the frame has no pose. Each angle is unwrapped: moved by a
// multiple of 360 deg to lie within 180 deg of the same angle at the previous frame that has a
// pose, so the +-180 deg seam is not drawn as a jump while a real jump stays one.
#include <array>
#include <string>
#include <vector>

#include "scene/BonePoses.h"
#include "track/TrialScene.h"

namespace fm::app {

struct PoseCurves {
    static constexpr int kCount = 6;
    std::array<std::vector<float>, kCount> values;  // [curve][frame]
    static const char* name(int curve);             // "x (mm)", ..., "roll (deg)"
    // The finite values' min and max of one curve (0, 0 when it has none).
    std::array<float, 2> range(int curve) const;
};

PoseCurves poseCurves(const TrialScene& trial, const std::string& bone, const BonePoses& poses);

}  // namespace fm::app

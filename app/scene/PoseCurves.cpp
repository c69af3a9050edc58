#include "scene/PoseCurves.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "pose/AutoscoperTra.h"

namespace fm::app {

const char* PoseCurves::name(int curve) {
    static const char* names[kCount] = {"x (mm)",     "y (mm)",      "z (mm)",
                                        "yaw (deg)", "pitch (deg)", "roll (deg)"};
    return curve >= 0 && curve < kCount ? names[curve] : "?";
}

std::array<float, 2> PoseCurves::range(int curve) const {
    float lo = std::numeric_limits<float>::infinity(), hi = -lo;
    for (float v : values.at(static_cast<std::size_t>(curve)))
        if (std::isfinite(v)) {
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
    if (lo > hi) return {0.0f, 0.0f};
    return {lo, hi};
}

PoseCurves poseCurves(const TrialScene& trial, const std::string& bone, const BonePoses& poses) {
    PoseCurves c;
    const auto n = static_cast<std::size_t>(poses.frameCount());
    for (auto& v : c.values) v.assign(n, std::numeric_limits<float>::quiet_NaN());
    double previous[PoseCurves::kCount] = {};
    bool havePrevious = false;
    for (std::size_t f = 0; f < n; ++f) {
        const auto pose = poses.pose(static_cast<int>(f));
        if (!pose) continue;
        double v[PoseCurves::kCount];
        xyzyprFromTransform(traPoseFromObject(trial, bone, *pose), v);
        for (int a = 3; a < PoseCurves::kCount && havePrevious; ++a)
            v[a] -= 360.0 * std::round((v[a] - previous[a]) / 360.0);
        for (int i = 0; i < PoseCurves::kCount; ++i) {
            c.values[static_cast<std::size_t>(i)][f] = static_cast<float>(v[i]);
            previous[i] = v[i];
        }
        havePrevious = true;
    }
    return c;
}

}  // namespace fm::app

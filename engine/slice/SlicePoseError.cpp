#include "slice/SlicePoseError.h"

#include <algorithm>
#include <cmath>

#include "core/Error.h"

namespace fm {

TargetRegistrationError sliceTargetError(const SliceGeometry& a, const SliceGeometry& b,
                                         const std::vector<glm::dvec3>& points) {
    if (points.empty()) throw Error("slice mTRE: no target points");
    TargetRegistrationError e;
    for (const glm::dvec3& p : points) {
        const glm::dvec3 d = toSliceFrame(a, p) - toSliceFrame(b, p);
        const double len = glm::length(d);
        e.meanMm += len;
        e.meanInPlaneMm += std::hypot(d.x, d.y);
        e.meanDepthMm += std::abs(d.z);
        e.maxMm = std::max(e.maxMm, len);
    }
    const double n = double(points.size());
    e.meanMm /= n;
    e.meanInPlaneMm /= n;
    e.meanDepthMm /= n;
    return e;
}

TargetRegistrationError sliceTargetError(const Pose& a, const Pose& b, const SliceSetup& setup,
                                         const glm::dvec3& volumeCenter,
                                         const std::vector<glm::dvec3>& points) {
    return sliceTargetError(sliceGeometry(a, setup, volumeCenter),
                            sliceGeometry(b, setup, volumeCenter), points);
}

std::vector<glm::dvec3> foregroundTargetPoints(const Volume& volume, std::size_t maxPoints) {
    if (volume.values.empty()) throw Error("foreground targets: the volume holds no values");
    double sum = 0.0;
    float lo = volume.values.front(), hi = lo;
    for (float v : volume.values) {
        sum += v;
        lo = std::min(lo, v);
        hi = std::max(hi, v);
    }
    if (!(hi > lo))
        throw Error("foreground targets: " + volume.meta.source + " is constant: no foreground");
    const double mean = sum / double(volume.values.size());
    // Strictly above the mean: the next float up, as boneTargetPoints takes ">= threshold".
    return boneTargetPoints(volume, std::nextafter(mean, double(hi) + 1.0), maxPoints);
}

}  // namespace fm

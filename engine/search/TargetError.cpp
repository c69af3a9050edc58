#include "search/TargetError.h"

#include <algorithm>
#include <cmath>

#include "core/Error.h"
#include "match/PoseError.h"

namespace fm {

std::vector<glm::dvec3> registrationTargets(const Volume& volume, double threshold) {
    const bool anyBone = std::any_of(volume.values.begin(), volume.values.end(),
                                     [threshold](float v) { return v >= threshold; });
    if (anyBone) return boneTargetPoints(volume, threshold);
    std::vector<glm::dvec3> targets;
    const glm::dvec3 h = 0.25 * glm::dvec3(volume.dims - 1);
    const glm::dvec3 ci = volume.worldToIndex(volume.center());
    for (int corner = 0; corner < 8; ++corner) {
        const glm::dvec3 sign((corner & 1) ? 1 : -1, (corner & 2) ? 1 : -1, (corner & 4) ? 1 : -1);
        targets.push_back(volume.indexToWorld(ci + sign * h));
    }
    return targets;
}

TargetError targetError(const ProjectionGeometry& truth, const ProjectionGeometry& found,
                        const std::vector<glm::dvec3>& targets) {
    if (targets.empty()) throw Error("target registration error: no targets");
    TargetError e;
    for (const glm::dvec3& p : targets) {
        const glm::dvec3 d = toCameraFrame(found, p) - toCameraFrame(truth, p);
        const double total = glm::length(d);
        e.meanMm += total;
        e.inPlaneMm += std::sqrt(d.x * d.x + d.y * d.y);
        e.outOfPlaneMm += std::abs(d.z);
        e.maxMm = std::max(e.maxMm, total);
    }
    const double n = double(targets.size());
    e.meanMm /= n;
    e.inPlaneMm /= n;
    e.outOfPlaneMm /= n;
    return e;
}

std::array<double, 6> parameterError(const Pose& truth, const Pose& found) {
    return poseDifference(truth, found);
}

}  // namespace fm

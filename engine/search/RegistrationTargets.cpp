#include "search/RegistrationTargets.h"

#include <algorithm>

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

}  // namespace fm

#pragma once
// How far apart two poses of one bone are: the distance its point `c` moves, and the angle of
// the rotation between them.
#include <algorithm>
#include <cmath>

#include "scene/RigidTransform.h"

namespace fm::test {

inline double centreError(const RigidTransform& a, const RigidTransform& b, const glm::dvec3& c) {
    return glm::length(a.applyToPoint(c) - b.applyToPoint(c));
}

inline double angleErrorDeg(const RigidTransform& a, const RigidTransform& b) {
    const glm::dmat3 d = a.rotation * glm::transpose(b.rotation);
    const double cosine = std::clamp((d[0][0] + d[1][1] + d[2][2] - 1.0) / 2.0, -1.0, 1.0);
    return glm::degrees(std::acos(cosine));
}

}  // namespace fm::test

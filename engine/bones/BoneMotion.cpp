#include "bones/BoneMotion.h"

#include <algorithm>
#include <cmath>

#include "core/Error.h"

namespace fm {

RigidTransform boneMotionTransform(const BoneMotion& m, const glm::dvec3& pivot) {
    for (double v : m)
        if (!std::isfinite(v)) throw Error("bone motion: a number is not finite");
    return RigidTransform::translate({m[0], m[1], m[2]}) * rotationAbout({0, 0, 1}, m[5], pivot) *
           rotationAbout({0, 1, 0}, m[4], pivot) * rotationAbout({1, 0, 0}, m[3], pivot);
}

BoneMotion boneMotionOf(const RigidTransform& t, const glm::dvec3& pivot) {
    t.validate("bone pose");
    // R = Rz(c) Ry(b) Rx(a); glm is column-major: R(row, col) = rotation[col][row].
    const glm::dmat3& r = t.rotation;
    const double b = std::asin(std::clamp(-r[0][2], -1.0, 1.0));
    const double a = std::atan2(r[1][2], r[2][2]);
    const double c = std::atan2(r[0][1], r[0][0]);
    // t = shift + pivot - R pivot.
    const glm::dvec3 shift = t.translation - pivot + r * pivot;
    return {shift.x, shift.y, shift.z, glm::degrees(a), glm::degrees(b), glm::degrees(c)};
}

}  // namespace fm

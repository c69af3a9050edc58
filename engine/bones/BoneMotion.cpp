#include "bones/BoneMotion.h"

#include <cmath>

#include "core/Error.h"

namespace fm {

RigidTransform boneMotionTransform(const BoneMotion& m, const glm::dvec3& pivot) {
    for (double v : m)
        if (!std::isfinite(v)) throw Error("bone motion: a number is not finite");
    return RigidTransform::translate({m[0], m[1], m[2]}) * rotationAbout({0, 0, 1}, m[5], pivot) *
           rotationAbout({0, 1, 0}, m[4], pivot) * rotationAbout({1, 0, 0}, m[3], pivot);
}

}  // namespace fm

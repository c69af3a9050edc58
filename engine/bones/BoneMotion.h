#pragma once
// Six numbers that move a bone in the world, as a user or a test names a motion: turns about
// the world x, y and z axes through a pivot (degrees, right hand, applied x first, then y, then
// z), then a shift along x, y and z (mm). Order: tx, ty, tz, rx, ry, rz. Used by the app's bone
// sliders and `register --bone-motion`. For the knee phantom with the pivot on the flexion axis,
// (0, 0, 0, a, 0, 0) is the tibia's pose of a knee flexed by a (kneeBonePoses).
#include <array>

#include <glm/glm.hpp>

#include "scene/RigidTransform.h"

namespace fm {

using BoneMotion = std::array<double, 6>;

// worldFromObject of a bone (identity = where the CT has it) moved by `motion` about `pivot`
// (world mm). Throws fm::Error if a number is not finite.
RigidTransform boneMotionTransform(const BoneMotion& motion, const glm::dvec3& pivot);

// The motion whose transform is `worldFromObject` (the inverse of boneMotionTransform; the
// turn about y in -90..90 deg, exact away from +-90). Throws fm::Error for a non-rigid pose.
BoneMotion boneMotionOf(const RigidTransform& worldFromObject, const glm::dvec3& pivot);

}  // namespace fm

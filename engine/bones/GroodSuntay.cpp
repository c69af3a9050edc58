#include "bones/GroodSuntay.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/Error.h"

namespace fm {
namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

// Raw angles and translations along e1, e2, e3, right-handed about the frame axes (X left,
// Y posterior, Z proximal); the clinical signs depend on the side.
struct RawJoint {
    double a, b, c;     // about e1, e2, e3 (deg)
    double q1, q2, q3;  // along e1, e2, e3 (mm)
};

RawJoint toRaw(const KneeAngles& k, BodySide side) {
    const double s = side == BodySide::Right ? 1.0 : -1.0;
    // Right knee: +X is medial. +b tilts the tibia's proximal axis to +X, its distal end to
    // -X: lateral, valgus. +c turns the front (-Y) towards +X: medial, internal.
    return {k.flexionDeg, -s * k.varusDeg, s * k.internalRotationDeg,
            s * k.medialShiftMm, -k.anteriorDrawerMm, -k.distractionMm};
}

}  // namespace

KneeAngles groodSuntayAngles(const RigidTransform& femurFromTibia, BodySide side) {
    femurFromTibia.validate("knee pose");
    const glm::dvec3 e1{1.0, 0.0, 0.0};
    const glm::dvec3 e3 = femurFromTibia.rotation[2];
    const glm::dvec3 floating = glm::cross(e3, e1);
    constexpr double kGimbalLock = 1e-9;
    if (glm::length(floating) < kGimbalLock)
        throw Error("knee angles: the tibia's long axis lies along the femur's mediolateral axis");
    const glm::dvec3 e2 = glm::normalize(floating);
    const glm::dvec3 femurY{0.0, 1.0, 0.0};
    const glm::dvec3 tibiaY = femurFromTibia.rotation[1];
    RawJoint r{};
    r.a = std::atan2(glm::dot(glm::cross(femurY, e2), e1), glm::dot(femurY, e2)) * kDeg;
    r.b = std::asin(std::clamp(glm::dot(e1, e3), -1.0, 1.0)) * kDeg;
    r.c = std::atan2(glm::dot(glm::cross(e2, tibiaY), e3), glm::dot(e2, tibiaY)) * kDeg;
    const glm::dvec3 h = femurFromTibia.translation;
    // Coordinates of h in the (non-orthogonal) basis e1, e2, e3: h = q1 e1 + q2 e2 + q3 e3.
    const glm::dvec3 q = glm::inverse(glm::dmat3(e1, e2, e3)) * h;
    r.q1 = q.x;
    r.q2 = q.y;
    r.q3 = q.z;
    const double s = side == BodySide::Right ? 1.0 : -1.0;
    KneeAngles k;
    k.flexionDeg = r.a;
    k.varusDeg = -s * r.b;
    k.internalRotationDeg = s * r.c;
    k.medialShiftMm = s * r.q1;
    k.anteriorDrawerMm = -r.q2;
    k.distractionMm = -r.q3;
    return k;
}

RigidTransform poseFromGroodSuntay(const KneeAngles& angles, BodySide side) {
    const RawJoint r = toRaw(angles, side);
    const glm::dvec3 o(0.0);
    const RigidTransform rot = rotationAbout({1, 0, 0}, r.a, o) * rotationAbout({0, 1, 0}, r.b, o) *
                               rotationAbout({0, 0, 1}, r.c, o);
    const glm::dvec3 e1{1.0, 0.0, 0.0};
    const glm::dvec3 e3 = rot.rotation[2];
    const glm::dvec3 e2 = glm::normalize(glm::cross(e3, e1));
    RigidTransform pose = rot;
    pose.translation = r.q1 * e1 + r.q2 * e2 + r.q3 * e3;
    return pose;
}

}  // namespace fm

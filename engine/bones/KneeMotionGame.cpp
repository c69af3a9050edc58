#include "bones/KneeMotionGame.h"

#include "bones/BoneMotionGame.h"

#include <cmath>
#include <string>

#include "core/Error.h"
#include "core/Random.h"

namespace fm {

KneeAngles kneeAnglesOf(const KneeJoint& joint, const RigidTransform& worldFromFemur,
                        const RigidTransform& worldFromTibia) {
    const RigidTransform femurAnatomicalFromTibiaAnatomical =
        (worldFromFemur * joint.femurFromAnatomical).inverse() * worldFromTibia *
        joint.tibiaFromAnatomical;
    return groodSuntayAngles(femurAnatomicalFromTibiaAnatomical, joint.side);
}

std::array<double, 6> kneeAngleArray(const KneeAngles& a) {
    return {a.medialShiftMm, a.anteriorDrawerMm, a.distractionMm,
            a.flexionDeg,    a.varusDeg,         a.internalRotationDeg};
}

KneeAngles kneeAnglesFromArray(const std::array<double, 6>& a) {
    KneeAngles k;
    k.medialShiftMm = a[0];
    k.anteriorDrawerMm = a[1];
    k.distractionMm = a[2];
    k.flexionDeg = a[3];
    k.varusDeg = a[4];
    k.internalRotationDeg = a[5];
    return k;
}

const char* kneeComponentName(int index) {
    static const char* kNames[] = {"medial shift", "anterior drawer", "distraction",
                                   "flexion",      "varus",           "internal rotation"};
    if (index < 0 || index >= 6) throw Error("knee: no component " + std::to_string(index));
    return kNames[index];
}

BoneMotion drawKneeMotion(std::uint64_t seed, Difficulty difficulty) {
    Rng rng(seed);
    BoneMotion m{};
    switch (difficulty) {
        case Difficulty::Easy:
            m[3] = rng.uniform(10.0, 60.0);
            break;
        case Difficulty::Medium:
            m[3] = rng.uniform(10.0, 60.0);
            m[4] = rng.uniform(-5.0, 5.0);
            m[5] = rng.uniform(-10.0, 10.0);
            break;
        case Difficulty::Hard:
            m[3] = rng.uniform(5.0, 90.0);
            m[4] = rng.uniform(-8.0, 8.0);
            m[5] = rng.uniform(-15.0, 15.0);
            for (int a = 0; a < 3; ++a) m[a] = rng.uniform(-4.0, 4.0);
            break;
    }
    // On the sliders' 0.1 grid, so that the answer can be typed exactly.
    for (double& v : m) v = std::round(v * 10.0) / 10.0;
    return m;
}

MatchVerdict judgeKneeMotion(const KneeAngles& reference, const KneeAngles& user,
                             double tibiaMtreMm, const MatchTolerances& tolerances) {
    return judgeNamedNumbers(kneeAngleArray(reference), kneeAngleArray(user), tibiaMtreMm,
                             kneeComponentName, tolerances);
}

}  // namespace fm

#include "bones/BoneMotionGame.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/Error.h"
#include "core/Random.h"

namespace fm {

double boneMotionSpread(Difficulty difficulty) {
    switch (difficulty) {
        case Difficulty::Easy:
            return 5.0;
        case Difficulty::Medium:
            return 7.0;
        case Difficulty::Hard:
            break;
    }
    return 10.0;
}

BoneMotion drawBoneMotion(std::uint64_t seed, Difficulty difficulty) {
    const MatchTolerances tolerances;
    const double spread = boneMotionSpread(difficulty);
    Rng rng(seed);
    BoneMotion m{};
    for (double& v : m) v = std::round(rng.uniform(-spread, spread) * 10.0) / 10.0;
    // At least one number clearly off, so that the unmoved bone is never a match: the one
    // furthest off is pushed out to between 2 tolerances and the spread, keeping its sign.
    int worst = 0;
    for (int k = 1; k < 6; ++k)
        if (std::abs(m[k]) / tolerances.forParameter(k) >
            std::abs(m[worst]) / tolerances.forParameter(worst))
            worst = k;
    const double floor = 2.0 * tolerances.forParameter(worst) + 0.1;
    if (std::abs(m[worst]) < floor) m[worst] = std::copysign(std::min(floor, spread), m[worst]);
    return m;
}

const char* boneMotionComponentName(int index) {
    static const char* kNames[] = {"x shift", "y shift", "z shift", "turn x", "turn y", "turn z"};
    if (index < 0 || index >= 6) throw Error("bone motion: no component " + std::to_string(index));
    return kNames[index];
}

MatchVerdict judgeNamedNumbers(const std::array<double, 6>& reference,
                               const std::array<double, 6>& user, double mtreMm,
                               const char* (*nameOf)(int), const MatchTolerances& tolerances) {
    // Angle errors wrapped as for the 2011 angles; only the names differ.
    MatchVerdict v =
        judgeMatch(Pose::fromArray(reference), Pose::fromArray(user), mtreMm, tolerances);
    for (int i = 0; i < 6; ++i) {
        const ParameterHint& h = v.hints[i];
        const char* word = h.status == ParameterStatus::TooHigh  ? "too high"
                           : h.status == ParameterStatus::TooLow ? "too low"
                                                                 : "OK";
        v.hints[i].text = std::string(nameOf(i)) + " " + word;
    }
    return v;
}

MatchVerdict judgeBoneMotion(const BoneMotion& reference, const BoneMotion& user, double mtreMm,
                             const MatchTolerances& tolerances) {
    return judgeNamedNumbers(reference, user, mtreMm, boneMotionComponentName, tolerances);
}

}  // namespace fm

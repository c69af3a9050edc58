#include "search/ConfirmedSearch.h"

#include <cmath>

#include "core/Error.h"
#include "core/Random.h"

namespace fm {

SearchPoint confirmationPoint(std::uint64_t seed, const std::array<double, 6>& radius,
                              const ConfirmationSettings& confirmation, int run) {
    SearchPoint point{};
    if (run <= 0) return point;
    Rng rng(seed * 0x9E3779B97F4A7C15ull + static_cast<std::uint64_t>(run));
    const double spread = confirmation.startSpread;
    const double r = std::sqrt(rng.uniform()), a = 2.0 * M_PI * rng.uniform();
    point[0] = spread * radius[0] * r * std::cos(a);
    point[1] = spread * radius[1] * r * std::sin(a);
    for (int i = 2; i < 6; ++i) point[i] = spread * radius[i] * rng.uniform(-1.0, 1.0);
    return point;
}

bool parametersAgree(const SceneParams& a, const SceneParams& b, const ConfirmationSettings& bounds) {
    const double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
    if (std::sqrt(dx * dx + dy * dy + dz * dz) > bounds.agreeInPlaneMm) return false;
    for (int i = 3; i < 6; ++i) {
        const double d = std::remainder(a[i] - b[i], 360.0);
        if (std::abs(d) > bounds.agreeRotationDeg) return false;
    }
    return true;
}

ConfirmedSearch runConfirmed(const SeededSearch& search, const SearchStart& startAt, const SceneParams& start,
                             std::uint64_t seed, const std::array<double, 6>& radius,
                             const ConfirmationSettings& confirmation, const RegistrationCallback& progress,
                             const std::atomic<bool>* stop) {
    if (confirmation.runs < 1 || confirmation.maxRuns < confirmation.runs)
        throw Error("registration: confirmation runs must be at least 1 and at most maxRuns");
    ConfirmedSearch out;
    std::size_t best = 0;
    // More than `runs` only while no two agree, and never for one search (runs = 1: unconfirmed).
    for (int run = 0; run < confirmation.maxRuns &&
                      (run < confirmation.runs || (confirmation.runs >= 2 && out.agreeing < 2));
         ++run) {
        if (run > 0 && stop && stop->load()) break;
        const SceneParams from = startAt(start, confirmationPoint(seed, radius, confirmation, run));
        out.runs.push_back(search(from, seed + static_cast<std::uint64_t>(run),
                                  run == 0 ? progress : RegistrationCallback{}));
        best = 0;
        for (std::size_t i = 1; i < out.runs.size(); ++i)
            if (out.runs[i].similarity > out.runs[best].similarity) best = i;
        out.agreeing = 0;
        for (const RegistrationResult& r : out.runs)
            out.agreeing += parametersAgree(out.runs[best].params, r.params, confirmation) ? 1 : 0;
        if (out.runs.back().stopped) break;
    }
    out.answer = answerOfRuns(out.runs, best);
    for (const RegistrationResult& r : out.runs) out.answer.stopped = out.answer.stopped || r.stopped;
    return out;
}

ConfirmedSearch runConfirmed(const Registration& registration, const SceneParams& start,
                             const ConfirmationSettings& confirmation, const RegistrationCallback& progress,
                             const std::atomic<bool>* stop) {
    const RegistrationSettings& settings = registration.settings();
    ConfirmedSearch out = runConfirmed(
        [&](const SceneParams& from, std::uint64_t seed, const RegistrationCallback& p) {
            return registration.run(from, p, stop, seed);
        },
        [&](const SceneParams& s, const SearchPoint& point) {
            return registration.parameterization().fromSearchPoint(s, point);
        },
        start, settings.seed, settings.searchRadius, confirmation, progress, stop);
    if (confirmation.uncertainty && !out.answer.stopped)
        out.uncertainty = poseUncertainty(registration, out.answer.params);
    return out;
}

}  // namespace fm

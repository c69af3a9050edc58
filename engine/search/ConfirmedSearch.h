#pragma once
// A registration confirmed by searches from independent starts (issue 30: "agreement between
// restarts"; "a result that is not ok is searched again before it is reported"): the first from
// the start, the others from starts drawn around it (seeded: run r uses seed + r), until two end
// within the agreement bounds of the best (1 mm, 2 deg) or maxRuns have run; the best is the
// answer. One scene searched here (`register` on a CT); xray/ConfirmedRegistration runs the same
// rule for every object of a radiograph side by side, track/ConfirmedFrame for a trial's frame.
#include <atomic>
#include <cstdint>
#include <functional>
#include <vector>

#include "search/PoseUncertainty.h"
#include "search/Registration.h"

namespace fm {

struct ConfirmationSettings {
    int runs = 2;     // searches at first (1 = the search alone, unconfirmed)
    int maxRuns = 4;  // at most this many while no two agree
    // Run r >= 1 starts at the start moved by a seeded draw: in-plane within a disc, depth and
    // each angle uniformly, each within startSpread x the search radius of that coordinate.
    double startSpread = 1.0;
    double agreeInPlaneMm = 1.0;  // the success bounds for one view
    double agreeRotationDeg = 2.0;
    bool uncertainty = true;  // the curvature at the answer (73 evaluations at the finest level)
};

// The search point (search coordinates: u, v, depth mm; angles deg) run `run` starts from, within
// startSpread x `radius` per coordinate; zero for run 0. Depends on (seed, run) only.
SearchPoint confirmationPoint(std::uint64_t seed, const std::array<double, 6>& radius,
                              const ConfirmationSettings& confirmation, int run);
inline SearchPoint confirmationPoint(const RegistrationSettings& settings, const ConfirmationSettings& confirmation,
                                     int run) {
    return confirmationPoint(settings.seed, settings.searchRadius, confirmation, run);
}

struct ConfirmedSearch {
    RegistrationResult answer;  // the best run; evaluations, seconds and profile are the runs' sums
    std::vector<RegistrationResult> runs;
    int agreeing = 0;  // runs within the agreement bounds of the answer (itself included)
    PoseUncertainty uncertainty;  // at the answer, when measured
};

// runs[best] carrying the evaluations, seconds and profile of every run (what the confirmation
// cost) and stopped if any was. Run: RegistrationResult, ObjectRegistrationResult, FrameRecord.
template <class Run>
Run answerOfRuns(const std::vector<Run>& runs, std::size_t best) {
    Run answer = runs.at(best);
    answer.evaluations = 0;
    answer.seconds = 0.0;
    answer.profile = {};
    for (const Run& r : runs) {
        answer.evaluations += r.evaluations;
        answer.seconds += r.seconds;
        answer.profile += r.profile;
    }
    return answer;
}

// Two parameter sets agree: the first three (mm) within agreeInPlaneMm as a vector, each of the
// last three (deg, wrapped) within agreeRotationDeg.
bool parametersAgree(const SceneParams& a, const SceneParams& b, const ConfirmationSettings& bounds);

// The rule for any search: `search(start, seed, progress)` runs one; `startAt(start, point)` gives
// the parameters of a search point around the start. No uncertainty (the caller's cost knows
// how). fm::Error for runs < 1 or maxRuns < runs.
using SeededSearch =
    std::function<RegistrationResult(const SceneParams& start, std::uint64_t seed, const RegistrationCallback& progress)>;
using SearchStart = std::function<SceneParams(const SceneParams& start, const SearchPoint& point)>;
ConfirmedSearch runConfirmed(const SeededSearch& search, const SearchStart& startAt, const SceneParams& start,
                             std::uint64_t seed, const std::array<double, 6>& radius,
                             const ConfirmationSettings& confirmation, const RegistrationCallback& progress = {},
                             const std::atomic<bool>* stop = nullptr);

// Throws as Registration::run; fm::Error for runs < 1 or maxRuns < runs. `progress` is the
// first run's.
ConfirmedSearch runConfirmed(const Registration& registration, const SceneParams& start,
                             const ConfirmationSettings& confirmation, const RegistrationCallback& progress = {},
                             const std::atomic<bool>* stop = nullptr);

}  // namespace fm

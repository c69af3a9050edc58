#pragma once
// Stage 3 of a search with no start (find/PoseFinder.h, find/ViewFinder.h): each hypothesis of the
// scan polished by the registration's own search at coarse levels, side by side one per core, so
// that exact renders, not the scan's approximations, rank them.
#include <array>
#include <atomic>
#include <vector>

#include "search/Registration.h"

namespace fm {

// `finish` searched at `levels` by Nelder-Mead alone (`evaluations` for its first level, half at the
// next; no tilt search, no out-of-plane hypotheses, no level left out), within `radius` per search
// coordinate (the scan's half steps), one thread per search.
RegistrationSettings refinementSettings(const RegistrationSettings& finish, std::vector<int> levels, int evaluations,
                                        const std::array<double, 6>& radius);

struct RefinedHypothesis {
    SceneParams params{};
    double cost = 0.0;  // -similarity at the finest of the levels
    int evaluations = 0;
    int hypothesis = 0;  // index of its start
};

// `refinement` run from each of `starts` on `threads`, best (lowest cost) first; ties keep the
// starts' order. The same for any thread count.
std::vector<RefinedHypothesis> refineHypotheses(const Registration& refinement, const std::vector<SceneParams>& starts,
                                                int threads, const std::atomic<bool>* stop);

}  // namespace fm

#include "find/RefineHypotheses.h"

#include <algorithm>

#include "core/Parallel.h"

namespace fm {

RegistrationSettings refinementSettings(const RegistrationSettings& finish, std::vector<int> levels, int evaluations,
                                        const std::array<double, 6>& radius) {
    RegistrationSettings refine = finish;
    refine.levelFactors = std::move(levels);
    refine.dropLevelsFinerThanVoxels = false;
    refine.method = SearchMethod::NelderMead;
    refine.globalEvaluations = evaluations;
    refine.polishEvaluations = evaluations / 2;
    refine.finestPolishEvaluations = -1;
    refine.polishCoarsest = false;
    refine.hypothesisTiltDeg = 0.0;
    refine.tiltRounds = 0;
    refine.depthRounds = 2;
    refine.searchRadius = radius;
    refine.depthStepMm = 0.5 * radius[2];
    refine.threads = 1;
    return refine;
}

std::vector<RefinedHypothesis> refineHypotheses(const Registration& refinement, const std::vector<SceneParams>& starts,
                                                int threads, const std::atomic<bool>* stop) {
    std::vector<RefinedHypothesis> refined(starts.size());
    parallelFor(static_cast<int>(starts.size()), threads, [&](int begin, int end) {
        for (int k = begin; k < end; ++k) {
            const RegistrationResult r = refinement.run(starts[static_cast<std::size_t>(k)], {}, stop);
            refined[static_cast<std::size_t>(k)] = {r.params, -r.similarity, r.evaluations, k};
        }
    }, 4);
    std::stable_sort(refined.begin(), refined.end(),
                     [](const RefinedHypothesis& a, const RefinedHypothesis& b) { return a.cost < b.cost; });
    return refined;
}

}  // namespace fm

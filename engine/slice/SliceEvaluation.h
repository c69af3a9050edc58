#pragma once
// The van de Kraats evaluation (search/Evaluation.h) for slices: start poses at known initial
// slice mTRE (SlicePoseError.h), binned; N starts per bin, the same for every method; success
// rate (final mTRE below 1 mm), median final mTRE, capture range and time per registration.
// The summaries are search/Evaluation.h's (summarizeBins, summarizeMethods).
#include <atomic>
#include <functional>
#include <vector>

#include "search/Evaluation.h"
#include "slice/SliceRegistration.h"

namespace fm {

// Runs every method of `settings` from every start against `reference` (with its mask; a
// slice at `truth`). settings.registration is not used (the X-ray settings); `slice` holds
// the search settings. Deterministic for a seed and thread count.
std::vector<EvaluationTrial> runSliceEvaluation(
    const SliceVolumePtr& volume, const Image& reference, const Mask* referenceMask,
    const SliceSetup& setup, const glm::dvec3& volumeCenter, const Pose& truth,
    const std::vector<glm::dvec3>& targets, const EvaluationSettings& settings,
    const SliceRegistrationSettings& slice,
    const std::function<void(const EvaluationTrial&, int done, int total)>& onTrial = {},
    const std::atomic<bool>* stop = nullptr);

}  // namespace fm

#include "slice/SliceEvaluation.h"

#include <ctime>

#include "core/Error.h"
#include "slice/SlicePoseError.h"

namespace fm {

std::vector<EvaluationTrial> runSliceEvaluation(
    const SliceVolumePtr& volume, const Image& reference, const Mask* referenceMask,
    const SliceSetup& setup, const glm::dvec3& volumeCenter, const Pose& truth,
    const std::vector<glm::dvec3>& targets, const EvaluationSettings& settings,
    const SliceRegistrationSettings& slice,
    const std::function<void(const EvaluationTrial&, int, int)>& onTrial,
    const std::atomic<bool>* stop) {
    if (settings.startsPerBin < 1) throw Error("evaluation: starts per bin must be at least 1");
    if (settings.methods.empty()) throw Error("evaluation: no methods");
    const SliceGeometry truthSlice = sliceGeometry(truth, setup, volumeCenter);
    auto error = [&](const Pose& p) {
        return sliceTargetError(truthSlice, sliceGeometry(p, setup, volumeCenter), targets);
    };
    Rng rng(settings.seed);
    std::vector<std::vector<Pose>> starts(settings.bins.size());
    for (std::size_t b = 0; b < settings.bins.size(); ++b)
        for (int s = 0; s < settings.startsPerBin; ++s)
            starts[b].push_back(Pose::fromArray(startInBin(
                truth.toArray(),
                [&](const SceneParams& p) { return error(Pose::fromArray(p)).meanMm; },
                settings.bins[b], rng)));
    std::vector<EvaluationTrial> trials;
    const int total =
        static_cast<int>(settings.methods.size() * settings.bins.size()) * settings.startsPerBin;
    for (SearchMethod method : settings.methods) {
        SliceRegistrationSettings rs = slice;
        rs.method = method;
        const SliceRegistration registration(volume, reference, referenceMask, setup,
                                             volumeCenter, rs);
        const double ceiling = registration.referenceSelfSimilarity();
        for (std::size_t b = 0; b < settings.bins.size(); ++b)
            for (int s = 0; s < settings.startsPerBin; ++s) {
                if (stop && stop->load()) return trials;
                const Pose& start = starts[b][s];
                const std::clock_t cpu0 = std::clock();
                const RegistrationResult r = registration.run(start, {}, stop);
                EvaluationTrial t;
                t.method = method;
                t.bin = static_cast<int>(b);
                t.start = s;
                t.startMtreMm = error(start).meanMm;
                t.final = error(r.pose());
                t.seconds = r.seconds;
                t.cpuSeconds = double(std::clock() - cpu0) / CLOCKS_PER_SEC;
                t.evaluations = r.evaluations;
                t.success = t.final.meanMm < settings.successMm;
                // Judged without the truth, as evaluate's X-ray trials (search/Evaluation.cpp).
                AnswerEvidence evidence;
                judgeAgainstPerfectMatch(evidence, r.similarity, ceiling);
                evidence.stopped = r.stopped;
                t.similarityRatio = evidence.similarityRatio.value_or(0.0);
                t.verdict = judgeEvidence(evidence).verdict;
                trials.push_back(t);
                if (onTrial) onTrial(t, static_cast<int>(trials.size()), total);
            }
    }
    return trials;
}

}  // namespace fm

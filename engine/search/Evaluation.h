#pragma once
// The standard evaluation of 2D/3D registration (van de Kraats et al., IEEE TMI 24(9), 2005):
// start poses at known initial mTRE, binned (0-2, 2-5, 5-10, 10-20 mm); N starts per bin; for
// every method the success rate (final mTRE below 1 mm), the median final mTRE (and its in-plane
// and out-of-plane parts), the time per registration and the capture range (the largest initial
// mTRE below which every bin succeeds at least 95% of the time).
//
// Start poses: a random direction in the six parameters, with 1 mm of translation weighed like
// 1 degree of rotation (so angle errors match translation errors, as in the protocol), scaled
// by bisection until the start's mTRE equals a target drawn uniformly within the bin. Every
// method gets the same starts.
#include <functional>
#include <optional>
#include <vector>

#include "match/PoseError.h"
#include "search/AnswerVerdict.h"
#include "search/Registration.h"
#include "search/RegistrationTargets.h"
#include "scene/SceneParameterization.h"

namespace fm {

struct StartBin {
    double lowMm = 0.0;
    double highMm = 0.0;
};
std::vector<StartBin> standardStartBins();  // 0-2, 2-5, 5-10, 10-20 mm

// What an evaluation registers: a scene, the numbers that move it, and the object whose
// target points (in its own frame) measure the error, seen by camera 0.
struct EvaluationScene {
    Scene scene;
    SceneParameterizationPtr parameterization;
    std::size_t targetObject = 0;
    // Camera 0's pixels to compare (e.g. one bone's footprint); nullopt = all.
    std::optional<Mask> valid;
    // Camera 0 at `params`, in the target object's frame (what targetRegistrationError takes).
    ProjectionGeometry camera(const SceneParams& params) const;
};

// Start numbers whose mTRE from `truth` lies within the bin. Throws fm::Error if no scale
// along the drawn directions reaches the bin (targets degenerate).
SceneParams startInBin(const SceneParams& truth, const EvaluationScene& scene,
                       const std::vector<glm::dvec3>& targets, const StartBin& bin, Rng& rng);
// The same for any error measure: `mtreFromTruth(params)` is the mTRE of `params` from the
// truth (the MRI slice mode measures it in slice frames, engine/slice/SlicePoseError.h).
SceneParams startInBin(const SceneParams& truth,
                       const std::function<double(const SceneParams&)>& mtreFromTruth,
                       const StartBin& bin, Rng& rng);

struct EvaluationSettings {
    std::vector<SearchMethod> methods = globalSearchMethods();
    std::vector<StartBin> bins = standardStartBins();
    int startsPerBin = 10;
    std::uint64_t seed = 1;
    double successMm = 1.0;
    double captureSuccessRate = 0.95;
    RegistrationSettings registration;
};

struct EvaluationTrial {
    SearchMethod method = SearchMethod::CmaEs;
    int bin = 0;
    int start = 0;  // index within the bin
    double startMtreMm = 0.0;
    TargetRegistrationError final;
    double seconds = 0.0;     // wall clock
    double cpuSeconds = 0.0;  // processor time of the whole process (all threads)
    int evaluations = 0;
    bool success = false;
    EvaluationProfile profile;  // where the evaluations' time went
    // Judged without the truth: the similarity over what a perfect match scores on this
    // reference (Registration::referenceSelfSimilarity): ok from kConfirmedSimilarityRatio,
    // lost below kLostSimilarityRatio (xray/AnswerCheck.h).
    double similarityRatio = 0.0;
    AnswerVerdict verdict = AnswerVerdict::Doubtful;
};

struct EvaluationBinSummary {
    SearchMethod method = SearchMethod::CmaEs;
    StartBin bin;
    int count = 0;
    double successRate = 0.0;
    double medianMtreMm = 0.0;
    double medianInPlaneMm = 0.0;
    double medianOutOfPlaneMm = 0.0;
    double medianSeconds = 0.0;
    double medianCpuSeconds = 0.0;
};

struct EvaluationMethodSummary {
    SearchMethod method = SearchMethod::CmaEs;
    double captureRangeMm = 0.0;  // 0 if even the first bin falls short
    double successRate = 0.0;     // over all starts
    double medianSeconds = 0.0;
};

// One registration of the protocol: a method from one start. The plan lists them method by
// method, then bin by bin, then start by start; that index is the job index of a distributed
// run (see distributed/JobRunner.h).
struct EvaluationStart {
    SearchMethod method = SearchMethod::CmaEs;
    int bin = 0;
    int start = 0;  // index within the bin
    SceneParams params;
};

// Every registration of the protocol, in order. The starts are drawn from one stream of
// settings.seed, bin by bin, start by start, and are the same for every method; the plan is a
// function of its arguments only (every rank of a distributed run computes the same plan).
std::vector<EvaluationStart> evaluationPlan(const SceneParams& truth,
                                            const EvaluationScene& scene,
                                            const std::vector<glm::dvec3>& targets,
                                            const EvaluationSettings& settings);

// Runs one registration of the plan. `registration` must have been built for `scene` with
// settings.registration and `start.method`. Every registration uses the seed
// settings.registration.seed: the result depends only on the start (and the thread count).
EvaluationTrial runEvaluationTrial(const Registration& registration, const EvaluationStart& start,
                                   const EvaluationScene& scene, const SceneParams& truth,
                                   const std::vector<glm::dvec3>& targets,
                                   const EvaluationSettings& settings,
                                   const std::atomic<bool>* stop = nullptr);

// Runs every method from every start against `reference` (camera 0's image, e.g. a DRR
// rendered at `truth`). `onTrial` (optional) is called after each registration.
// Deterministic for a seed and thread count.
std::vector<EvaluationTrial> runEvaluation(
    const EvaluationScene& scene, const Image& reference, const SceneParams& truth,
    const std::vector<glm::dvec3>& targets, const EvaluationSettings& settings,
    const std::function<void(const EvaluationTrial&, int done, int total)>& onTrial = {},
    const std::atomic<bool>* stop = nullptr);

std::vector<EvaluationBinSummary> summarizeBins(const std::vector<EvaluationTrial>& trials,
                                                const EvaluationSettings& settings);
std::vector<EvaluationMethodSummary> summarizeMethods(const std::vector<EvaluationTrial>& trials,
                                                      const EvaluationSettings& settings);

double median(std::vector<double> values);  // NaN for none

}  // namespace fm

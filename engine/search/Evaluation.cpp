#include "search/Evaluation.h"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <limits>

#include "core/Error.h"
#include "scene/VolumeScene.h"

namespace fm {

std::vector<StartBin> standardStartBins() {
    return {{0, 2}, {2, 5}, {5, 10}, {10, 20}};
}

ProjectionGeometry EvaluationScene::camera(const SceneParams& params) const {
    if (!parameterization) throw Error("evaluation: no scene parameterization");
    return cameraInObjectFrameAt(scene, *parameterization, params, 0, targetObject);
}

SceneParams startInBin(const SceneParams& truth, const EvaluationScene& scene,
                       const std::vector<glm::dvec3>& targets, const StartBin& bin, Rng& rng) {
    const ProjectionGeometry truthGeometry = scene.camera(truth);
    return startInBin(
        truth,
        [&](const SceneParams& p) {
            return targetRegistrationError(truthGeometry, scene.camera(p), targets).meanMm;
        },
        bin, rng);
}

SceneParams startInBin(const SceneParams& truth,
                       const std::function<double(const SceneParams&)>& mtreFromTruth,
                       const StartBin& bin, Rng& rng) {
    if (!(bin.lowMm >= 0.0 && bin.highMm > bin.lowMm))
        throw Error("start bin must satisfy 0 <= low < high");
    const std::array<double, 6> base = truth;
    for (int attempt = 0; attempt < 20; ++attempt) {
        std::array<double, 6> dir;
        double norm = 0.0;
        for (double& d : dir) {
            d = rng.normal();
            norm += d * d;
        }
        norm = std::sqrt(norm);
        for (double& d : dir) d /= norm;
        const double goal = rng.uniform(bin.lowMm, bin.highMm);
        auto poseAt = [&](double t) {
            std::array<double, 6> p;
            for (int i = 0; i < 6; ++i) p[i] = base[i] + t * dir[i];
            return p;
        };
        auto mtre = [&](double t) { return mtreFromTruth(poseAt(t)); };
        // Bracket the goal, then bisect (mTRE grows with t along a line for these ranges).
        double lo = 0.0, hi = 1.0;
        while (mtre(hi) < goal && hi < 1e3) hi *= 2.0;
        if (mtre(hi) < goal) continue;
        for (int i = 0; i < 60; ++i) {
            const double mid = 0.5 * (lo + hi);
            (mtre(mid) < goal ? lo : hi) = mid;
        }
        const SceneParams p = poseAt(0.5 * (lo + hi));
        const double reached = mtre(0.5 * (lo + hi));
        if (reached >= bin.lowMm && reached <= bin.highMm) return p;
    }
    throw Error("could not place a start pose with an mTRE in [" + std::to_string(bin.lowMm) +
                ", " + std::to_string(bin.highMm) + "] mm");
}

double median(std::vector<double> v) {
    if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

std::vector<EvaluationStart> evaluationPlan(const SceneParams& truth,
                                            const EvaluationScene& scene,
                                            const std::vector<glm::dvec3>& targets,
                                            const EvaluationSettings& settings) {
    if (settings.startsPerBin < 1) throw Error("evaluation: starts per bin must be at least 1");
    if (settings.methods.empty()) throw Error("evaluation: no methods");
    // The same starts for every method.
    Rng rng(settings.seed);
    std::vector<std::vector<SceneParams>> starts(settings.bins.size());
    for (std::size_t b = 0; b < settings.bins.size(); ++b)
        for (int s = 0; s < settings.startsPerBin; ++s)
            starts[b].push_back(startInBin(truth, scene, targets, settings.bins[b], rng));
    std::vector<EvaluationStart> plan;
    for (SearchMethod method : settings.methods)
        for (std::size_t b = 0; b < settings.bins.size(); ++b)
            for (int s = 0; s < settings.startsPerBin; ++s)
                plan.push_back({method, static_cast<int>(b), s, starts[b][s]});
    return plan;
}

EvaluationTrial runEvaluationTrial(const Registration& registration, const EvaluationStart& start,
                                   const EvaluationScene& scene, const SceneParams& truth,
                                   const std::vector<glm::dvec3>& targets,
                                   const EvaluationSettings& settings,
                                   const std::atomic<bool>* stop) {
    const ProjectionGeometry truthGeometry = scene.camera(truth);
    const std::clock_t cpu0 = std::clock();
    const RegistrationResult r = registration.run(start.params, {}, stop);
    const double cpu = double(std::clock() - cpu0) / CLOCKS_PER_SEC;
    EvaluationTrial t;
    t.profile = r.profile;
    t.method = start.method;
    t.bin = start.bin;
    t.start = start.start;
    t.startMtreMm =
        targetRegistrationError(truthGeometry, scene.camera(start.params), targets).meanMm;
    t.final = targetRegistrationError(truthGeometry, scene.camera(r.params), targets);
    t.seconds = r.seconds;
    t.cpuSeconds = cpu;
    t.evaluations = r.evaluations;
    t.success = t.final.meanMm < settings.successMm;
    // How sure, without the truth: against what a perfect match scores on this reference.
    const double ceiling = registration.referenceSelfSimilarity();
    AnswerEvidence evidence;
    judgeAgainstPerfectMatch(evidence, r.similarity, ceiling);
    evidence.stopped = r.stopped;
    t.similarityRatio = evidence.similarityRatio.value_or(0.0);
    t.verdict = judgeEvidence(evidence).verdict;
    return t;
}

std::vector<EvaluationTrial> runEvaluation(
    const EvaluationScene& scene, const Image& reference, const SceneParams& truth,
    const std::vector<glm::dvec3>& targets, const EvaluationSettings& settings,
    const std::function<void(const EvaluationTrial&, int, int)>& onTrial,
    const std::atomic<bool>* stop) {
    const std::vector<EvaluationStart> plan = evaluationPlan(truth, scene, targets, settings);
    std::vector<EvaluationTrial> trials;
    const int total = static_cast<int>(plan.size());
    for (std::size_t i = 0; i < plan.size();) {
        RegistrationSettings rs = settings.registration;
        rs.method = plan[i].method;
        const Registration registration(scene.scene, scene.parameterization,
                                        {{0, reference, scene.valid}},
                                        rs);
        for (; i < plan.size() && plan[i].method == rs.method; ++i) {
            if (stop && stop->load()) return trials;
            trials.push_back(
                runEvaluationTrial(registration, plan[i], scene, truth, targets, settings, stop));
            if (onTrial) onTrial(trials.back(), static_cast<int>(trials.size()), total);
        }
    }
    return trials;
}

std::vector<EvaluationBinSummary> summarizeBins(const std::vector<EvaluationTrial>& trials,
                                                const EvaluationSettings& settings) {
    std::vector<EvaluationBinSummary> out;
    for (SearchMethod m : settings.methods)
        for (std::size_t b = 0; b < settings.bins.size(); ++b) {
            EvaluationBinSummary s;
            s.method = m;
            s.bin = settings.bins[b];
            std::vector<double> mtre, inPlane, outOfPlane, seconds, cpu;
            int successes = 0;
            for (const EvaluationTrial& t : trials) {
                if (t.method != m || t.bin != static_cast<int>(b)) continue;
                ++s.count;
                successes += t.success;
                mtre.push_back(t.final.meanMm);
                inPlane.push_back(t.final.meanInPlaneMm);
                outOfPlane.push_back(t.final.meanDepthMm);
                seconds.push_back(t.seconds);
                cpu.push_back(t.cpuSeconds);
            }
            if (s.count == 0) continue;
            s.medianCpuSeconds = median(cpu);
            s.successRate = double(successes) / s.count;
            s.medianMtreMm = median(mtre);
            s.medianInPlaneMm = median(inPlane);
            s.medianOutOfPlaneMm = median(outOfPlane);
            s.medianSeconds = median(seconds);
            out.push_back(s);
        }
    return out;
}

std::vector<EvaluationMethodSummary> summarizeMethods(const std::vector<EvaluationTrial>& trials,
                                                      const EvaluationSettings& settings) {
    const std::vector<EvaluationBinSummary> bins = summarizeBins(trials, settings);
    std::vector<EvaluationMethodSummary> out;
    for (SearchMethod m : settings.methods) {
        EvaluationMethodSummary s;
        s.method = m;
        // Capture range: the upper edge of the last bin of an unbroken run from the first bin
        // in which the success rate reaches the threshold.
        for (const EvaluationBinSummary& b : bins) {
            if (b.method != m) continue;
            if (b.successRate + 1e-12 < settings.captureSuccessRate) break;
            s.captureRangeMm = b.bin.highMm;
        }
        std::vector<double> seconds;
        int n = 0, ok = 0;
        for (const EvaluationTrial& t : trials)
            if (t.method == m) {
                ++n;
                ok += t.success;
                seconds.push_back(t.seconds);
            }
        if (n == 0) continue;
        s.successRate = double(ok) / n;
        s.medianSeconds = median(seconds);
        out.push_back(s);
    }
    return out;
}

}  // namespace fm

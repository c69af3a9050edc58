#include "find/BiplaneFinder.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <tuple>

#include "core/Error.h"
#include "find/RefineHypotheses.h"
#include "find/SeenPose.h"
#include "find/SharedView.h"
#include "scene/ObjectPoseParameterization.h"

namespace fm {

namespace {

// The coarsest power of two (up to maxScanFactor) at which the bone's bounding-box diagonal,
// at the middle of the band on the first camera's axis, spans minScanSpanPixels.
int scanFactorFor(const XrayModel& model, const ProjectionGeometry& first, double depth, const BiplaneFindSettings& s) {
    const CameraAxes axes = cameraAxes(first);
    const Box3 box = model.bounds();
    const double diagonalMm = box.empty() ? 0.0 : glm::length(box.upper - box.lower);
    const double spanPixels = diagonalMm * axes.distance / depth / axes.spacing.x;
    int factor = 1;
    while (factor * 2 <= s.maxScanFactor && spanPixels / (factor * 2) >= s.minScanSpanPixels) factor *= 2;
    return factor;
}

// Two poses within `mm` at the pivot and `deg` of turn.
bool posesWithin(const RigidTransform& a, const RigidTransform& b, const glm::dvec3& pivot, double mm, double deg) {
    return glm::length(a.applyToPoint(pivot) - b.applyToPoint(pivot)) <= mm && rotationBetweenDeg(a.rotation, b.rotation) <= deg;
}

// An answer's similarity (summed over the cameras) per camera: what kBiplaneMinSimilarity bounds.
double perCameraSimilarity(const BiplaneCandidate& c, std::size_t cameras) {
    return c.similarity / static_cast<double>(std::max<std::size_t>(cameras, 1));
}

bool sameAnswer(const RigidTransform& a, const RigidTransform& b, const glm::dvec3& pivot) {
    return posesWithin(a, b, pivot, kBiplaneSameMm, kBiplaneSameDeg);
}

// The registration of `scene` in `views` in the first camera's frame from `start` (angles 0 there).
Registration registrationFrom(const Scene& scene, const std::vector<RegistrationView>& views,
                              const RegistrationSettings& settings, const RigidTransform& start, const glm::dvec3& pivot,
                              std::shared_ptr<ObjectPoseParameterization>& parameterization) {
    parameterization = std::make_shared<ObjectPoseParameterization>(scene.objects[0].name, scene.cameras.at(views[0].camera),
                                                                     start, pivot);
    return Registration(scene, parameterization, views, settings);
}

// Steps 1-4 with the scan at `scanFactor` (0: scanFactorFor's).
FoundBiplane findBiplaneOnce(const Scene& scene, const std::vector<RegistrationView>& views,
                             const RegistrationSettings& finish, const BiplaneFindSettings& settings, int scanFactor,
                             const std::atomic<bool>* stop, const FindStageCallback& onStage) {
    if (views.size() < 2) throw Error("biplane find: needs two or more cameras");
    if (scene.objects.empty()) throw Error("biplane find: no object");
    if (settings.refined < 1 || settings.finalists < 1 || settings.refineEvaluations < 1 || settings.finishEvaluations < 2)
        throw Error("biplane find: hypotheses and evaluations must be positive");
    if (settings.glanceEvaluations < 0 || !(settings.glanceKeptShare > 0.0 && settings.glanceKeptShare <= 1.0))
        throw Error("biplane find: the glance's evaluations must be 0 or more and its kept share in (0, 1]");
    FoundBiplane out;
    const ProjectionGeometry& first = scene.cameras.at(views[0].camera);
    std::vector<ProjectionGeometry> others;
    for (std::size_t k = 1; k < views.size(); ++k) others.push_back(scene.cameras.at(views[k].camera));
    // The depths the cameras share, unless the search space gives a band in mm.
    const auto band = settings.space.nearMm > 0.0
                          ? std::optional<std::pair<double, double>>({settings.space.nearMm, settings.space.farMm})
                          : sharedViewDepths(first, others);
    if (!band) throw Error("biplane find: the cameras share no view (no depth of the first camera's rays is seen by another)");
    out.band = *band;
    const XrayModel& model = *scene.objects[0].model;
    const glm::dvec3 pivot = defaultPivot(model);

    const auto starting = [&](const char* stage) {
        if (onStage) onStage(stage);
    };

    // 1. scan
    starting("scan");
    auto clock = FindClock::now();
    BiplaneScanSettings scanSettings = settings.scan;
    scanSettings.factor = scanFactor > 0 ? scanFactor : scanFactorFor(model, first, 0.5 * (band->first + band->second), settings);
    scanSettings.threads = settings.threads;
    // Placements at most maxPlacementsPerSide per side of the scan image.
    int side = 0;
    for (const RegistrationView& v : views) side = std::max({side, v.reference.width, v.reference.height});
    scanSettings.placementStride = 1;
    while (side / (scanSettings.factor * scanSettings.placementStride) > settings.maxPlacementsPerSide)
        scanSettings.placementStride *= 2;
    out.scanFactor = scanSettings.factor;
    out.placementStride = scanSettings.placementStride;
    const BiplaneScan scan = scanBiplane(scene, pivot, views, settings.space, *band, scanSettings, stop);
    out.orientations = scan.orientations;
    const int refined = std::min<int>(settings.refined, static_cast<int>(scan.hypotheses.size()));
    out.stages.push_back({"scan", secondsSince(clock), scan.placements, refined});
    if ((stop && stop->load()) || refined == 0) {
        out.stopped = stop && stop->load();
        out.verdictText = refined == 0 ? "lost: no pose of the search space is seen by every camera" : "lost: stopped in the scan";
        return out;
    }

    // 2. glance and refine at the scan's pixel: Nelder-Mead from each hypothesis within half a grid
    // step and a scan pixel and a half.
    clock = FindClock::now();
    const CameraAxes axes = cameraAxes(first);
    const double pixelMm = axes.spacing.x * scanSettings.factor * 0.5 * (band->first + band->second) / axes.distance;
    const double halfStep = 0.5 * scanSettings.angleStepDeg, reach = 1.5 * pixelMm;
    RegistrationSettings refine = refinementSettings(finish, {scanSettings.factor}, settings.refineEvaluations,
                                                     {reach, reach, reach, halfStep, halfStep, halfStep});
    refine.depthRounds = 0;  // the other cameras see depth
    const RigidTransform origin = scan.hypotheses[0].worldFromObject(pivot);
    std::shared_ptr<ObjectPoseParameterization> frame;
    const Registration coarse = registrationFrom(scene, views, refine, origin, pivot, frame);
    std::vector<SceneParams> starts;
    for (int k = 0; k < refined; ++k) starts.push_back(frame->paramsOf(scan.hypotheses[k].worldFromObject(pivot)));
    // 2a. glance: every hypothesis polished briefly; the best share of them go on to 2b from where
    // their glance left them (most of the scan's hypotheses are far from any answer, and a few
    // evaluations show it: the flexed femur's frame 6 was found from the glance's 66th of 1600, the
    // scan's 1095th).
    // The starts are in the scan's order: a refined hypothesis's index is its rank in the scan.
    const int kept = std::max(settings.finalists, static_cast<int>(std::lround(settings.glanceKeptShare * refined)));
    std::vector<RefinedHypothesis> looked;  // the glance's best `kept`, best first
    if (settings.glanceEvaluations > 0 && kept < refined) {
        starting("glance");
        RegistrationSettings look = refine;
        look.globalEvaluations = settings.glanceEvaluations;
        std::shared_ptr<ObjectPoseParameterization> lookFrame;  // the same numbers as `frame`'s
        const Registration glance = registrationFrom(scene, views, look, origin, pivot, lookFrame);
        looked = refineHypotheses(glance, starts, settings.threads, stop);
        long long glanced = 0;
        for (const RefinedHypothesis& r : looked) glanced += r.evaluations;
        looked.resize(static_cast<std::size_t>(kept));
        starts.clear();
        for (const RefinedHypothesis& r : looked) starts.push_back(r.params);
        out.stages.push_back({"glance", secondsSince(clock), glanced, kept});
        clock = FindClock::now();
    }
    // 2b. refine; stopped in the glance, its best are the finalists, at their glance's costs.
    starting("refine");
    long long evaluations = 0;
    std::vector<RefinedHypothesis> polished;
    if (!looked.empty() && stop && stop->load()) {
        polished = looked;
    } else {
        polished = refineHypotheses(coarse, starts, settings.threads, stop);
        for (RefinedHypothesis& r : polished) {
            evaluations += r.evaluations;
            if (!looked.empty()) r.hypothesis = looked[static_cast<std::size_t>(r.hypothesis)].hypothesis;
        }
    }
    // The best distinct ones go on.
    std::vector<RefinedHypothesis> finalists;
    for (const RefinedHypothesis& r : polished) {
        if (static_cast<int>(finalists.size()) == settings.finalists) break;
        const RigidTransform pose = frame->worldFromObject(r.params);
        if (std::none_of(finalists.begin(), finalists.end(), [&](const RefinedHypothesis& f) {
                return sameAnswer(frame->worldFromObject(f.params), pose, pivot);
            }))
            finalists.push_back(r);
    }
    out.stages.push_back({"refine", secondsSince(clock), evaluations, static_cast<int>(finalists.size())});
    if (stop && stop->load()) {
        out.stopped = true;
        for (const RefinedHypothesis& f : finalists)
            out.candidates.push_back({frame->worldFromObject(f.params), -f.cost, f.hypothesis});
        out.verdict = AnswerVerdict::Doubtful;
        out.verdictText = "doubtful: stopped before the finish (the best at the scan's pixel, unconfirmed)";
        return out;
    }

    // 3. finish at 1/2 and 1/4 of the scan's pixel.
    starting("finish");
    clock = FindClock::now();
    std::vector<int> finishLevels{std::max(1, scanSettings.factor / 2)};
    if (scanSettings.factor / 4 >= 1) finishLevels.push_back(scanSettings.factor / 4);
    RegistrationSettings fine = refinementSettings(finish, finishLevels, settings.finishEvaluations,
                                                   {pixelMm, pixelMm, pixelMm, 0.2 * halfStep, 0.2 * halfStep, 0.2 * halfStep});
    fine.depthRounds = 0;
    const Registration finer = registrationFrom(scene, views, fine, origin, pivot, frame);
    starts.clear();
    for (const RefinedHypothesis& f : finalists) starts.push_back(f.params);
    const std::vector<RefinedHypothesis> done = refineHypotheses(finer, starts, settings.threads, stop);
    evaluations = 0;
    for (const RefinedHypothesis& r : done) {
        evaluations += r.evaluations;
        const RigidTransform pose = frame->worldFromObject(r.params);
        if (std::none_of(out.candidates.begin(), out.candidates.end(),
                         [&](const BiplaneCandidate& c) { return sameAnswer(c.worldFromObject, pose, pivot); }))
            out.candidates.push_back({pose, -r.cost, finalists[static_cast<std::size_t>(r.hypothesis)].hypothesis});
    }
    out.stages.push_back({"finish", secondsSince(clock), evaluations, static_cast<int>(out.candidates.size())});
    out.stopped = stop && stop->load();

    // 4. How sure.
    std::tie(out.verdict, out.verdictText) = judgeBiplaneAnswers(out.candidates, finalists.size(), views.size(), pivot);
    return out;
}

bool clearlySeen(const FoundBiplane& f, std::size_t cameras) {
    return !f.candidates.empty() && perCameraSimilarity(f.candidates[0], cameras) >= kBiplaneMinSimilarity;
}

}  // namespace

FoundBiplane findBiplanePose(const Scene& scene, const std::vector<RegistrationView>& views,
                             const RegistrationSettings& finish, const BiplaneFindSettings& settings,
                             const std::atomic<bool>* stop, const FindStageCallback& onStage) {
    if (settings.finerScanWhenUnseen && settings.refinedWhenFiner < 1)
        throw Error("biplane find: the finer scan's hypotheses must be positive");
    FoundBiplane out = findBiplaneOnce(scene, views, finish, settings, 0, stop, onStage);
    // 5. Nothing clearly seen: the scan ranked the truth too low at its pixel (the flexed femur's
    // frame 13: its neighbours 1674th of 7776 at 1/8, where the best 400 are refined). Once more
    // with the scan at half that pixel, down to 1/4 (1/2 would scan a wrist bone at full size),
    // refining more of its hypotheses (frame 19's answer came from the 768th); the better best
    // answer is kept, and both passes' stages.
    if (!settings.finerScanWhenUnseen || out.stopped || clearlySeen(out, views.size()) || out.scanFactor < 8) return out;
    BiplaneFindSettings again = settings;
    again.refined = settings.refinedWhenFiner;
    FoundBiplane finer = findBiplaneOnce(scene, views, finish, again, out.scanFactor / 2, stop, onStage);
    const bool better = !finer.candidates.empty() &&
                        (out.candidates.empty() || finer.candidates[0].similarity > out.candidates[0].similarity);
    const bool stopped = finer.stopped;  // a stop in the second pass is the whole find's
    std::vector<FindStage> stages = out.stages;
    stages.insert(stages.end(), finer.stages.begin(), finer.stages.end());
    char text[120];
    std::snprintf(text, sizeof text, " (scanned at 1/%d, then at 1/%d: %s)", out.scanFactor, finer.scanFactor,
                  better ? "that pass kept" : "the first pass kept");
    if (better) out = std::move(finer);
    out.stages = std::move(stages);
    out.stopped = stopped;
    out.verdictText += text;
    return out;
}

std::pair<AnswerVerdict, std::string> judgeBiplaneAnswers(const std::vector<BiplaneCandidate>& candidates,
                                                          std::size_t finalists, std::size_t cameras,
                                                          const glm::dvec3& pivot) {
    if (candidates.empty()) return {AnswerVerdict::Lost, "lost: no answer"};
    // The best against its best rival (the best answer of another basin).
    const BiplaneCandidate& best = candidates[0];
    const auto rival = std::find_if(candidates.begin() + 1, candidates.end(), [&](const BiplaneCandidate& c) {
        return !posesWithin(c.worldFromObject, best.worldFromObject, pivot, kBiplaneRivalMm, kBiplaneRivalDeg);
    });
    char text[240];
    AnswerVerdict verdict = AnswerVerdict::Doubtful;
    const double perCamera = perCameraSimilarity(best, cameras);
    if (perCamera < kBiplaneMinSimilarity) {
        std::snprintf(text, sizeof text,
                      "doubtful: the best answer scores %.2f per camera, below %.2f: the bone is not clearly seen at any "
                      "pose searched (is it in the search space?)", perCamera, kBiplaneMinSimilarity);
    } else if (rival != candidates.end()) {
        const double ratio = rival->similarity / best.similarity;
        verdict = ratio < kBiplaneRivalRatio ? AnswerVerdict::Ok : AnswerVerdict::Doubtful;
        std::snprintf(text, sizeof text, "%s: the best answer of another basin scores %.2f of it (%s %.2f)",
                      toString(verdict), ratio, ratio < kBiplaneRivalRatio ? "below" : "at least", kBiplaneRivalRatio);
    } else {
        // No other basin left: every finalist, each from its own hypothesis, ended at this answer.
        verdict = finalists >= 2 ? AnswerVerdict::Ok : AnswerVerdict::Doubtful;
        std::snprintf(text, sizeof text, "%s: all %zu finalists ended at it (no other basin left to compare it with)",
                      toString(verdict), finalists);
    }
    return {verdict, text};
}

}  // namespace fm

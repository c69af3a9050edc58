#include "find/PoseFinder.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include "core/Error.h"
#include "core/Parallel.h"
#include "find/OrientedEdges.h"
#include "find/OutlineTemplates.h"
#include "find/RefineHypotheses.h"
#include "find/SeenPose.h"
#include "find/TemplateScan.h"
#include "scene/ObjectPoseParameterization.h"
#include "similarity/EdgeDistance.h"
#include "similarity/ImagePyramid.h"
#include "xray/CameraPoseDifference.h"
#include "xray/ConfirmedRegistration.h"
#include "xray/ObjectRegistration.h"

namespace fm {

namespace {

void validate(const FindSettings& s) {
    const auto powerOfTwo = [](int f) { return f >= 1 && (f & (f - 1)) == 0; };
    if (!powerOfTwo(s.maxScanFactor) || s.maxScanFactor < 2 || !powerOfTwo(s.refineFactor) || s.refineFactor < 2)
        throw Error("find: the scan and refinement factors must be powers of two, at least 2");
    if (!(s.minScanSpanPixels >= 4.0)) throw Error("find: the model must span at least 4 scan pixels");
    if (!(s.tiltStepDeg > 0.0 && s.rollStepDeg > 0.0 && s.scaleStep > 1.0 && s.capPixels > 0.0))
        throw Error("find: grid steps and the cap must be positive (the scale step above 1)");
    if (s.hypotheses < 1 || s.refineEvaluations < 1 || s.finalists < 1 || s.finalists > s.hypotheses)
        throw Error("find: at least one hypothesis, refinement evaluation and finalist (finalists <= hypotheses)");
}

// The scales of the scan: the band's depths as magnifications over the templates', in steps of
// at most `step`.
std::vector<double> scaleGrid(const FindSpace& space, double templateDepth, double distance, double step) {
    const double low = templateDepth / space.farDepth(distance);
    const double high = templateDepth / space.nearDepth(distance);
    const int gaps = std::max(1, static_cast<int>(std::ceil(std::log(high / low) / std::log(step) - 1e-9)));
    std::vector<double> scales;
    for (int k = 0; k <= gaps; ++k) scales.push_back(low * std::pow(high / low, double(k) / gaps));
    return scales;
}

// The poses whose outlines one view can barely tell from `pose`'s (parallel projection drops the
// depth): the object mirrored through the plane across the view at its pivot and back through
// each of its own axes' planes (a rotation again; for an object symmetric about that plane, or
// flat across it, the same outline), and its tilts reversed as the camera sees them (a plate seen
// nearly edge-on, tilted +a or -a).
std::vector<RigidTransform> lookalikePoses(const RigidTransform& pose, const glm::dvec3& pivotInObject,
                                           const CameraAxes& axes) {
    std::vector<RigidTransform> out;
    const glm::dvec3 centre = pose.applyToPoint(pivotInObject);
    const glm::dmat3 inWorld = glm::dmat3(1.0) - 2.0 * glm::outerProduct(axes.view, axes.view);
    for (int k = 0; k < 3; ++k) {
        glm::dmat3 inObject(1.0);
        inObject[k][k] = -1.0;
        RigidTransform mirrored;
        mirrored.rotation = inWorld * pose.rotation * inObject;
        mirrored.translation = centre - mirrored.rotation * pivotInObject;
        out.push_back(mirrored);
    }
    const SeenPose seen = seenFrom(axes, pose, pivotInObject);
    for (int flip = 0; flip < 2; ++flip) {
        SeenPose reversed = seen;
        (flip == 0 ? reversed.tiltUDeg : reversed.tiltVDeg) *= -1.0;
        out.push_back(worldFromSeen(axes, reversed, pivotInObject));
    }
    return out;
}

// The coarsest power of two up to maxScanFactor at which the model, seen along the optical axis at
// the band's far end, spans minScanSpanPixels (twice its outline's largest distance from the
// pivot: JTML's femoral component 236 px, the tray 175 px).
int scanFactorFor(const SceneObject& target, const CameraAxes& axes, const FindSettings& settings) {
    FindSpace flat = settings.space;
    flat.tiltDeg = 0.0;
    const OutlineTemplates probe = renderOutlineTemplates(target, axes, flat, 1.0, axes.spacing.x * 4.0, 1);
    const double far = settings.space.farDepth(axes.distance);
    const double spanPixels = 2.0 * probe.templates.front().radius * 4.0 * probe.depth / far;
    int factor = 2;
    while (factor * 2 <= settings.maxScanFactor && spanPixels / (factor * 2) >= settings.minScanSpanPixels) factor *= 2;
    return factor;
}

}  // namespace

double FoundPose::seconds() const { return findSeconds(stages); }

FoundPose findObjectPose(const Scene& scene, std::size_t object, const RegistrationView& view,
                         const RegistrationSettings& finish, const FindSettings& settings,
                         const std::atomic<bool>* stop) {
    validate(settings);
    if (object >= scene.objects.size())
        throw Error("find: object " + std::to_string(object + 1) + " is not in the scene");
    if (view.camera >= scene.cameras.size())
        throw Error("find: camera " + std::to_string(view.camera + 1) + " is not in the scene");
    const SceneObject& target = scene.objects[object];
    if (!target.model) throw Error("find: object '" + target.name + "' has no model");
    const ProjectionGeometry& camera = scene.cameras[view.camera];
    if (view.reference.width != camera.detector.size.x || view.reference.height != camera.detector.size.y)
        throw Error("find: the radiograph's size differs from camera " + std::to_string(view.camera + 1) + "'s");
    const CameraAxes axes = cameraAxes(camera);
    if (settings.space.farDepth(axes.distance) >= axes.distance) {
        char text[200];
        std::snprintf(text, sizeof text, "find: the depth band reaches %.0f mm from the source, beyond camera %zu's film "
                      "(%.0f mm): give depth=NEARmm:FARmm within it", settings.space.farDepth(axes.distance),
                      view.camera + 1, axes.distance);
        throw Error(text);
    }
    const glm::dvec3 pivot = defaultPivot(*target.model);
    const int threads = settings.threads > 0 ? settings.threads : defaultThreadCount();
    const auto stopped = [&] { return stop && stop->load(); };
    FoundPose found;

    // 1. Templates: one outline per pair of tilts, on the optical axis at the band's middle depth,
    //    at half the scan's pixel; the scan as coarse as keeps the model kMinScanSpanPixels wide at
    //    the band's far end (a probe template at 1/4 measures it).
    auto t0 = FindClock::now();
    const int scanFactor = scanFactorFor(target, axes, settings);
    const double scanPixelMm = axes.spacing.x * scanFactor;
    const OutlineTemplates templates = renderOutlineTemplates(
        target, axes, settings.space, settings.tiltStepDeg, axes.spacing.x * scanFactor / 2, threads);
    found.scanFactor = scanFactor;
    found.stages.push_back({"templates", secondsSince(t0), static_cast<int>(templates.templates.size()),
                            static_cast<int>(templates.templates.size())});

    // 2. Scan: the edges found at half the scan's pixel, pooled to it; every template turned,
    //    scaled and shifted over the whole image.
    t0 = FindClock::now();
    const OrientedDistances distances = orientedEdgeDistances(downsampleBy(view.reference, scanFactor / 2), 2);
    const Image& coarse = distances.distance[0];
    std::optional<Mask> coarseValid;
    if (view.valid) coarseValid = downsampleMaskBy(*view.valid, scanFactor);
    ScanGrid grid;
    grid.rollsDeg = evenGrid(settings.space.rollDeg, settings.rollStepDeg, settings.space.rollDeg >= 180.0);
    grid.scales = scaleGrid(settings.space, templates.depth, axes.distance, settings.scaleStep);
    grid.rollSign = axes.rollSign;
    grid.templateToScan = templates.pixelMm / scanPixelMm;
    grid.capPixels = settings.capPixels;
    const std::vector<ScanHypothesis> scanned =
        scanTemplates(distances, coarseValid ? &*coarseValid : nullptr, templates, grid, threads);
    const std::vector<ScanHypothesis> hypotheses =
        distinctBest(scanned, templates, grid, static_cast<std::size_t>(settings.hypotheses), settings.perPlace);
    found.stages.push_back({"scan", secondsSince(t0), static_cast<long long>(scanned.size()) * coarse.width * coarse.height,
                            static_cast<int>(hypotheses.size())});
    if (stopped()) {
        found.stopped = true;
        return found;
    }

    // 3. Refine: each hypothesis as a pose, polished at the refinement level (exact renders).
    t0 = FindClock::now();
    const auto poseOf = [&](const ScanHypothesis& h) {
        const OutlineTemplate& t = templates.templates[static_cast<std::size_t>(h.templateIndex)];
        SeenPose seen;
        // The scan pixel's centre in full-resolution pixel coordinates.
        seen.pixel = (glm::dvec2(h.position) + 0.5) * double(scanFactor) - 0.5;
        seen.depth = templates.depth / h.scale;
        seen.rollDeg = h.rollDeg;
        seen.tiltUDeg = t.tiltUDeg;
        seen.tiltVDeg = t.tiltVDeg;
        return worldFromSeen(axes, seen, pivot);
    };
    Scene alone = scene;
    for (std::size_t i = 0; i < alone.objects.size(); ++i) alone.objects[i].visible = i == object;
    SeenPose middle;
    middle.pixel = axes.principalPixel;
    middle.depth = templates.depth;
    const auto parameterization = std::make_shared<ObjectPoseParameterization>(
        target.name, camera, worldFromSeen(axes, middle, pivot), pivot, DepthSearch::AlongRay);
    const double atObject = scanPixelMm * templates.depth / axes.distance;  // a scan pixel at the middle depth
    const RegistrationSettings refine = refinementSettings(
        finish, {settings.refineFactor, settings.refineFactor / 2}, settings.refineEvaluations,
        {0.5 * atObject, 0.5 * atObject, templates.depth * (settings.scaleStep - 1.0), 0.5 * settings.tiltStepDeg,
         0.5 * settings.tiltStepDeg, 0.5 * settings.rollStepDeg});
    const Registration refinement(alone, parameterization, {view}, refine);
    std::vector<SceneParams> starts;
    for (const ScanHypothesis& h : hypotheses) starts.push_back(parameterization->paramsOf(poseOf(h)));
    struct Refined {
        RigidTransform pose;
        double cost = 0.0;
        int evaluations = 0;
        int hypothesis = 0;
    };
    std::vector<Refined> refined;
    int refineEvaluations = 0;
    for (const RefinedHypothesis& r : refineHypotheses(refinement, starts, threads, stop)) {
        refined.push_back({parameterization->worldFromObject(r.params), r.cost, r.evaluations, r.hypothesis});
        refineEvaluations += r.evaluations;
    }
    const std::size_t finalists = std::min(refined.size(), static_cast<std::size_t>(settings.finalists));
    found.stages.push_back({"refine", secondsSince(t0), refineEvaluations, static_cast<int>(finalists)});
    if (stopped()) {
        found.stopped = true;
        return found;
    }

    // 4. Finish: the best refined hypotheses registered fully, side by side; then the best
    //    answer's look-alikes (mirror images, reversed tilts: one view barely tells them apart),
    //    so that whichever of them the image prefers wins, and the other is seen as a rival.
    t0 = FindClock::now();
    // The view prepared once for all of them (pyramids, edge maps).
    const Registration full = prepareObjectRegistration(scene, object, view, finish);
    int finishEvaluations = 0;
    std::vector<FoundCandidate> answers;
    const auto registerAll = [&](const std::vector<Refined>& starts) {
        const int each = starts.size() >= static_cast<std::size_t>(threads) ? 1 : threads;
        std::vector<FoundCandidate> batch(starts.size());
        parallelFor(static_cast<int>(starts.size()), each == 1 ? threads : 1, [&](int begin, int end) {
            for (int k = begin; k < end; ++k) {
                const Refined& from = starts[static_cast<std::size_t>(k)];
                const ObjectRegistrationResult r =
                    registerObject(full, scene, object, view, from.pose, finish.seed, each, {}, stop);
                batch[static_cast<std::size_t>(k)] = {r.worldFromObject, r.similarity, from.hypothesis, r.evaluations};
            }
        }, 4);
        for (const FoundCandidate& c : batch) finishEvaluations += c.evaluations;
        answers.insert(answers.end(), batch.begin(), batch.end());
        std::stable_sort(answers.begin(), answers.end(),
                         [](const FoundCandidate& x, const FoundCandidate& y) { return x.similarity > y.similarity; });
    };
    registerAll(std::vector<Refined>(refined.begin(), refined.begin() + static_cast<std::ptrdiff_t>(finalists)));
    if (!stopped()) {
        std::vector<Refined> lookalikes;
        for (const RigidTransform& pose : lookalikePoses(answers.front().worldFromObject, pivot, axes))
            lookalikes.push_back({pose, 0.0, 0, answers.front().hypothesis});
        registerAll(lookalikes);
    }
    for (const FoundCandidate& a : answers) {
        const bool same = std::any_of(found.candidates.begin(), found.candidates.end(), [&](const FoundCandidate& c) {
            const CameraPoseDifference d = cameraPoseDifference(camera, c.worldFromObject, a.worldFromObject, pivot);
            return sameAnswerInView(d);
        });
        if (!same) found.candidates.push_back(a);
    }
    found.stages.push_back({"finish", secondsSince(t0), finishEvaluations, static_cast<int>(found.candidates.size())});
    found.stopped = stopped();
    return found;
}

}  // namespace fm

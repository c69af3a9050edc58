#include "find/ViewFinder.h"

#include <algorithm>
#include <cmath>

#include "core/Error.h"
#include "core/Parallel.h"
#include "find/OutlineTemplates.h"
#include "find/RefineHypotheses.h"
#include "match/MatchVerdict.h"
#include "scene/CoarseVolumes.h"
#include "scene/SceneParameterization.h"
#include "scene/VolumeScene.h"
#include "similarity/ImagePyramid.h"

namespace fm {

namespace {

void validate(const ViewFindSettings& s) {
    if (!(s.templateStepDeg > 0.0 && s.rollStepDeg > 0.0 && s.scaleStep > 1.0))
        throw Error("find: grid steps must be positive (the scale step above 1)");
    if (s.scanPixels < 8 || s.rescored < 1 || s.hypotheses < 1 || s.refineEvaluations < 1 || s.finalists < 1 ||
        s.finalists > s.hypotheses)
        throw Error("find: the scan needs 8 pixels, and at least one rescored placement, hypothesis, refinement "
                    "evaluation and finalist (finalists <= hypotheses)");
}

// The rotation turning unit vector `a` onto unit vector `b` about their common perpendicular.
glm::dvec3 turnedLike(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& x) {
    const glm::dvec3 axis = glm::cross(a, b);
    const double sine = glm::length(axis), cosine = glm::dot(a, b);
    if (sine < 1e-15) return x;
    const glm::dvec3 k = axis / sine;
    return x * cosine + glm::cross(k, x) * sine + k * glm::dot(k, x) * (1.0 - cosine);
}

// A pyramid level of the reference with its pitch and principal point.
struct Level {
    Image image;
    double pitchMm = 1.0;
    glm::dvec2 principal{0.0};
    ViewScanImage scan() const { return {&image, pitchMm, principal}; }
};
Level levelOf(const Image& reference, const SceneSetup& setup, int factor) {
    Level l;
    l.image = downsampleBy(reference, factor);
    l.pitchMm = setup.filmSizeMm.x / setup.filmPixels.x * factor;
    // A level pixel is the mean of factor^2 film pixels: its centre sits (factor - 1) / 2 in.
    const glm::dvec2 centre = 0.5 * (glm::dvec2(setup.filmPixels) - 1.0);
    l.principal = (centre - 0.5 * (factor - 1)) / double(factor);
    return l;
}

}  // namespace

Pose placementPose(const ViewTemplate& view, const ViewPlacement& placement, const SceneSetup& setup,
                   const glm::dvec3& volumeCenter) {
    Pose unturned;
    unturned.azimuthDeg = view.azimuthDeg;
    unturned.elevationDeg = view.elevationDeg;
    const ProjectionGeometry g = sceneGeometry(unturned, setup, volumeCenter);
    const glm::dvec3 n = glm::normalize(glm::cross(g.detector.u, g.detector.v));  // along the beam
    // The film turned by the roll: a film point's coordinates turn counter-clockwise in (col, row).
    const double c = std::cos(glm::radians(placement.rollDeg)), s = std::sin(glm::radians(placement.rollDeg));
    const glm::dvec3 u1 = c * g.detector.u - s * g.detector.v, v1 = s * g.detector.u + c * g.detector.v;
    const double sid = setup.sourceToIsocenterMm + setup.isocenterToFilmMm;
    const double depth = setup.sourceToIsocenterMm / placement.scale;  // magnification ~ 1 / depth
    const glm::dvec3 toCentre = placement.shiftMm.x * u1 + placement.shiftMm.y * v1 + sid * n;
    const glm::dvec3 ray = glm::normalize(toCentre);
    ProjectionGeometry h = g;
    h.detector.u = turnedLike(ray, n, u1);
    h.detector.v = turnedLike(ray, n, v1);
    h.source = volumeCenter - depth * glm::length(toCentre) / sid * n;
    return poseOfSceneCamera(h, setup, volumeCenter);
}

FoundView findScenePose(const DrrVolumePtr& volume, const SceneSetup& setup, const glm::dvec3& volumeCenter,
                        const Image& reference, const RegistrationSettings& finish, const ViewFindSettings& settings,
                        const std::atomic<bool>* stop, const FindStageCallback& onStage) {
    validate(settings);
    validateSceneSetup(setup);
    if (!volume) throw Error("find: no volume");
    if (reference.width != setup.filmPixels.x || reference.height != setup.filmPixels.y)
        throw Error("find: the reference's size differs from the film's");
    const auto [low, high] = std::minmax_element(reference.pixels.begin(), reference.pixels.end());
    if (!(*high > *low)) throw Error("find: the reference is uniform (nothing of the CT on the film?): nothing to find");
    const int threads = settings.threads > 0 ? settings.threads : defaultThreadCount();
    const auto stopped = [&] { return stop && stop->load(); };
    FoundView found;
    int scanFactor = 1;  // the finer scan image: at least scanPixels across
    while (std::min(setup.filmPixels.x, setup.filmPixels.y) / (scanFactor * 2) >= settings.scanPixels) scanFactor *= 2;
    if (scanFactor < 2) throw Error("find: the film needs at least " + std::to_string(2 * settings.scanPixels) + " pixels");
    const Level fine = levelOf(reference, setup, scanFactor), coarse = levelOf(reference, setup, 2 * scanFactor);

    // The reach of the offsets: their largest part across the film and along the beam.
    const double reach = settings.space.offsetMm * std::sqrt(3.0);
    const double s = setup.sourceToIsocenterMm, sid = s + setup.isocenterToFilmMm;
    const double maxShiftMm = reach * sid / (s - std::min(reach, 0.5 * s));

    // 1. Templates at the finer scan's pitch through block means no coarser than its rays at the
    //    isocenter, on a film wide enough for every turn, scale and shift.
    const auto starting = [&](const char* stage) {
        if (onStage) onStage(stage);
    };
    starting("templates");
    auto t0 = FindClock::now();
    const double pitch = fine.pitchMm;
    const glm::dvec3 voxel = drrVolumeInfo(*volume).spacing;
    const int coarsen = coarseningFactor(std::min({voxel.x, voxel.y, voxel.z}), pitch * s / sid, 1.25);
    const DrrVolumePtr traced = coarsen > 1 ? coarsenDrrVolume(*volume, coarsen, threads) : volume;
    ViewScanGrid grid;
    grid.rollsDeg = evenGrid(settings.space.rotationDeg, settings.rollStepDeg);
    const double lowScale = s / (s + reach), highScale = s / (s - std::min(reach, 0.5 * s));
    const int gaps = std::max(1, static_cast<int>(std::ceil(std::log(highScale / lowScale) / std::log(settings.scaleStep))));
    for (int k = 0; k <= gaps; ++k) grid.scales.push_back(lowScale * std::pow(highScale / lowScale, double(k) / gaps));
    const double halfFilm = 0.5 * glm::length(glm::dvec2(fine.image.width, fine.image.height)) * pitch + maxShiftMm;
    const int halfPixels = static_cast<int>(std::ceil(halfFilm / (lowScale * pitch))) + 2;
    const ViewTemplates templates = renderViewTemplates(*traced, setup, volumeCenter, settings.space,
                                                        settings.templateStepDeg, pitch, halfPixels, threads);
    found.stages.push_back({"templates", secondsSince(t0), static_cast<long long>(templates.templates.size()),
                            static_cast<int>(templates.templates.size())});

    // 2. Scan: every placement on the coarser image, the best again on the finer one.
    starting("scan");
    t0 = FindClock::now();
    std::vector<ViewPlacement> placed = scanViews(coarse.scan(), halvedTemplates(templates), grid, maxShiftMm, threads);
    const int shifts = 2 * scanShiftPixels(maxShiftMm, coarse.pitchMm) + 1;
    const long long placements = static_cast<long long>(placed.size()) * shifts * shifts;
    std::stable_sort(placed.begin(), placed.end(), [](const ViewPlacement& a, const ViewPlacement& b) { return a.ncc > b.ncc; });
    placed.resize(std::min(placed.size(), static_cast<std::size_t>(settings.rescored)));
    placed = rescoreViews(fine.scan(), templates, std::move(placed), 2, threads);
    const std::vector<ViewPlacement> hypotheses =
        distinctViews(std::move(placed), templates, grid, 2.0 * pitch, static_cast<std::size_t>(settings.hypotheses));
    found.stages.push_back({"scan", secondsSince(t0), placements, static_cast<int>(hypotheses.size())});
    const auto poseOf = [&](const ViewPlacement& h) {
        return placementPose(templates.templates[static_cast<std::size_t>(h.templateIndex)], h, setup, volumeCenter);
    };
    if (stopped()) {  // the scan's best as it stands (its similarity: the scan's NCC)
        found.stopped = true;
        if (!hypotheses.empty()) found.candidates.push_back({poseOf(hypotheses.front()), hypotheses.front().ncc, 0, 0});
        return found;
    }

    // 3. Refine: each hypothesis polished at the scan's level and the next finer one.
    starting("refine");
    t0 = FindClock::now();
    const auto parameterization = std::make_shared<Pose2011Parameterization>(setup, volumeCenter);
    const Scene scene = volumeScene(volume);
    const double atIsocenter = pitch * s / sid;
    const Registration refinement(
        scene, parameterization, {{0, reference, {}}},
        refinementSettings(finish, {scanFactor, scanFactor / 2}, settings.refineEvaluations,
                           {0.5 * atIsocenter, 0.5 * atIsocenter, s * (settings.scaleStep - 1.0),
                            0.5 * settings.templateStepDeg, 0.5 * settings.templateStepDeg, 0.5 * settings.rollStepDeg}));
    std::vector<SceneParams> starts;
    for (const ViewPlacement& h : hypotheses) starts.push_back(poseOf(h).toArray());
    const std::vector<RefinedHypothesis> refined = refineHypotheses(refinement, starts, threads, stop);
    int refineEvaluations = 0;
    for (const RefinedHypothesis& r : refined) refineEvaluations += r.evaluations;
    const std::size_t finalists = std::min(refined.size(), static_cast<std::size_t>(settings.finalists));
    found.stages.push_back({"refine", secondsSince(t0), refineEvaluations, static_cast<int>(finalists)});
    if (stopped()) {  // the refinement's best as it stands (its similarity at 1/4)
        found.stopped = true;
        if (!refined.empty())
            found.candidates.push_back({Pose::fromArray(refined.front().params), -refined.front().cost,
                                        refined.front().hypothesis, refined.front().evaluations});
        return found;
    }

    // 4. Finish: the finalists registered fully, side by side.
    starting("finish");
    t0 = FindClock::now();
    const Registration full(scene, parameterization, {{0, reference, {}}}, finish);
    const int each = finalists >= static_cast<std::size_t>(threads) ? 1 : threads;
    std::vector<ViewCandidate> answers(finalists);
    parallelFor(static_cast<int>(finalists), each == 1 ? threads : 1, [&](int begin, int end) {
        for (int k = begin; k < end; ++k) {
            const Registration mine(full, parameterization, each);
            const RegistrationResult r = mine.run(refined[static_cast<std::size_t>(k)].params, {}, stop);
            answers[static_cast<std::size_t>(k)] = {r.pose(), r.similarity, refined[static_cast<std::size_t>(k)].hypothesis,
                                                    r.evaluations};
        }
    }, 4);
    int finishEvaluations = 0;
    for (const ViewCandidate& a : answers) finishEvaluations += a.evaluations;
    std::stable_sort(answers.begin(), answers.end(),
                     [](const ViewCandidate& x, const ViewCandidate& y) { return x.similarity > y.similarity; });
    for (const ViewCandidate& a : answers) {
        // One answer when the 2011 game's judge would call them a match (every number within its
        // tolerance: 2 mm, 2 deg).
        const bool same = std::any_of(found.candidates.begin(), found.candidates.end(), [&](const ViewCandidate& c) {
            return judgeMatch(c.pose, a.pose, 0.0).match;
        });
        if (!same) found.candidates.push_back(a);
    }
    found.stages.push_back({"finish", secondsSince(t0), finishEvaluations, static_cast<int>(found.candidates.size())});
    found.stopped = stopped();
    return found;
}

}  // namespace fm

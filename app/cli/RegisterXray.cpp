#include "cli/RegisterXray.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <vector>

#include "camera/CameraFile.h"
#include "cli/ValueChecks.h"
#include "core/Error.h"
#include "find/FindSpace.h"
#include "find/FoundRegistration.h"
#include "find/SeenPose.h"
#include "meshdrr/MeshDrr.h"
#include "model/MeshModel.h"
#include "radiograph/LabelMask.h"
#include "radiograph/Radiograph.h"
#include "radiograph/RadiographPreparation.h"
#include "scene/MeshXrayModel.h"
#include "scene/ObjectPoseParameterization.h"
#include "xray/AnswerCheck.h"
#include "xray/CameraPoseDifference.h"
#include "xray/ConfirmedRegistration.h"
#include "xray/ModelCoverage.h"
#include "xray/ObjectRegistration.h"
#include "xray/PoseSpec.h"

namespace fm::cli {

namespace {

bool isTra(const std::string& path) {
    return path.size() > 4 && (path.substr(path.size() - 4) == ".tra" ||
                               path.substr(path.size() - 4) == ".TRA");
}

// The file for model k of a list that holds one per model or a single .tra for all.
const std::string& perModel(const std::vector<std::string>& list, std::size_t k,
                            std::size_t models, const char* option) {
    if (list.size() == models) return list[k];
    if (list.size() == 1 && isTra(list[0])) return list[0];
    throw Error(std::string(option) + ": give one per --model (" + std::to_string(models) +
                ") or a single .tra for all");
}

// How a model's pose was found: the stages, and the answer as the camera sees it.
void printFound(const FoundPose& found, const ProjectionGeometry& camera, const glm::dvec3& pivot) {
    for (const std::string& line : describeFindStages(found.stages)) std::printf("found       %s\n", line.c_str());
    const SeenPose seen = seenFrom(cameraAxes(camera), found.candidates.front().worldFromObject, pivot);
    std::printf("found at    pixel %.1f %.1f, depth %.1f mm, roll %.1f deg, tilts %.1f %.1f deg (as the camera "
                "sees it; scan at 1/%d, %.2f s)\n",
                seen.pixel.x, seen.pixel.y, seen.depth, seen.rollDeg, seen.tiltUDeg, seen.tiltVDeg,
                found.scanFactor, found.seconds());
}

}  // namespace

void addXrayRegisterOptions(CLI::App* cmd, XrayRegisterArgs& a) {
    cmd->add_option("--camera", a.camera,
                    "Calibration of --reference (MayaCam 2.0/1.0, JointTrack JT_INTCALIB or "
                    "geometry JSON): real X-ray mode, with --model");
    cmd->add_option("--model", a.models, "Implant or bone model (.stl, .ply, .obj); repeatable");
    cmd->add_option("--out", a.outs,
                    "Write the found pose: .jts (one per model) or .tra (one for all); with "
                    "--trial: the .tra of the result at --frame");
    cmd->add_option("--mask", a.masks,
                    "Label mask per model (binary image): the silhouette IoU is reported");
    cmd->add_option("--mu", a.mu, "Model attenuation 1/mm (default 1.2, cobalt-chromium)");
    cmd->add_option("--tra-form", a.traForm,
                    "How a --start .tra's numbers divide when their count does not say (48 a row: 3 "
                    "matrices or 8 xyzypr rows): matrix or xyzypr")
        ->check(oneOf({"matrix", "xyzypr"}, ".tra form"));
    cmd->add_option("--runs", a.runs,
                    "Searches per model from independent starts (the first from --start, the others "
                    "drawn around it); the answer is confirmed when two end at the same pose (1 = one "
                    "search, unconfirmed)")
        ->check(CLI::Range(1, 16))
        ->capture_default_str();
    cmd->add_option("--max-runs", a.maxRuns,
                    "While no two searches agree, search again from further starts up to this many")
        ->check(CLI::Range(1, 32))
        ->capture_default_str();
    cmd->add_option("--find-space", a.findSpace,
                    "Where a model with no start is looked for (no --start, or 'find' in its place): "
                    "tilt=DEG (about the film axes from the model's frame as the camera sees it, default "
                    "35), roll=DEG (about the ray, default 180: any), depth=NEAR:FAR (fractions of the "
                    "source-to-detector distance, default 0.25:0.92)");
    addPageOption(cmd, a.page, "Page of a multi-page TIFF reference (0-based)");
    addRadiographOptions(cmd, a.prep);
}

ConfirmationSettings confirmationFrom(const XrayRegisterArgs& a) {
    if (a.maxRuns < a.runs)
        throw Error("--max-runs (" + std::to_string(a.maxRuns) + ") must be at least --runs (" +
                    std::to_string(a.runs) + ")");
    ConfirmationSettings c;
    c.runs = a.runs;
    c.maxRuns = a.maxRuns;
    return c;
}

void runXrayRegister(const std::string& reference, const XrayRegisterArgs& a,
                     const std::vector<std::string>& starts, const SearchArgs& search,
                     bool similarityGiven) {
    if (reference.empty()) throw Error("--model needs --reference IMG (the radiograph)");
    if (a.camera.empty()) throw Error("--model needs --camera CALIB (the radiograph's calibration)");
    const std::size_t n = a.models.size();
    // No --start: every model is found; `find` in a model's place finds that one.
    std::vector<bool> findPose(n, starts.empty());
    for (std::size_t k = 0; k < n && !starts.empty(); ++k) findPose[k] = perModel(starts, k, n, "--start") == "find";
    const bool finding = std::find(findPose.begin(), findPose.end(), true) != findPose.end();
    if (!finding && !a.findSpace.empty())
        throw Error("--find-space applies to models with no start; every --model has a --start");
    const FindSettings find = [&] {
        FindSettings f;
        if (!a.findSpace.empty()) f.space = parseFindSpace(a.findSpace, "--find-space");
        f.threads = search.threads;
        return f;
    }();
    if (!a.masks.empty() && a.masks.size() != n)
        throw Error("--mask: give one per --model (" + std::to_string(n) + ")");
    const ConfirmationSettings confirmation = confirmationFrom(a);
    if (!(a.mu >= 0.0) || a.mu > 1e3)
        throw Error("--mu must be 0 (the default) or a positive attenuation in 1/mm");
    // Everything that can be refused is checked before the search.
    std::vector<std::string> outPaths;
    for (std::size_t k = 0; k < n && !a.outs.empty(); ++k) {
        outPaths.push_back(perModel(a.outs, k, n, "--out"));
        checkPoseOutput(outPaths.back(), a.frame);
    }

    checkPageApplies(reference, a.page);
    const RadiographFile file = readRadiograph(reference, a.page);
    for (const auto& w : file.warnings)
        std::fprintf(stderr, "warning: %s: %s\n", reference.c_str(), w.c_str());
    const glm::ivec2 size(file.image.width, file.image.height);
    const CameraReadResult cam = readCameraFile(a.camera, size);
    checkImageSize(cam.camera, a.camera, size.x, size.y, reference);
    const PreparedRadiograph prepared =
        prepareRadiograph(file.image, preparationFrom(a.prep, file.bitsPerSample));
    if (prepared.valid.count() == 0)
        throw Error(reference + ": no valid pixel is left after the preparation flags");

    std::vector<Mask> labels;
    for (const std::string& m : a.masks) labels.push_back(readLabelMask(m, size));

    Scene scene;
    scene.cameras.push_back(toProjectionGeometry(cam.camera, a.camera));
    std::vector<RigidTransform> startPoses;
    for (std::size_t k = 0; k < n; ++k) {
        const MeshModel model = loadMeshModel(a.models[k]);
        const double mu = a.mu > 0.0 ? a.mu : kMuCobaltChromePerMm;
        // Models are told apart by position: the same file name twice gets implant, implant_2.
        const std::string name =
            uniqueObjectName(scene, std::filesystem::path(a.models[k]).stem().string());
        auto xray = std::make_shared<MeshXrayModel>(prepareMeshDrr(model), mu, name);
        if (findPose[k]) {
            startPoses.emplace_back();  // replaced by the pose found
        } else {
            const std::string& spec = perModel(starts, k, n, "--start");
            const bool one = starts.size() != n;  // one .tra for all models
            startPoses.push_back(readPoseSpec(spec, a.frame, one ? k : 0, one ? static_cast<int>(n) : 0,
                                              a.traForm.empty() ? TraForm::Auto : parseTraForm(a.traForm, "--tra-form")));
        }
        scene.objects.push_back({name, xray, startPoses.back(), true});
    }
    // A start that covers no valid pixel leaves the search blind: refused with the numbers.
    for (std::size_t k = 0; k < n; ++k) {
        if (findPose[k]) continue;
        const std::string blind = blindness(
            modelCoverage(scene.objects[k], scene.cameras[0], prepared.valid, search.threads));
        if (!blind.empty())
            throw Error(a.models[k] + " at its start " + formatPoseSpec(startPoses[k]) + " (" +
                        perModel(starts, k, n, "--start") + ", camera " + a.camera + ") " + blind);
    }
    SearchArgs given = search;
    if (!similarityGiven) given.similarity = toString(SimilarityMeasure::EdgeDistance);
    const RegistrationSettings settings = registrationSettings(given, realXraySettings());
    std::printf("reference   %s (%s, %d x %d), %zu of %zu pixels valid\n", reference.c_str(),
                file.format.c_str(), size.x, size.y, prepared.valid.count(),
                prepared.valid.inside.size());
    std::printf("camera      %s (%s)\n", a.camera.c_str(), cam.format.c_str());
    const bool sideBySide = registersSideBySide(n * static_cast<std::size_t>(a.runs), settings);
    std::printf("search      %s, %s, seed %llu, %s, %d %s per model%s, %s\n",
                toString(settings.method), toString(settings.similarity),
                static_cast<unsigned long long>(settings.seed), describeLevels(settings).c_str(),
                a.runs, a.runs == 1 ? "search" : "searches from independent starts",
                a.runs > 1 ? (" (up to " + std::to_string(a.maxRuns) + " while no two agree)").c_str() : "",
                sideBySide ? "side by side, one per core" : "one after the other");
    if (finding) std::printf("find        %s\n", describeFindSpace(find.space).c_str());
    const RegistrationView view{0, prepared.image, prepared.valid};
    const auto started = std::chrono::steady_clock::now();
    const FoundRegistration result = registerObjectsFinding(scene, findPose, view, settings, find, confirmation);
    const ObjectsRegistration& all = result.registration;
    const double wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    std::vector<std::string> lost, doubtful;
    for (std::size_t k = 0; k < n; ++k) {
        SceneObject& object = scene.objects[k];
        const ConfirmedObject& c = all.objects[k];
        const ObjectRegistrationResult& r = c.answer;
        object.worldFromObject = r.worldFromObject;
        const glm::dvec3 pivot = defaultPivot(*object.model);
        std::printf("\nmodel       %s (%s)\n", a.models[k].c_str(), object.model->describe().c_str());
        if (const std::optional<FoundPose>& found = result.found[k]) {
            if (found->candidates.empty()) throw Error(a.models[k] + ": stopped before a pose was found");
            startPoses[k] = found->candidates.front().worldFromObject;
            printFound(*found, scene.cameras[0], pivot);
        }
        std::printf("start       %s%s\n", formatPoseSpec(startPoses[k]).c_str(), findPose[k] ? " (found)" : "");
        std::printf("final pose  %s\n", formatPoseSpec(r.worldFromObject).c_str());
        const CameraPoseDifference d =
            cameraPoseDifference(scene.cameras[0], startPoses[k], r.worldFromObject, pivot);
        std::printf("moved       in-plane %.3f mm (u %.3f, v %.3f), depth %.3f mm; rotation %.3f deg "
                    "(about the view %.3f, out of plane %.3f)\n",
                    d.inPlaneMm, d.translationMm.x, d.translationMm.y, d.depthMm, d.rotationDeg,
                    d.inPlaneRotationDeg, d.outOfPlaneRotationDeg);
        std::printf("similarity  %.5f (%s at the finest level)\n", r.similarity,
                    toString(settings.similarity));
        for (std::size_t i = 0; i < c.runs.size() && c.runs.size() > 1; ++i) {
            const CameraPoseDifference e =
                cameraPoseDifference(scene.cameras[0], r.worldFromObject, c.runs[i].worldFromObject, pivot);
            std::printf("run %-7zu similarity %.5f, from the answer in-plane %.3f mm, depth %+.3f mm, "
                        "rotation %.3f deg\n",
                        i + 1, c.runs[i].similarity, e.inPlaneMm, e.depthMm, e.rotationDeg);
        }
        AnswerEvidence evidence = c.evidence;
        if (!a.masks.empty()) {
            const Mask& label = labels[k];
            const Mask before = objectSilhouette(
                {object.name, object.model, startPoses[k], true}, scene.cameras[0], search.threads);
            const Mask after = objectSilhouette(object, scene.cameras[0], search.threads);
            evidence.iou = silhouetteIoU(after, label);
            std::printf("IoU         %.4f against %s (start %.4f)\n", *evidence.iou, a.masks[k].c_str(),
                        silhouetteIoU(before, label));
        }
        if (evidence.uncertainty)
            std::printf("uncertainty %s (camera frame)\n", describeUncertainty(*evidence.uncertainty).c_str());
        std::printf("time        %.3f s (%d evaluations in %zu %s%s)%s\n", r.seconds, r.evaluations,
                    c.runs.size(), c.runs.size() == 1 ? "search" : "searches",
                    evidence.uncertainty ? (", " + std::to_string(evidence.uncertainty->evaluations) +
                                            " more for the uncertainty").c_str()
                                         : "",
                    r.stopped ? " (stopped)" : "");
        std::printf("speed       %s\n", describeEvaluations(r.profile, sideBySide ? 1 : settings.threads).c_str());
        // A lost answer (the model walked off the image, the mask disagrees) is not written; a
        // doubtful one is, and says so.
        const AnswerCheck check = checkAnswer(object, r.worldFromObject, {view}, scene.cameras, evidence, search.threads);
        std::printf("verdict     %s\n", check.text.c_str());
        if (check.verdict == AnswerVerdict::Lost) {
            lost.push_back(a.models[k]);
            continue;
        }
        if (check.verdict == AnswerVerdict::Doubtful) doubtful.push_back(a.models[k]);
        if (!a.outs.empty()) {
            const std::string& out = outPaths[k];
            writePoseSpec(out, a.frame, a.outs.size() == n ? 0 : k, r.worldFromObject);
            std::printf("wrote       %s (frame %d)%s\n", out.c_str(), a.frame,
                        check.verdict == AnswerVerdict::Doubtful ? ", doubtful: check it before use" : "");
        }
    }
    for (const std::string& m : doubtful)
        std::fprintf(stderr, "warning: %s: the answer is doubtful (see its verdict line)\n", m.c_str());
    // Each model's time line is its searches' sum; this is the wall time of the whole answer
    // (searches, re-searches, uncertainty), also for one model whose searches ran side by side.
    std::printf("\ntotal time  %.3f s for %zu model%s (%s)\n", wallSeconds, n, n == 1 ? "" : "s",
                sideBySide ? "side by side" : "one after the other");
    if (!lost.empty()) {
        std::string names;
        for (const std::string& m : lost) names += (names.empty() ? "" : ", ") + m;
        throw Error("lost (nothing written for it): " + names);
    }
}

}  // namespace fm::cli

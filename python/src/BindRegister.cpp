// `register` from Python: implant or bone meshes against a real radiograph with its calibration,
// the same search as `fluoromatch register --reference IMG --camera CALIB --model M --start S`
// (xray/ObjectRegistration.h), with the CLI's options as keyword arguments and the same pose for
// the same seed. Every result says how sure it is (xray/AnswerCheck.h).
#include <algorithm>
#include <filesystem>
#include <optional>

#include <pybind11/stl.h>

#include "Arrays.h"
#include "Bindings.h"
#include "FindStages.h"
#include "Progress.h"
#include "Preparation.h"
#include "PyMesh.h"
#include "camera/CameraFile.h"
#include "core/Error.h"
#include "find/FoundRegistration.h"
#include "radiograph/LabelMask.h"
#include "radiograph/Radiograph.h"
#include "radiograph/RadiographPreparation.h"
#include "scene/MeshXrayModel.h"
#include "scene/ObjectPoseParameterization.h"
#include "search/SearchOptions.h"
#include "xray/AnswerCheck.h"
#include "xray/ConfirmedRegistration.h"
#include "xray/CameraPoseDifference.h"
#include "xray/ModelCoverage.h"
#include "xray/ObjectRegistration.h"
#include "xray/PoseSpec.h"

namespace fm::py {

namespace {

namespace fs = std::filesystem;

bool isPath(const pb::handle& h) {
    return pb::isinstance<pb::str>(h) || pb::isinstance(h, pb::module_::import("pathlib").attr("PurePath"));
}

std::vector<pb::object> listOf(const pb::object& value) {
    std::vector<pb::object> out;
    if (isPath(value) || pb::isinstance<PyMesh>(value) || pb::isinstance<pb::array>(value)) {
        out.push_back(value);
        return out;
    }
    for (const pb::handle& h : value) out.push_back(pb::reinterpret_borrow<pb::object>(h));
    return out;
}

pb::dict progressDict(const RegistrationProgress& p, const std::string& model) {
    pb::dict d;
    d["model"] = model;
    d["level"] = p.level;
    d["levels"] = p.levelCount;
    d["factor"] = p.factor;
    d["stage"] = p.stage;
    d["evaluations"] = p.evaluations;
    d["budget"] = p.evaluationBudget;
    d["best_cost"] = p.bestCost;
    d["seconds"] = p.seconds;
    return d;
}

}  // namespace

void bindRegister(pb::module_& m) {
    m.def(
        "register",
        [](const pb::object& reference, const pb::object& camera, const pb::object& models,
           const pb::object& start, int frame, const pb::object& out, const pb::object& mask, double mu,
           bool invert, bool log, std::optional<double> i0, std::optional<double> excludeBelow, int erode,
           std::optional<std::array<int, 4>> roi, int page, int bits, const std::string& traForm,
           const std::string& method, const std::string& similarity, std::uint64_t seed, int budget,
           int polishBudget, std::optional<std::vector<int>> levels, std::optional<std::vector<double>> radius,
           int threads, const std::string& polish, int runs, int maxRuns, const std::string& findSpace,
           const pb::object& progress) {
            // 1. Everything that can be refused, before the search.
            if (runs < 1 || runs > 16) throw Error("runs must be 1 to 16 (searches from independent starts)");
            if (maxRuns < runs || maxRuns > 32) throw Error("max_runs must be at least runs and at most 32");
            const std::vector<pb::object> modelList = listOf(models);
            const std::size_t n = modelList.size();
            if (n == 0) throw Error("models: give at least one model");
            // No start: every model is found (engine/find); None or "find" in a model's place finds that one.
            const std::vector<pb::object> starts = start.is_none() ? std::vector<pb::object>(n, pb::none()) : listOf(start);
            const bool oneTra = starts.size() == 1 && n > 1 && isPath(starts[0]) &&
                                fs::path(starts[0].cast<std::string>()).extension() == ".tra";
            if (starts.size() != n && !oneTra)
                throw Error("start: give one per model (" + std::to_string(n) + ") or a single .tra for all");
            std::vector<bool> findPose(n, false);
            for (std::size_t k = 0; k < n && !oneTra; ++k)
                findPose[k] = starts[k].is_none() ||
                              (pb::isinstance<pb::str>(starts[k]) && starts[k].cast<std::string>() == "find");
            const bool finding = std::find(findPose.begin(), findPose.end(), true) != findPose.end();
            if (!finding && !findSpace.empty())
                throw Error("find_space applies to models with no start; every model has a start");
            FindSettings find;
            if (!findSpace.empty()) find.space = parseFindSpace(findSpace, "find_space");
            find.threads = threads;
            if (!(mu >= 0.0) || mu > 1e3) throw Error("mu must be 0 (the default) or a positive attenuation in 1/mm");
            std::vector<std::string> outs;
            if (!out.is_none())
                for (const pb::object& o : listOf(out)) outs.push_back(pb::str(o).cast<std::string>());
            const bool oneOutTra = outs.size() == 1 && n > 1 && fs::path(outs[0]).extension() == ".tra";
            if (!outs.empty() && outs.size() != n && !oneOutTra)
                throw Error("out: give one per model (" + std::to_string(n) + ") or a single .tra for all");
            for (const std::string& o : outs) checkPoseOutput(o, frame);
            const TraForm form = traForm == "auto" ? TraForm::Auto : parseTraForm(traForm, "tra_form");
            SearchOptions options;
            options.method = method;
            options.similarity = similarity;
            options.polish = polish;
            options.seed = seed;
            options.budget = budget;
            options.polishBudget = polishBudget;
            if (levels && levels->empty()) throw Error("levels: give at least one factor");
            options.levels = levels.value_or(std::vector<int>{});
            options.radius = radius.value_or(std::vector<double>{});
            options.threads = threads;
            options.prefix = "";
            // `fluoromatch register --model`'s search: the same settings for the same words.
            const RegistrationSettings settings = applySearchOptions(options, realXraySettings());

            // 2. The radiograph, its calibration, its preparation (`radiograph` options).
            std::string referenceName = "reference image";
            Image image;
            if (isPath(reference)) {
                referenceName = pb::str(reference).cast<std::string>();
                RadiographFile file = readRadiograph(referenceName, page);
                image = std::move(file.image);
                bits = file.bitsPerSample;
            } else {
                image = arrayToImage(reference, "reference");
            }
            const glm::ivec2 size(image.width, image.height);
            PinholeCamera cam;
            std::string cameraName = "camera";
            if (pb::isinstance<PinholeCamera>(camera)) {
                cam = camera.cast<PinholeCamera>();
            } else {
                cameraName = pb::str(camera).cast<std::string>();
                cam = readCameraFile(cameraName, size).camera;
            }
            checkImageSize(cam, cameraName, size.x, size.y, referenceName);
            const RadiographPreparation prep = preparationOf(invert, log, i0, excludeBelow, erode, roi, bits);
            const PreparedRadiograph prepared = prepareRadiograph(image, prep);
            if (prepared.valid.count() == 0)
                throw Error(referenceName + ": no valid pixel is left after the preparation options");
            std::vector<std::optional<Mask>> labels(n);
            if (!mask.is_none()) {
                const std::vector<pb::object> masks = listOf(mask);
                if (masks.size() != n) throw Error("mask: give one per model (" + std::to_string(n) + ")");
                for (std::size_t k = 0; k < n; ++k)
                    labels[k] = isPath(masks[k]) ? readLabelMask(pb::str(masks[k]).cast<std::string>(), size)
                                                 : arrayToMask(masks[k], "mask");
            }

            // 3. The scene: one object per model at its start pose, the camera.
            Scene scene;
            scene.cameras.push_back(toProjectionGeometry(cam, cameraName));
            std::vector<RigidTransform> startPoses;
            std::vector<std::string> names;
            for (std::size_t k = 0; k < n; ++k) {
                PyMesh loaded;
                const PyMesh* mesh = nullptr;
                std::string file = "model";
                if (pb::isinstance<PyMesh>(modelList[k])) {
                    mesh = &modelList[k].cast<const PyMesh&>();
                    file = mesh->source;
                } else {
                    file = pb::str(modelList[k]).cast<std::string>();
                    loaded.model = std::make_shared<MeshModel>(loadMeshModel(file));
                    loaded.mesh = loaded.model->mesh;
                    loaded.source = file;
                    mesh = &loaded;
                }
                const std::string name = uniqueObjectName(scene, fs::path(file).stem().string());
                auto xray = std::make_shared<MeshXrayModel>(mesh->tracedPtr(), mu > 0.0 ? mu : kMuCobaltChromePerMm, name);
                const pb::object& s = oneTra ? starts[0] : starts[k];
                if (findPose[k])
                    startPoses.emplace_back();  // replaced by the pose found
                else
                    startPoses.push_back(isPath(s) ? readPoseSpec(pb::str(s).cast<std::string>(), frame, oneTra ? k : 0,
                                                                  oneTra ? static_cast<int>(n) : 0, form)
                                                   : toTransform(s, "start"));
                scene.objects.push_back({name, xray, startPoses.back(), true});
                names.push_back(name);
            }
            for (std::size_t k = 0; k < n; ++k) {
                if (findPose[k]) continue;
                const std::string blind = blindness(modelCoverage(scene.objects[k], scene.cameras[0], prepared.valid, threads));
                if (!blind.empty()) throw Error(names[k] + " at its start " + formatPoseSpec(startPoses[k]) + " " + blind);
            }

            // 4. The searches: side by side, one per core, as the CLI runs them.
            ProgressRelay relay(progress);
            const RegistrationView view{0, prepared.image, prepared.valid};
            FoundRegistration result;
            {
                pb::gil_scoped_release unlock;
                ConfirmationSettings confirmation;
                confirmation.runs = runs;
                confirmation.maxRuns = maxRuns;
                result = registerObjectsFinding(
                    scene, findPose, view, settings, find, confirmation,
                    [&](std::size_t k) -> RegistrationCallback {
                        return [&, k](const RegistrationProgress& p) {
                            relay.report([&] { return progressDict(p, names[k]); });
                        };
                    },
                    relay.stopFlag());
            }
            const ObjectsRegistration& all = result.registration;
            const double wallSeconds = all.wallSeconds;
            relay.rethrowIfFailed();
            for (std::size_t k = 0; k < n; ++k)
                if (result.found[k]) {
                    if (result.found[k]->candidates.empty()) throw Error(names[k] + ": stopped before a pose was found");
                    startPoses[k] = result.found[k]->candidates.front().worldFromObject;
                }

            // 5. The answers, each with its verdict; written (like the CLI) unless lost.
            pb::list answers;
            for (std::size_t k = 0; k < n; ++k) {
                SceneObject& object = scene.objects[k];
                const ConfirmedObject& c = all.objects[k];
                const ObjectRegistrationResult& r = c.answer;
                object.worldFromObject = r.worldFromObject;
                std::optional<double> iou, startIou;
                if (labels[k]) {
                    iou = silhouetteIoU(objectSilhouette(object, scene.cameras[0], threads), *labels[k]);
                    startIou = silhouetteIoU(
                        objectSilhouette({object.name, object.model, startPoses[k], true}, scene.cameras[0], threads),
                        *labels[k]);
                }
                AnswerEvidence evidence = c.evidence;
                evidence.iou = iou;
                const AnswerCheck check = checkAnswer(object, r.worldFromObject, {view}, scene.cameras, evidence, threads);
                const CameraPoseDifference d = cameraPoseDifference(scene.cameras[0], startPoses[k], r.worldFromObject,
                                                                    defaultPivot(*object.model));
                pb::dict a;
                a["model"] = names[k];
                a["pose"] = fromTransform(r.worldFromObject);
                a["start"] = fromTransform(startPoses[k]);
                a["jts_row"] = formatPoseSpec(r.worldFromObject);
                a["similarity"] = r.similarity;
                a["measure"] = toString(settings.similarity);
                a["evaluations"] = r.evaluations;
                a["seconds"] = r.seconds;
                a["wall_seconds"] = wallSeconds;
                a["stopped"] = r.stopped;
                a["profile"] = profileDict(r.profile);
                a["verdict"] = toString(check.verdict);
                a["verdict_text"] = check.text;
                a["runs"] = c.evidence.runs;
                a["agreeing"] = c.evidence.agreeing;
                a["uncertainty"] = c.evidence.uncertainty ? uncertaintyDict(*c.evidence.uncertainty) : pb::object(pb::none());
                a["iou"] = iou ? pb::cast(*iou) : pb::none();
                a["start_iou"] = startIou ? pb::cast(*startIou) : pb::none();
                pb::dict moved;
                moved["in_plane_mm"] = d.inPlaneMm;
                moved["depth_mm"] = d.depthMm;
                moved["rotation_deg"] = d.rotationDeg;
                a["moved"] = moved;
                a["written"] = pb::none();
                a["found"] = pb::none();
                if (const std::optional<FoundPose>& f = result.found[k]) {
                    pb::dict found;
                    found["stages"] = findStagesList(f->stages);
                    found["scan_factor"] = f->scanFactor;
                    found["seconds"] = f->seconds();
                    found["rival_shortfall"] = c.evidence.rival ? pb::cast(c.evidence.rival->shortfallRatio) : pb::object(pb::none());
                    a["found"] = found;
                }
                if (!outs.empty() && check.verdict != AnswerVerdict::Lost && !r.stopped) {
                    const std::string& path = oneOutTra ? outs[0] : outs[k];
                    writePoseSpec(path, frame, oneOutTra ? k : 0, r.worldFromObject);
                    a["written"] = path;
                }
                answers.append(a);
            }
            return answers;
        },
        pb::arg("reference"), pb::arg("camera"), pb::arg("models"), pb::arg("start") = pb::none(), pb::kw_only(),
        pb::arg("frame") = 0, pb::arg("out") = pb::none(), pb::arg("mask") = pb::none(), pb::arg("mu") = 0.0,
        pb::arg("invert") = false, pb::arg("log") = false, pb::arg("i0") = pb::none(),
        pb::arg("exclude_below") = pb::none(), pb::arg("erode") = 3, pb::arg("roi") = pb::none(),
        pb::arg("page") = -1, pb::arg("bits") = 8, pb::arg("tra_form") = "auto", pb::arg("method") = "cmaes",
        pb::arg("similarity") = "edge", pb::arg("seed") = 1, pb::arg("budget") = 0, pb::arg("polish_budget") = -1,
        pb::arg("levels") = pb::none(), pb::arg("radius") = pb::none(), pb::arg("threads") = 0,
        pb::arg("polish") = "nm", pb::arg("runs") = 2, pb::arg("max_runs") = 4, pb::arg("find_space") = "",
        pb::arg("progress") = pb::none(),
        R"doc(
Registers implant or bone meshes in a real radiograph, as `fluoromatch register --reference IMG
--camera CALIB --model M ... --start S` does, with its options as keyword arguments (--exclude-
below is exclude_below, --polish-budget polish_budget, --tra-form tra_form; levels and radius
as lists). The same pose as the CLI for the same arguments and seed.

reference: a radiograph path or a (rows, cols) array (then bits= gives its full scale);
camera: a calibration path or a Camera; models: path(s) or Mesh(es); start: per model a .jts /
.tra path (row `frame`), six numbers as text, or a worldFromObject 4x4 array; one .tra for
all models; None (or "find" in a model's place) finds the pose with no start (docs/find.md;
find_space="tilt=35,roll=180,depth=0.25:0.92" as --find-space). mask: a label mask per model (path or boolean array): the silhouette IoU and the
verdict use it. out: .jts per model or one .tra, written as the CLI does (not when lost).
progress(dict) is called as the search goes; return False to stop it (Ctrl-C stops it too).

Returns one dict per model: pose (worldFromObject 4x4), start, jts_row, similarity, measure,
evaluations, seconds, wall_seconds, stopped, profile (where the evaluations' time went: thread
seconds of set_up, render, footprint, similarity), verdict ("ok", "doubtful" or "lost"; ok
needs a second search from another start ending there or a mask that agrees), verdict_text (the
reasons), runs and agreeing (searches from independent starts: `runs=` at first, up to
`max_runs=` while no two agree; the answer is the best), uncertainty (per camera-frame
coordinate u, v, depth mm and about u, v, view deg: the spread the image allows, "weak": the
weakly fixed ones), iou, start_iou, moved, written, found (for a model found with no start:
stages [{name, seconds, evaluations, kept}], scan_factor, seconds, rival_shortfall: the best
different answer's shortfall from a perfect outline over the answer's; else None).)doc");
}

}  // namespace fm::py

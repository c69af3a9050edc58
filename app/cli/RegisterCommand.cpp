// `fluoromatch register`: automatic pose search of a CT against one reference image, either a
// DRR rendered at a known pose (--reference-pose: the truth is known and the error reported) or
// an image file with its projection geometry (--reference IMG --geometry g.json). With
// --camera and --model it registers implant or bone models in a real radiograph instead
// (cli/RegisterXray.h).
#include <unistd.h>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <sstream>
#include <string>

#include "bones/BoneMotion.h"
#include "bones/BoneRegistration.h"
#include "bones/BoneScene.h"
#include "bones/BoneVolume.h"
#include "cli/BoneOptions.h"
#include "cli/CommandRegistry.h"
#include "cli/ModeOptions.h"
#include "cli/RegisterXray.h"
#include "cli/SearchCli.h"
#include "cli/SliceCli.h"
#include "cli/TrialRegister.h"
#include "cli/ValueChecks.h"
#include "cli/VolumeOption.h"
#include "core/Error.h"
#include "find/ViewFinder.h"
#include "match/PoseError.h"
#include "scene/VolumeScene.h"
#include "search/AnswerVerdict.h"
#include "search/ConfirmedSearch.h"
#include "search/Registration.h"
#include "search/RegistrationTargets.h"
#include "source/VolumeSource.h"

namespace {

struct RegisterArgs {
    std::string volume = fm::kDefaultVolumeSpec;
    std::string referencePose;
    std::string reference;
    std::string geometry;
    std::vector<std::string> start;  // one (2011 pose), or one per --model
    std::string truth;
    std::string pose;
    fm::cli::SearchArgs search;
    bool slice = false;
    fm::cli::SliceGridArgs grid;
    std::string interpolation = "cubic";
    fm::cli::BoneOptions bones;
    std::string boneMotion = "5,-5,5,5,-5,5";
    bool biplane = false;
    bool noRest = false;
    double marginMm = 20.0;
    fm::cli::XrayRegisterArgs xray;
};

// The one --start of the modes that take a single pose ("" = not given).
std::string singleStart(const RegisterArgs& a) {
    if (a.start.size() > 1)
        throw fm::Error("--start: give one pose (several --start are for several --model)");
    return a.start.empty() ? std::string() : a.start[0];
}

std::array<double, 6> parseSix(const std::string& text, const std::string& option) {
    std::array<double, 6> v{};
    std::stringstream ss(text);
    std::string item;
    int n = 0;
    while (std::getline(ss, item, ',')) {
        std::size_t used = 0;
        double x = 0.0;
        try {
            x = std::stod(item, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (n >= 6 || used != item.size() || item.empty() || !std::isfinite(x))
            throw fm::Error(option + ": expected six numbers tx,ty,tz (mm),rx,ry,rz (deg), got \"" +
                            text + "\"");
        v[n++] = x;
    }
    if (n != 6)
        throw fm::Error(option + ": expected six numbers tx,ty,tz (mm),rx,ry,rz (deg), got \"" +
                        text + "\"");
    return v;
}

// `register --bone`: one bone of the CT moved by --bone-motion in a synthetic reference (one
// view, or two with --biplane), registered alone from where the CT has it; the rest of the CT
// stays where it is (or is left out with --no-rest).
void runRegisterBone(const RegisterArgs& a) {
    if (a.bones.bone.empty() || !a.bones.without.empty())
        throw fm::Error("register takes --bone NAME (not --without)");
    if (a.bones.labels.empty())
        throw fm::Error("register --bone needs --labels (a label map, phantom:knee or components)");
    if (!(a.marginMm >= 0.0) || a.marginMm > 500.0)
        throw fm::Error("--footprint-margin must be 0..500 mm");
    const fm::RegistrationSettings settings = fm::cli::registrationSettings(a.search);
    const fm::Volume ct = fm::loadVolume(a.volume);
    const fm::LabelledVolume labels = fm::loadLabels(a.bones.labels, a.bones.table, ct);
    const fm::BoneSelection bone = fm::resolveBone(a.bones.bone, labels.table);
    fm::DrrValueOptions values;
    values.values = a.search.values == "raw" ? fm::DrrValues::Raw : fm::DrrValues::Mu;
    fm::Scene scene = fm::cli::boneSceneFor(ct, labels, bone, a.noRest, values);
    const fm::Pose view = a.pose.empty() ? fm::Pose{} : fm::parsePose(a.pose);
    const fm::SceneSetup setup = fm::defaultSceneSetup();
    scene.cameras.push_back(fm::sceneGeometry(view, setup, ct.center()));
    if (a.biplane) {
        fm::Pose side = view;
        side.azimuthDeg = fm::wrapDegrees(side.azimuthDeg + 90.0);
        scene.cameras.push_back(fm::sceneGeometry(side, setup, ct.center()));
    }
    // The truth: the bone turned about its own centre (world x, then y, then z), then shifted.
    const std::array<double, 6> m = parseSix(a.boneMotion, "--bone-motion");
    const glm::dvec3 centre = fm::boneCentroid(labels.labels, bone);
    const fm::RigidTransform truth = fm::boneMotionTransform(m, centre);
    fm::Scene moved = scene;
    moved.object(bone.name).worldFromObject = truth;
    std::vector<fm::Image> references;
    for (std::size_t c = 0; c < moved.cameras.size(); ++c)
        references.push_back(fm::renderView(moved, c, {}));
    const auto targets = fm::boneTargetPoints(fm::boneVolume(ct, labels.labels, bone), 200.0, 1000);

    std::printf("volume      %s (%d x %d x %d)\n", a.volume.c_str(), ct.dims.x, ct.dims.y, ct.dims.z);
    std::printf("bone        %s (%zu label%s), %zu other object%s static%s\n", bone.name.c_str(),
                bone.labels.size(), bone.labels.size() == 1 ? "" : "s", scene.objects.size() - 1,
                scene.objects.size() == 2 ? "" : "s", a.noRest ? ", the rest of the CT left out" : "");
    std::printf("reference   the bone moved by %s (mm; deg about its centre), %zu view%s\n",
                a.boneMotion.c_str(), references.size(), references.size() == 1 ? "" : "s");
    std::printf("search      %s, %s, seed %llu, %s\n", fm::toString(settings.method),
                fm::toString(settings.similarity), static_cast<unsigned long long>(settings.seed),
                fm::cli::describeLevels(settings).c_str());
    const fm::ConfirmationSettings confirmation = fm::cli::confirmationFrom(a.xray);
    fm::cli::ProgressBar bar(isatty(fileno(stderr)) != 0);
    const fm::BoneRegistrationResult r =
        fm::registerBone(scene, bone.name, references, settings, a.marginMm,
                         [&](const fm::RegistrationProgress& p) { bar.update(p); }, nullptr, confirmation);
    bar.finish();
    const auto before = fm::bonePoseError(scene.cameras[0], truth, {}, targets);
    const auto after = fm::bonePoseError(scene.cameras[0], truth, r.worldFromBone, targets);
    const auto rows = r.worldFromBone.toRowMajor4x4();
    std::printf("\nfound pose  worldFromBone (row-major 4x4):\n");
    for (int i = 0; i < 3; ++i)
        std::printf("            %10.6f %10.6f %10.6f %10.3f\n", rows[4 * i], rows[4 * i + 1],
                    rows[4 * i + 2], rows[4 * i + 3]);
    std::printf("mTRE        start %.3f mm -> final %.3f mm (in-plane %.3f mm, out-of-plane "
                "%.3f mm; %zu targets)\n",
                before.meanMm, after.meanMm, after.meanInPlaneMm, after.meanDepthMm, targets.size());
    std::printf("time        %.3f s (%d evaluations in %d %s)%s\n", r.search.seconds, r.search.evaluations,
                r.evidence.runs, r.evidence.runs == 1 ? "search" : "searches", r.search.stopped ? " (stopped)" : "");
    if (r.evidence.uncertainty)
        std::printf("uncertainty %s (camera 1's frame)\n", fm::describeUncertainty(*r.evidence.uncertainty).c_str());
    std::printf("verdict     %s\n", fm::judgeEvidence(r.evidence).text.c_str());
}

void printPoseRow(const char* label, const std::array<double, 6>& v) {
    std::printf("%-14s %9.3f %9.3f %9.3f %9.3f %9.3f %9.3f\n", label, v[0], v[1], v[2], v[3], v[4],
                v[5]);
}

// register's modes and the options each takes (cli/ModeOptions.h); the given options choose
// one, and the rest are refused before any work. In registerModes()'s order.
enum RegisterMode { kTrialMode, kModelMode, kSliceMode, kBoneMode, kPoseMode };

const std::vector<fm::cli::CommandMode>& registerModes() {
    static const std::vector<fm::cli::CommandMode> modes = [] {
        // The search options of cli/SearchCli.h (--values only where a CT's values are
        // integrated) and the real X-ray ones of cli/RegisterXray.h, as they are added.
        const auto withSearch = [](std::initializer_list<const char*> own) {
            fm::cli::SearchArgs scratch;
            return fm::cli::optionNames([&](CLI::App* c) { fm::cli::addSearchOptions(c, scratch); },
                                        own, {"values"});
        };
        std::vector<std::string> xray = withSearch({"reference", "start", "frame"});
        fm::cli::XrayRegisterArgs scratchXray;
        for (std::string& name : fm::cli::optionNames(
                 [&](CLI::App* c) { fm::cli::addXrayRegisterOptions(c, scratchXray); }))
            xray.push_back(std::move(name));
        // The tracker's search: its own settings, seeded; the radiograph flags over the trial's
        // preparation of its frames.
        fm::cli::RadiographOptions scratchPrep;
        const std::vector<std::string> trialOptions = fm::cli::optionNames(
            [&](CLI::App* c) { fm::cli::addRadiographOptions(c, scratchPrep); },
            {"trial", "bone", "frame", "cameras", "start", "out", "seed", "threads", "runs", "max-runs", "find-space"});
        return std::vector<fm::cli::CommandMode>{
            // The tracker's search, seeded; the radiograph flags over the trial's preparation.
            {"register --trial", "one bone in one frame of a trial, in its cameras", trialOptions},
            {"register --model", "models in a real radiograph", xray},
            {"register --slice", "a 2D image against slices of a volume",
             withSearch({"slice", "volume", "reference-pose", "reference", "start", "truth", "size",
                         "spacing", "thickness", "interpolation", "runs", "max-runs"})},
            {"register --bone", "one bone of a labelled CT against a reference it renders",
             withSearch({"volume", "labels", "label-table", "bone", "without", "bone-motion",
                         "pose", "biplane", "no-rest", "footprint-margin", "values", "runs", "max-runs"})},
            {"register", "a CT against one image, the 2011 pose",
             withSearch({"volume", "reference-pose", "reference", "geometry", "start", "truth",
                         "values", "runs", "max-runs", "find-space"})}};
    }();
    return modes;
}

RegisterMode registerMode(const RegisterArgs& a, const fm::cli::TrialRegisterArgs& trial) {
    if (!trial.trial.empty()) return kTrialMode;
    if (!a.xray.models.empty() || !a.xray.camera.empty()) return kModelMode;
    if (a.slice) return kSliceMode;
    if (!a.bones.bone.empty() || !a.bones.labels.empty() || !a.bones.without.empty())
        return kBoneMode;
    return kPoseMode;
}

void runRegister(const RegisterArgs& a, bool similarityGiven, int frame) {
    if (!a.xray.models.empty() || !a.xray.camera.empty()) {
        if (a.xray.models.empty()) throw fm::Error("--camera needs --model MODEL");
        fm::cli::XrayRegisterArgs xray = a.xray;
        xray.frame = frame;
        fm::cli::runXrayRegister(a.reference, xray, a.start, a.search, similarityGiven);
        return;
    }
    if (a.slice) {
        if (!a.geometry.empty())
            throw fm::Error("--slice: --geometry is the X-ray projection geometry; a slice "
                            "reference takes its pixel grid from the image (--spacing overrides)");
        fm::cli::SliceRegisterArgs s;
        s.volume = a.volume;
        s.referencePose = a.referencePose;
        s.reference = a.reference;
        s.start = singleStart(a);
        s.truth = a.truth;
        s.similarityGiven = similarityGiven;
        s.grid = a.grid;
        s.interpolation = a.interpolation;
        s.search = a.search;
        s.confirmation = fm::cli::confirmationFrom(a.xray);
        return fm::cli::runSliceRegister(s);
    }
    if (!a.bones.bone.empty() || !a.bones.labels.empty() || !a.bones.without.empty())
        return runRegisterBone(a);
    const bool synthetic = !a.referencePose.empty();
    if (synthetic == !a.reference.empty())
        throw fm::Error("give either --reference-pose POSE or --reference IMG --geometry g.json");
    if (!synthetic && a.geometry.empty())
        throw fm::Error("--reference needs --geometry g.json (the image's projection geometry)");
    fm::RegistrationSettings settings = fm::cli::registrationSettings(a.search);
    fm::cli::useWholeCtSpeedups(settings, a.search);
    // The 2011 scene with no start: the pose is found (find/ViewFinder.h). A calibrated camera
    // (--geometry) is its own start: the search begins there.
    const bool findPose = synthetic && singleStart(a).empty();
    if (!findPose && !a.xray.findSpace.empty())
        throw fm::Error("--find-space applies to register --reference-pose with no --start (the pose found from "
                        "nothing)");
    fm::ViewFindSettings find;
    if (!a.xray.findSpace.empty()) find.space = fm::parseViewSpace(a.xray.findSpace, "--find-space");
    find.threads = settings.threads;

    const fm::Volume volume = fm::loadVolume(a.volume);
    const fm::DrrVolumePtr prepared = fm::cli::prepareForSearch(volume, a.search.values);
    const fm::SceneSetup setup = fm::defaultSceneSetup();

    // The 2011 scene: the CT stays; its camera is the 2011 camera or the calibrated g.json
    // camera moved like it.
    std::shared_ptr<const fm::SceneParameterization> parameterization;
    std::function<fm::ProjectionGeometry(const fm::Pose&)> model;
    fm::Image reference;
    std::optional<fm::Pose> truth;
    if (synthetic) {
        truth = fm::parsePose(a.referencePose);
        auto p = std::make_shared<fm::Pose2011Parameterization>(setup, volume.center());
        model = [p](const fm::Pose& pose) { return p->geometry(pose); };
        parameterization = p;
        reference = fm::cli::renderReference(*prepared, model(*truth));
    } else {
        auto p = std::make_shared<fm::FixedCamera2011Parameterization>(
            fm::readGeometryFile(a.geometry), setup, volume.center());
        model = [p](const fm::Pose& pose) { return p->geometry(pose); };
        parameterization = p;
        reference = fm::cli::readReferenceImage(a.reference);
        if (!a.truth.empty()) truth = fm::parsePose(a.truth);
    }
    fm::Pose start;
    try {
        const std::string given = singleStart(a);
        if (!given.empty()) start = fm::parsePose(given);
    } catch (const fm::Error& e) {
        throw fm::Error(std::string("--start: ") + e.what());
    }

    std::printf("volume      %s (%d x %d x %d)\n", a.volume.c_str(), volume.dims.x, volume.dims.y,
                volume.dims.z);
    if (synthetic)
        std::printf("reference   DRR at pose %s (%d x %d)\n", fm::formatPose(*truth).c_str(),
                    reference.width, reference.height);
    else
        std::printf("reference   %s (%d x %d), geometry %s\n", a.reference.c_str(), reference.width,
                    reference.height, a.geometry.c_str());
    std::optional<fm::FoundView> found;
    if (findPose) {
        std::printf("find        %s\n", fm::describeViewSpace(find.space).c_str());
        found = fm::findScenePose(prepared, setup, volume.center(), reference, settings, find);
        for (const std::string& line : fm::describeFindStages(found->stages))
            std::printf("found       %s\n", line.c_str());
        start = found->candidates.front().pose;
        std::printf("found at    %s (%.2f s)\n", fm::formatPose(start).c_str(), fm::findSeconds(found->stages));
    } else {
        std::printf("start       %s\n", fm::formatPose(start).c_str());
    }
    const fm::Registration registration(fm::volumeScene(prepared), parameterization,
                                        {{0, reference, {}}}, settings);
    // The registration's own settings: levels finer than the voxels are left out.
    std::printf("search      %s, %s, seed %llu, %s\n", fm::toString(settings.method),
                fm::toString(settings.similarity), static_cast<unsigned long long>(settings.seed),
                fm::cli::describeLevels(registration.settings()).c_str());
    if (registration.levelCount() < static_cast<int>(settings.levelFactors.size()))
        std::printf("            (finer levels left out: their rays would resample the %.3g mm "
                    "voxels)\n",
                    std::min({fm::drrVolumeInfo(*prepared).spacing.x, fm::drrVolumeInfo(*prepared).spacing.y, fm::drrVolumeInfo(*prepared).spacing.z}));
    const fm::ConfirmationSettings confirmation = fm::cli::confirmationFrom(a.xray);
    std::printf("            %d %s%s\n", confirmation.runs,
                confirmation.runs == 1 ? "search" : "searches from independent starts",
                confirmation.runs > 1
                    ? (" (up to " + std::to_string(confirmation.maxRuns) + " while no two agree)").c_str()
                    : "");
    fm::cli::ProgressBar bar(isatty(fileno(stderr)) != 0);
    const fm::ConfirmedSearch confirmed = fm::runConfirmed(
        registration, start.toArray(), confirmation, [&](const fm::RegistrationProgress& p) { bar.update(p); });
    bar.finish();
    const fm::RegistrationResult& result = confirmed.answer;
    const fm::Pose finalPose = result.pose();

    std::printf("\nfinal pose  %s\n", fm::formatPose(finalPose).c_str());
    std::printf("similarity  %.5f (%s at the finest level)\n", result.similarity,
                fm::toString(settings.similarity));
    // The bone's target points (mTRE), made once if needed.
    std::optional<std::vector<glm::dvec3>> targetPoints;
    const auto targets = [&]() -> const std::vector<glm::dvec3>& {
        if (!targetPoints) targetPoints = fm::registrationTargets(volume);
        return *targetPoints;
    };
    if (truth) {
        std::printf("\n%-14s %9s %9s %9s %9s %9s %9s\n", "", "x mm", "y mm", "z mm", "az deg",
                    "el deg", "rot deg");
        printPoseRow("truth", truth->toArray());
        printPoseRow(found ? "found error" : "start error", fm::poseDifference(*truth, start));
        printPoseRow("final error", fm::poseDifference(*truth, finalPose));
        const fm::TargetRegistrationError before =
            fm::targetRegistrationError(model(*truth), model(start), targets());
        const fm::TargetRegistrationError after =
            fm::targetRegistrationError(model(*truth), model(finalPose), targets());
        std::printf(
            "\nmTRE        %s %.3f mm -> final %.3f mm (in-plane %.3f mm, "
            "out-of-plane %.3f mm; %zu targets)\n",
            found ? "found" : "start", before.meanMm, after.meanMm, after.meanInPlaneMm, after.meanDepthMm, targets().size());
    }
    std::printf("time        %.3f s (%d evaluations in %zu %s, %.2f ms each)%s\n", result.seconds,
                result.evaluations, confirmed.runs.size(), confirmed.runs.size() == 1 ? "search" : "searches",
                1000.0 * result.seconds / std::max(1, result.evaluations), result.stopped ? " (stopped)" : "");
    std::printf("speed       %s\n", fm::describeEvaluations(result.profile, settings.threads).c_str());
    // How sure, without the truth: the searches' agreement; for a reference this CT rendered, the
    // similarity against a perfect match's; the curvature at the answer.
    fm::AnswerEvidence evidence;
    evidence.runs = static_cast<int>(confirmed.runs.size());
    evidence.agreeing = confirmed.agreeing;
    evidence.stopped = result.stopped;
    if (confirmed.uncertainty.measured()) {
        evidence.uncertainty = confirmed.uncertainty;
        static const std::array<const char*, 6> names{"offset u", "offset v", "offset depth", "azimuth",
                                                      "elevation", "rotation"};
        evidence.coordinateNames = &names;
        std::printf("uncertainty %s (the CT offset along the start camera's axes)\n",
                    fm::describeUncertainty(confirmed.uncertainty, &names).c_str());
    }
    // A found pose (always on a rendered reference) is confirmed by the perfect match alone, from
    // a higher ratio: its confirming searches started around it and share its basin, right or wrong.
    const double ceiling = registration.referenceSelfSimilarity();
    if (synthetic)
        fm::judgeAgainstPerfectMatch(evidence, result.similarity, ceiling,
                                     found ? fm::kConfirmedFoundPerfectMatchRatio : fm::kConfirmedPerfectMatchRatio);
    if (found) {
        evidence.agreementConfirms = false;
        // The finder's second answer, if it is a different one (beyond the search radius: nearer, it
        // is the answer's own basin, e.g. a finalist stopped 2.9 deg short at 0.989 against 0.99998
        // on one hard knee draw, or the answer itself), is a rival.
        if (found->candidates.size() > 1) {
            const fm::ViewCandidate& other = found->candidates[1];
            const auto d = fm::poseDifference(finalPose, other.pose);
            const double inPlane =
                fm::targetRegistrationError(model(finalPose), model(other.pose), targets()).meanInPlaneMm;
            const double rotation = std::max({std::abs(d[3]), std::abs(d[4]), std::abs(d[5])});
            if (fm::beyondSearchRadius(settings.searchRadius, inPlane, rotation)) {
                evidence.rival = fm::rivalEvidence(result.similarity, other.similarity, ceiling, inPlane, rotation);
                std::printf("rival       %s (similarity %.5f)\n", fm::formatPose(other.pose).c_str(), other.similarity);
            }
        }
    }
    std::printf("verdict     %s\n", fm::judgeEvidence(evidence).text.c_str());
}

FM_REGISTER_COMMAND("register", 40, [](CLI::App& app) {
    auto* cmd = app.add_subcommand(
        "register", "Find the pose whose DRR matches a reference image (automatic search)");
    auto a = std::make_shared<RegisterArgs>();
    fm::cli::addVolumeOption(cmd, a->volume);
    auto* refPose = cmd->add_option("--reference-pose", a->referencePose,
                                    "Render the reference as a DRR at this pose x,y,z,az,el,rot "
                                    "(the truth: errors are reported)")
                        ->check(fm::cli::kPoseText);
    auto* ref = cmd->add_option("--reference", a->reference,
                                "Reference image (.png, .mha/.mhd: values like a DRR line "
                                "integral, bright = more attenuation)");
    refPose->excludes(ref);
    cmd->add_option("--geometry", a->geometry, "Projection geometry JSON of --reference");
    cmd->add_option("--start", a->start,
                    "Start pose x,y,z,az,el,rot (none: with --reference-pose the pose is found from "
                    "nothing, see --find-space; with --geometry the calibrated camera); with --model: a .jts or "
                    ".tra file (row --frame) or x,y,z,zrot,xrot,yrot, one per --model (or one "
                    ".tra for all), 'find' for a model to be found (none given: all are found, "
                    "see --find-space); with --trial: a .tra (its pose at --frame; default the "
                    "trial's keyframe)");
    cmd->add_option("--truth", a->truth, "True pose of --reference, if known (errors reported)")
        ->check(fm::cli::kPoseText);
    fm::cli::addSearchOptions(cmd, a->search);
    fm::cli::addBoneOptions(cmd, a->bones);
    cmd->add_option("--bone-motion", a->boneMotion,
                    "With --bone: the reference's motion of the bone, tx,ty,tz (mm), rx,ry,rz "
                    "(deg, about world x, y, z through the bone's centre)")
        ->capture_default_str();
    cmd->add_option("--pose", a->pose, "With --bone: the camera, a 2011 pose (default the AP view)")
        ->check(fm::cli::kPoseText);
    cmd->add_flag("--biplane", a->biplane, "With --bone: a second camera at azimuth +90 deg");
    cmd->add_flag("--no-rest", a->noRest, "With --bone: leave the rest of the CT out of the images");
    cmd->add_option("--footprint-margin", a->marginMm,
                    "With --bone: mm added around the bone's footprint (the compared pixels)")
        ->capture_default_str();
    cmd->add_flag("--slice", a->slice,
                  "MRI slice mode: match a 2D image with planar slices of the volume "
                  "(similarity mi by default; see docs/mri.md)");
    fm::cli::addSliceGridOptions(cmd, a->grid);
    cmd->add_option("--interpolation", a->interpolation,
                    "With --slice: cubic (B-spline, default) or linear")
        ->capture_default_str();
    fm::cli::addXrayRegisterOptions(cmd, a->xray);
    auto trial = std::make_shared<fm::cli::TrialRegisterArgs>();
    fm::cli::addTrialRegisterOptions(cmd, *trial);
    cmd->callback([a, trial, cmd] {
        const RegisterMode mode = registerMode(*a, *trial);
        fm::cli::refuseOptionsOutside(*cmd, registerModes()[mode], registerModes());
        if (mode == kPoseMode || mode == kSliceMode)
            for (std::string start : a->start)  // a 2011 pose here: checked before any work
                if (const std::string e = fm::cli::kPoseText(start); !e.empty())
                    throw CLI::ValidationError("--start: " + e);
        if (!trial->trial.empty()) {
            // --bone, --start and --out are the command's own; here they are the trial's bone,
            // a .tra holding its start pose at --frame and the .tra to write.
            trial->bone = a->bones.bone;
            if (a->start.size() > 1 || a->xray.outs.size() > 1)
                throw fm::Error("register --trial: give one --start .tra and one --out .tra");
            trial->start = a->start.empty() ? std::string() : a->start[0];
            trial->out = a->xray.outs.empty() ? std::string() : a->xray.outs[0];
            trial->seed = a->search.seed;
            trial->threads = a->search.threads;
            trial->confirmation = fm::cli::confirmationFrom(a->xray);
            trial->prep = a->xray.prep;
            trial->findSpace = a->xray.findSpace;
            fm::cli::runTrialRegister(*trial);
        } else {
            // --frame is shared: the trial's frame, or the row of --start/--out pose files.
            runRegister(*a, cmd->get_option("--similarity")->count() > 0,
                        cmd->get_option("--frame")->count() > 0 ? trial->frame : 0);
        }
    });
    return cmd;
});

}  // namespace

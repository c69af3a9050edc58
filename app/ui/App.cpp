#include "ui/App.h"

#include <imgui.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <chrono>
#include <filesystem>

#include "core/Error.h"
#include "geometry/PatientDirection.h"
#include "match/MatchVerdict.h"
#include "match/PoseError.h"
#include "mesh/MarchingCubes.h"
#include "platform/Gl.h"
#include "render/SceneRenderer.h"
#include "render/Texture.h"
#include "ui/PresentFrame.h"
#include "scene/Matching.h"
#include "scene/DisplaySurface.h"
#include "scene/SliceImages.h"

namespace fm::app {
namespace {

// While solving, the user pane follows the best pose at most every this many frames: an exact
// DRR costs tens of ms on the UI thread, which the search needs too.
constexpr std::uint64_t kSolveDisplayEveryFrames = 4;

double msSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

}  // namespace

App::App(RenderBackend& backend, AppOptions options)
    : backend_(backend), options_(std::move(options)), nextSeed_(options_.seed) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::StyleColorsDark();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // fixed layout: nothing to remember between runs
    backend_.initImGui();
    ImGui_ImplOpenGL3_Init("#version 330 core");

    if (!options_.spectrum.empty()) {
        state_.realistic.enabled = true;
        state_.realistic.spectrum = options_.spectrum;
    }
    referenceTexture_ = std::make_unique<render::Texture>();
    userTexture_ = std::make_unique<render::Texture>();
    compareTexture_ = std::make_unique<render::Texture>();
    sceneRenderer_ = std::make_unique<render::SceneRenderer>();
    userDrrWorker_ = std::make_unique<NewestWins<UserDrrRequest, UserDrrResult>>(
        [](const UserDrrRequest& r) {
            UserDrrResult out{r, {}, {}};
            try {
                out.render = renderAppImage(*r.scene, r.key, r.threads);
            } catch (const std::exception& e) {
                out.error = e.what();
            }
            return out;
        },
        [this] { backend_.wake(); });  // a sleeping window shows it at once

    if (options_.userPose) state_.userPose = *options_.userPose;
    if (options_.view) state_.view = *options_.view;
    state_.showTimings = options_.showTimings;
    const MatchTolerancesView tolerances = matchTolerances();
    state_.toleranceOffsetMm = tolerances.offsetMm;
    state_.toleranceAngleDeg = tolerances.angleDeg;
    state_.volumePathField = options_.volumeSpec;
    state_.requests.loadVolume = options_.volumeSpec;
    state_.labels.pathField = options_.labelsSpec;
    state_.labels.tableField = options_.labelTable;
}

App::~App() {
    solver_.stop();
    userDrrWorker_.reset();
    sceneRenderer_.reset();
    referenceTexture_.reset();
    userTexture_.reset();
    compareTexture_.reset();
    ImGui_ImplOpenGL3_Shutdown();
    backend_.shutdownImGui();
    ImGui::DestroyContext();
}

void App::waitForLoad() {
    processRequests();  // a load requested but not yet started
    if (auto result = loader_.wait()) installLoadResult(std::move(*result));
    state_.load.loading = false;
    processRequests();  // the command line's labels, once their CT is there
    if (auto result = bonesLoader_.wait()) installLabelledBones(std::move(*result));
    pollLabels();
}

void App::installLoadResult(SceneLoader::Result result) {
    if (result.scene) {  // the solve searches the scene being replaced: end it first
        solver_.stop();
        pollSolver();
        state_.solve = SolveStatus{state_.solve.method};
        solveShownPose_.reset();
    }
    if (!result.scene) {
        // The current scene stays; the reader's message is shown as is.
        state_.load.error = result.error;
        return;
    }
    // The bone-only choice stays; its level starts at this scene's bone level.
    state_.drrThreshold.level = static_cast<float>(result.scene->isoValue);
    state_.drrThreshold.valuesInHu = looksLikeHounsfield(*result.scene->volume);
    showScene(std::move(result.scene));
    state_.load.error.clear();
    state_.load.loadedSpec = scene_->spec;
    state_.load.summary = scene_->summary;
    state_.translationRangeMm = scene_->translationRangeMm;
    state_.bone.minLevel = scene_->minValue;
    state_.bone.maxLevel = std::max(scene_->maxValue, scene_->minValue + 1.0f);
    state_.bone.level = static_cast<float>(scene_->isoValue);
    showBone(scene_->mesh, scene_->isoValue, scene_->meshFactor, scene_->fullMeshTriangles);
    installBones();
    state_.labels.loaded.clear();
    state_.labels.error.clear();
    // The command line's label map is for the first CT.
    if (firstScene_ && !options_.labelsSpec.empty())
        state_.requests.loadLabels = {options_.labelsSpec, options_.labelTable};
    state_.timings.meshMs = scene_->meshSeconds * 1000.0;
    for (int a = 0; a < 3; ++a)
        state_.userPose.offset[a] = std::clamp(
            state_.userPose.offset[a], -scene_->translationRangeMm, scene_->translationRangeMm);
    referenceCache_.clear();
    userCache_.clear();
    referenceKey_.reset();
    userKey_.reset();
    userRequested_.reset();
    // An MRI file opens in the slice mode, anything else as X-rays; the user may switch.
    state_.mode = scene_->looksLikeMri ? ImagingMode::Slice : ImagingMode::Xray;
    if (firstScene_ && options_.mode) state_.mode = *options_.mode;
    if (firstScene_ && options_.referencePose) {
        state_.referencePose = *options_.referencePose;
        state_.referenceSource = "given on the command line";
        state_.referenceRevealed = false;
        state_.attempts = 0;
        state_.match.reset();
        state_.bestUserPoseErrorMm.reset();
        state_.assisted = false;
    } else {
        newReference();
    }
    firstScene_ = false;
}

void App::showScene(std::shared_ptr<LoadedScene> plain) {
    plainScene_ = std::move(plain);
    const DrrThreshold& t = state_.drrThreshold;
    if (!t.enabled) {
        scene_ = plainScene_;  // its own images, cached ones included
        return;
    }
    const auto start = std::chrono::steady_clock::now();
    scene_ = withDrrThreshold(*plainScene_, t.level, options_.drrThreads);
    state_.drrThreshold.prepareMs = msSince(start);
}

void App::applyDrrThreshold() {
    if (!scene_) return;
    // Other images: a running solve compares with the old ones, so it ends (as on a reload).
    solver_.stop();
    pollSolver();
    state_.solve = SolveStatus{state_.solve.method};
    solveShownPose_.reset();
    showScene(plainScene_);
    referenceKey_.reset();
    userKey_.reset();
    userRequested_.reset();
    state_.matchIsStale = state_.match.has_value();
}

void App::showBone(std::shared_ptr<const Mesh> mesh, double level, int factor,
                   std::size_t fullTriangles) {
    bone_ = std::move(mesh);
    ++boneGeneration_;
    state_.bone.shownLevel = level;
    state_.bone.displayFactor = factor;
    state_.bone.fullTriangles = fullTriangles;
    state_.bone.triangles = 0;
    if (scene_ && scene_->bones)
        for (const auto& b : boneSurfaces_) state_.bone.triangles += b ? b->triangleCount() : 0;
    else
        state_.bone.triangles = bone_ ? bone_->triangleCount() : 0;
}

void App::remesh() {
    // Cached: the surface is rebuilt only for a level other than the one shown.
    if (!scene_ || double(state_.bone.level) == state_.bone.shownLevel) return;
    MarchingCubesOptions options;
    options.isoValue = state_.bone.level;
    options.threads = options_.drrThreads;
    const auto start = std::chrono::steady_clock::now();
    DisplaySurface surface;
    std::vector<std::shared_ptr<const Mesh>> boneSurfaces;
    try {
        // With bones, each bone's own surface (its volume alone); otherwise the CT's.
        if (scene_->bones)
            for (const SceneBone& b : scene_->bones->bones)
                boneSurfaces.push_back(
                    std::make_shared<const Mesh>(marchingCubes(*b.volume, options)));
        else
            surface = displaySurface(*scene_->volume, options);
    } catch (const Error& e) {  // e.g. more vertices than 32-bit indices hold: keep the old one
        state_.load.error = e.what();
        state_.bone.level = static_cast<float>(state_.bone.shownLevel);
        return;
    }
    state_.timings.meshMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    ++remeshes_;
    if (scene_->bones) boneSurfaces_ = std::move(boneSurfaces);
    showBone(std::move(surface.mesh), options.isoValue, surface.factor, surface.fullTriangles);
}

void App::newReference() {
    if (!scene_) return;
    const bool haveReference = referenceKey_.has_value();
    const Pose* avoid = haveReference ? &state_.referencePose : nullptr;
    const ReferenceChoice choice =
        state_.mode == ImagingMode::Slice
            ? chooseSliceReference(*scene_, nextSeed_++, state_.userPose, state_.difficulty, avoid)
            : chooseReference(*scene_, nextSeed_++, state_.userPose, state_.difficulty, avoid);
    state_.referencePose = choice.pose;
    state_.referenceSource = choice.source;
    state_.referenceRevealed = false;
    state_.attempts = 0;
    state_.bestUserPoseErrorMm.reset();
    state_.assisted = false;
    state_.match.reset();
    state_.matchIsStale = false;
    // A solution belongs to its reference.
    solver_.stop();
    pollSolver();
    state_.solve = SolveStatus{state_.solve.method};
    solveShownPose_.reset();
}

void App::startSolve(bool find) {
    if (!scene_) return;
    const int method = std::clamp(state_.solve.method, 0, kSolveMethodCount - 1);
    const BonesState& bones = state_.bones;
    if (state_.mode == ImagingMode::Xray && !bones.flex.active && bones.sliderTarget >= 0 &&
        bones.sliderTarget < int(bones.list.size())) {
        // The camera game's reference is another camera's view of the unmoved bones: no motion
        // of one bone explains it.
        solver_.stop();
        state_.solve = SolveStatus{method};
        state_.solve.error = "Solve finds a bone's motion against a bone game's reference: start " +
                             std::string(bones.isKnee ? "the flex game" : "the move game") +
                             " (Bones tab), or choose the camera.";
        return;
    }
    if (find && (state_.mode != ImagingMode::Xray || boneToSolve() >= 0)) {
        solver_.stop();
        state_.solve = SolveStatus{method};
        state_.solve.error = "Find searches the camera's pose from nothing: it needs the X-ray mode and the camera "
                             "as the target.";
        return;
    }
    if (state_.mode == ImagingMode::Slice) {
        SampledSlice reference =
            renderAppSlice(*scene_, state_.referencePose, 1, options_.drrThreads);
        solver_.startSlice(scene_, std::move(reference.image), std::move(reference.mask),
                           state_.userPose,
                           appSliceSolveSettings(parseSearchMethod(kSolveMethods[method]),
                                                 options_.drrThreads));
    } else if (const int bone = boneToSolve(); bone >= 0) {
        startBoneSolve(method, bone);
    } else {
        solveBone_ = -1;
        if (find)
            startFind(method);
        else
            startXraySolve(method);
    }
    state_.solve = SolveStatus{method};
    state_.solve.running = true;
    state_.solve.find = find;
    state_.solve.bone = solveBone_;
    solveJudged_ = false;
    solveShownPose_ = state_.userPose;
    solveShownFrame_ = state_.frame;
    pollSolver();
}

Image App::xrayReference() {
    return referenceCache_.get(*scene_, state_.referencePose, 1, options_.drrThreads, ImagingMode::Xray, {},
                               referenceSpectrum())
        .image;
}

void App::startXraySolve(int method) {
    solver_.start(scene_, xrayReference(), state_.userPose,
                  appSolveSettings(parseSearchMethod(kSolveMethods[method]), options_.drrThreads));
}

void App::startFind(int method) {
    // The registration `register` runs on a CT (block means at coarse levels, no level finer than
    // the voxels), over the default search space (the hard reference draws).
    RegistrationSettings settings = appSolveSettings(parseSearchMethod(kSolveMethods[method]), options_.drrThreads);
    useWholeCtSpeedups(settings);
    ViewFindSettings find;
    find.threads = options_.drrThreads;
    solver_.startFind(scene_, xrayReference(), settings, find);
}

void App::pollSolver() {
    const SolveSnapshot s = solver_.snapshot();
    if (s.version == solveVersion_ && (!s.finished || solveJudged_)) return;
    solveVersion_ = s.version;
    SolveStatus& out = state_.solve;
    out.running = s.running;
    out.finished = s.finished;
    out.stopped = s.stopped;
    out.error = s.error;
    out.stage = s.stage;
    out.level = s.level;
    out.levelCount = s.levelCount;
    out.evaluations = s.evaluations;
    out.budget = s.budget;
    out.costHistory = s.costHistory;
    out.bestPose = s.bestPose;
    out.candidate = s.candidate;
    out.elapsedMs = s.elapsedMs;
    // The user pane follows a Solve's best pose; a Find has none to show until it ends.
    if (s.running && solveBone_ < 0 && !out.find &&
        state_.frame >= solveShownFrame_ + kSolveDisplayEveryFrames) {
        solveShownPose_ = s.bestPose;
        solveShownFrame_ = state_.frame;
    }
    if (!s.running) solveShownPose_.reset();
    if (s.finished && !solveJudged_ && scene_ && solveBone_ >= 0) {
        judgeBoneSolve();
    } else if (s.finished && !solveJudged_ && scene_) {
        // Judged like a user's attempt: per-parameter error and mTRE against the reference.
        out.error6 = poseDifference(state_.referencePose, s.bestPose);
        out.poseErrorMm = state_.mode == ImagingMode::Slice
                              ? sliceMtre(*scene_, state_.referencePose, s.bestPose)
                              : sceneMtre(*scene_, state_.referencePose, s.bestPose);
        const MatchVerdict verdict = judgeMatch(state_.referencePose, s.bestPose, out.poseErrorMm);
        out.matched = verdict.match;
        out.closeness = verdict.closeness;
        solveJudged_ = true;
    }
}

const Pose& App::shownUserPose() const {
    return solveShownPose_ ? *solveShownPose_ : state_.userPose;
}

void App::processRequests() {
    Requests requests = std::move(state_.requests);
    state_.requests = {};
    if (requests.resetView) {
        // The whole set-up framed; what is shown (bone, box, apparatus) stays as chosen.
        View3d framed = View3d::framed();
        framed.showBone = state_.view.showBone;
        framed.showBox = state_.view.showBox;
        framed.showApparatus = state_.view.showApparatus;
        state_.view = framed;
    }
    if (requests.reveal) state_.referenceRevealed = true;
    if (requests.loadVolume) {
        solver_.stop();  // a new scene ends the search of the old one
        state_.load.error.clear();
        loader_.start(*requests.loadVolume);
    }
    if (requests.mode && *requests.mode != state_.mode && scene_) {
        // Another kind of image: the reference, the attempts and the solve start over.
        state_.mode = *requests.mode;
        referenceKey_.reset();
        userKey_.reset();
        userRequested_.reset();
        newReference();
    }
    if (requests.newReference) newReference();
    if (requests.remesh) remesh();
    if (requests.boneThreshold) applyDrrThreshold();
    if (requests.stopSolve) {
        solver_.stop();
        pollSolver();
    }
    if (requests.solve || requests.find) startSolve(requests.find);
    if (requests.applySolution && state_.solve.finished && state_.solve.bone >= 0 &&
        state_.solve.bone < int(state_.bones.list.size())) {
        const auto specs = boneMotionSpecs();
        auto& motion = state_.bones.list[state_.solve.bone].motion;
        for (int k = 0; k < kParameterCount; ++k)
            motion[k] = std::clamp(state_.solve.boneMotion[k], specs[k].min, specs[k].max);
        state_.solve.applied = true;
    } else if (requests.applySolution && state_.solve.finished) {
        // The only way a solve changes the user's pose: the user asked for it.
        Pose p = state_.solve.bestPose;
        const auto specs = parameterSpecs(state_.translationRangeMm);
        std::array<double, 6> v = p.toArray();
        for (int k = 0; k < kParameterCount; ++k)
            v[k] = std::clamp(v[k], specs[k].min, specs[k].max);
        state_.userPose = Pose::fromArray(v);
        state_.solve.applied = true;
        state_.assisted = true;  // until the next reference
        state_.matchIsStale = true;
    }
    if (requests.match && scene_ && state_.mode == ImagingMode::Slice) {
        ++state_.attempts;
        MatchOutcome outcome = evaluateSliceMatch(
            *scene_, state_.userPose, state_.referencePose,
            renderAppSlice(*scene_, state_.userPose, 1, options_.drrThreads),
            renderAppSlice(*scene_, state_.referencePose, 1, options_.drrThreads));
        recordAttempt(std::move(outcome));
    } else if (requests.match && scene_) {
        // Judge the exact images, whatever the preview showed.
        const Image user = userCache_
                               .get(*scene_, state_.userPose, 1,
                                    options_.drrThreads, ImagingMode::Xray, userObjects())
                               .image;
        const Image reference = referenceCache_
                                    .get(*scene_, state_.referencePose, 1,
                                         options_.drrThreads, ImagingMode::Xray,
                                         shownReferenceObjects(), referenceSpectrum())
                                    .image;
        ++state_.attempts;
        MatchOutcome outcome =
            evaluateMatch(*scene_, state_.userPose, state_.referencePose, user, reference);
        recordAttempt(std::move(outcome));
    }
    if (requests.endFlex) state_.bones.flex = FlexGame{};
    if (requests.newFlex) newFlex();
    if (requests.checkFlex) checkFlex();
    if (requests.growAtPixel) growAt(*requests.growAtPixel);
    if (requests.loadLabels) startLabels((*requests.loadLabels)[0], (*requests.loadLabels)[1]);
    if (requests.components) startComponents();
    refreshMatchTexts();
}

void App::recordAttempt(MatchOutcome outcome) {
    outcome.attempt = state_.attempts;
    outcome.assisted = state_.assisted;
    if (!outcome.assisted &&
        (!state_.bestUserPoseErrorMm || outcome.poseErrorMm < *state_.bestUserPoseErrorMm))
        state_.bestUserPoseErrorMm = outcome.poseErrorMm;
    state_.match = std::move(outcome);
    state_.matchIsStale = false;
}

void App::refreshMatchTexts() {
    // The numbers (signed errors, mTRE) only once they no longer give the answer away.
    if (state_.match)
        wordOutcome(*state_.match, state_.hintWording,
                    state_.match->matched || state_.referenceRevealed);
    const FlexGame& flex = state_.bones.flex;
    if (flex.outcome)
        wordOutcome(*state_.bones.flex.outcome, state_.hintWording,
                    flex.outcome->matched || flex.revealed);
}

ImageEdgeLetters App::edgeLetters(const Pose& pose) const {
    // A slice's columns and rows run along its own axes; a DRR's along the film's.
    if (state_.mode == ImagingMode::Slice) {
        const SliceGeometry slice = appSlice(*scene_, pose);
        return imageEdgeLetters(slice.u, slice.v);
    }
    const ProjectionGeometry drr = appGeometry(*scene_, pose);
    return imageEdgeLetters(drr.detector.u, drr.detector.v);
}

void App::updateImages() {
    if (!scene_) return;
    const int threads = options_.drrThreads;
    const ImagingMode mode = state_.mode;
    const Pose& referencePose = referenceCamera();
    state_.realistic.available = realisticReferenceAvailable();
    const ObjectStates referenceObjectStates = shownReferenceObjects();
    const std::string spectrum = referenceSpectrum();
    const DrrKey referenceKey{scene_->generation, referencePose.toArray(), 1,
                              mode, referenceObjectStates, spectrum};
    if (referenceKey_ != referenceKey) {
        DrrRender r = referenceCache_.get(*scene_, referencePose, 1, threads,
                                          mode, referenceObjectStates, spectrum);
        referenceDrr_ = std::move(r.image);
        referenceDataMask_ = std::move(r.dataMask);
        state_.timings.referenceDrrMs = r.milliseconds;
        referenceKey_ = referenceKey;
        ++referenceVersion_;
        state_.referenceEdges = edgeLetters(referencePose);
    }

    // While a slider is dragged: a coarser film, traced exactly; the full film again on release.
    const bool coarse = state_.interacting && state_.coarseWhileDragging;
    const int factor = coarse ? state_.timings.coarseFactor : 1;
    updateUserDrr(DrrKey{scene_->generation, shownUserPose().toArray(), factor, mode,
                         userObjects()});

    if (state_.display.autoWindow) {
        // The reference's range, scanned once per reference image, not once per frame.
        if (autoWindowOf_ != referenceVersion_) {
            autoWindow_ = render::fullRange(referenceDrr_);
            autoWindowOf_ = referenceVersion_;
        }
        state_.display.window = autoWindow_.window;
        state_.display.level = autoWindow_.level;
    }
    const DisplayKey key{referenceVersion_, userVersion_, state_.display.window,
                         state_.display.level, state_.display.compare};
    if (key == shownKey_) return;
    const render::WindowLevel wl{state_.display.window, state_.display.level};
    if (key.reference != shownKey_.reference || key.window != shownKey_.window ||
        key.level != shownKey_.level)
        referenceTexture_->upload(referenceDrr_.width, referenceDrr_.height,
                                  render::windowedRgba(referenceDrr_, wl));
    userTexture_->upload(userDrr_.width, userDrr_.height, render::windowedRgba(userDrr_, wl));
    // The comparison needs equal sizes: during a coarse drag, compare with a coarse reference.
    const Image& reference =
        userDrr_.width == referenceDrr_.width
            ? referenceDrr_
            : referenceCache_
                  .get(*scene_, referencePose, userKey_ ? userKey_->downsample : 1, threads,
                       mode, referenceObjectStates)
                  .image;
    std::vector<std::uint8_t> rgba;
    switch (state_.display.compare) {
        case CompareMode::Difference:
            rgba = render::differenceRgba(reference, userDrr_, wl);
            break;
        case CompareMode::Overlay:
            rgba = render::overlayRgba(reference, userDrr_, wl);
            break;
        case CompareMode::Checkerboard:
            rgba =
                render::checkerboardRgba(reference, userDrr_, wl, std::max(8, userDrr_.width / 8));
            break;
    }
    if (!rgba.empty()) compareTexture_->upload(userDrr_.width, userDrr_.height, rgba);
    shownKey_ = key;
}

void App::updateUserDrr(const DrrKey& key) {
    if (key != userRequested_) {
        userRequested_ = key;
        const std::uint64_t number = ++userRequests_;
        if (std::optional<DrrRender> hit = userCache_.find(key)) {
            userShownNumber_ = number;
            showUserDrr(key, std::move(*hit), frameInputTime_);
        } else {
            userDrrWorker_->request({scene_, key, options_.drrThreads, number, frameInputTime_});
        }
    }
    std::optional<UserDrrResult> done =
        options_.userDrrOffThread ? userDrrWorker_->take() : userDrrWorker_->wait();
    // Older than what is shown, or of another scene or kind of image: dropped.
    if (!done || done->request.number <= userShownNumber_ ||
        done->request.key.sceneGeneration != key.sceneGeneration || done->request.key.mode != key.mode)
        return;
    if (!done->error.empty()) {
        state_.load.error = done->error;
        return;
    }
    userShownNumber_ = done->request.number;
    userCache_.insert(done->request.key, done->render);
    if (done->request.key.downsample > 1) ++coarseUserRenders_; else ++exactUserRenders_;
    showUserDrr(done->request.key, std::move(done->render), done->request.inputTime);
}

void App::showUserDrr(const DrrKey& key, DrrRender render,
                      std::chrono::steady_clock::time_point inputTime) {
    const bool coarse = key.downsample > 1;
    userDrr_ = std::move(render.image);
    userDataMask_ = std::move(render.dataMask);
    state_.timings.userDrrMs = render.milliseconds;
    state_.timings.userDrrCoarse = coarse;
    (coarse ? state_.timings.lastCoarseMs : state_.timings.lastExactMs) = render.milliseconds;
    userKey_ = key;
    ++userVersion_;
    const Pose pose = Pose::fromArray(key.pose);
    state_.userEdges = edgeLetters(pose);
    state_.userSliceEmpty = key.mode == ImagingMode::Slice && !sliceCutsVolume(*scene_, pose);
    userShownInputTime_ = inputTime;
}

std::optional<OpenRequest> App::takeOpenRequest() {
    std::optional<OpenRequest> r = std::move(state_.openRequest);
    state_.openRequest.reset();
    // A CT is the game's own: loaded here, as the CT field does.
    if (r && r->kind == OpenRequest::Kind::Volume) {
        state_.volumePathField = r->volume;
        state_.requests.loadVolume = r->volume;
        state_.open.shown = false;
        return std::nullopt;
    }
    return r;
}

void App::openFailed(const std::string& why) {
    state_.open.shown = true;  // the fields as typed, to mend
    state_.open.error = why;
}

void App::frame() {
    const auto start = std::chrono::steady_clock::now();
    backend_.newFrame();
    frameInputTime_ = std::chrono::steady_clock::now();
    userShownInputTime_.reset();
    for (auto& path : backend_.takeDroppedPaths()) {
        // A dropped trial opens the workspace (the shell does); anything else is a CT.
        const std::string ext = std::filesystem::path(path).extension().string();
        if (ext == ".json" || ext == ".cfg") {
            OpenRequest r;
            r.kind = OpenRequest::Kind::Trial;
            r.trial = path;
            state_.openRequest = r;
            continue;
        }
        state_.volumePathField = path;
        state_.requests.loadVolume = path;
    }
    if (auto result = loader_.poll()) installLoadResult(std::move(*result));
    pollLabels();
    const SceneLoader::Progress progress = loader_.progress();
    state_.load.loading = progress.busy;
    state_.load.requestedSpec = progress.spec;
    state_.load.stage = progress.stage;
    state_.load.progress = progress.fraction;
    state_.load.elapsedSeconds = progress.elapsedSeconds;
    pollSolver();

    ImGui_ImplOpenGL3_NewFrame();
    ImGui::NewFrame();
    state_.interacting = false;
    UiTextures textures;
    textures.reference = referenceTexture_->empty() ? 0 : referenceTexture_->id();
    textures.user = userTexture_->empty() ? 0 : userTexture_->id();
    textures.compare = compareTexture_->empty() ? 0 : compareTexture_->id();
    textures.scene3d = sceneRenderer_->texture();
    textures.referenceImage = referenceDrr_.width > 0 ? &referenceDrr_ : nullptr;
    textures.userImage = userDrr_.width > 0 ? &userDrr_ : nullptr;
    textures.referenceDataMask = referenceDataMask_.width > 0 ? &referenceDataMask_ : nullptr;
    textures.userDataMask = userDataMask_.width > 0 ? &userDataMask_ : nullptr;
    refreshMatchTexts();  // the hint mode or Reveal may have changed since
    ui_.draw(state_, textures);

    processRequests();
    updateBones();
    updateImages();

    // The 3D view is redrawn only when something it shows changed; while the user drags a
    // slider or orbits it skips multisampling (4x MSAA costs ~4x on llvmpipe). After a release
    // it stays so until the exact DRR comes from its worker: the multisampled view is drawn
    // once, with the exact film, not first with the preview's.
    const bool interacting = state_.interacting || ImGui::IsMouseDown(ImGuiMouseButton_Left);
    const bool fast =
        interacting || (state_.timings.userDrrCoarse && userDrrWorker_->busy());
    const SceneKey sceneKey{scene_ ? scene_->generation : 0,
                            boneGeneration_,
                            state_.userPose.toArray(),
                            state_.view.azimuthDeg,
                            state_.view.elevationDeg,
                            state_.view.zoom,
                            state_.view.panX,
                            state_.view.panY,
                            state_.view.showBone,
                            state_.view.showBox,
                            state_.view.showApparatus,
                            ui_.sceneViewSize(),
                            shownKey_.user,
                            shownKey_.window,
                            shownKey_.level,
                            fast,
                            state_.mode,
                            userObjects()};
    if (sceneKey != sceneKey_) {
        sceneRenderer_->draw(scene_.get(), surfaces(), state_.userPose, state_.view,
                             userTexture_->empty() ? 0 : userTexture_->id(), ui_.sceneViewSize(),
                             !fast, state_.mode == ImagingMode::Slice);
        sceneKey_ = sceneKey;
        ++sceneDraws_;
    }
    std::vector<std::pair<glm::vec2, std::string>> labels;
    std::vector<glm::vec4> colors;
    for (const auto& l : sceneRenderer_->labels()) {
        labels.emplace_back(l.pixel, l.text);
        colors.push_back(l.color);
    }
    ui_.drawSceneLabels(labels, colors);
    presenter_.present(backend_);
    if (userShownInputTime_) {  // input latency: from reading the input to its DRR on screen
        state_.timings.userDrrLatencyMs = msSince(*userShownInputTime_);
        ++state_.timings.userDrrsShown;
    }
    // Nothing moving: the window sleeps until the next event instead of redrawing.
    const bool working = state_.load.loading || state_.labels.loading || state_.solve.running ||
                         userDrrWorker_->busy();
    backend_.setActivity(interacting ? Activity::Busy
                         : working                  ? Activity::Background
                                                    : Activity::Idle);
    ++state_.frame;
    state_.timings.frameMs = msSince(start);
}

render::RgbaImage App::capture() const { return captureFrame(backend_); }

}  // namespace fm::app

#include "workspace/WorkspaceApp.h"

#include <imgui.h>
#include <imgui_impl_opengl3.h>

#include <chrono>
#include <cstdio>
#include <thread>

#include "core/Error.h"
#include "mesh/MarchingCubes.h"
#include "scene/LoadedScene.h"
#include "platform/Gl.h"
#include "render/SceneRenderer.h"
#include "render/Texture.h"
#include "ui/PresentFrame.h"
#include "scene/ObjectPoseParameterization.h"
#include "track/PoseOverlay.h"
#include "workspace/RawImageHint.h"
#include "workspace/ShownPose.h"
#include "xray/AnswerCheck.h"
#include "workspace/WorkspacePose.h"
#include "xray/CameraPoseDifference.h"
#include "xray/ObjectRegistration.h"

namespace fm::app {

WorkspaceApp::WorkspaceApp(RenderBackend& backend, std::shared_ptr<WorkspaceModel> model, WorkspaceOptions options)
    : backend_(backend), model_(std::move(model)), options_(options) {
    if (!model_) throw Error("the workspace needs a scene");
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::StyleColorsDark();
    ImGui::GetIO().IniFilename = nullptr;  // fixed layout: nothing to remember between runs
    backend_.initImGui();
    ImGui_ImplOpenGL3_Init("#version 330 core");
    sceneRenderer_ = std::make_unique<render::SceneRenderer>();

    const TrialScene& t = model_->trial();
    state_.title = model_->title();
    state_.source = t.trial.source.string();
    state_.showTimings = options_.showTimings;
    for (const TrialCamera& c : t.trial.cameras) state_.cameraNames.push_back(c.name);
    for (int k = 0; k < model_->objectCount(); ++k) {
        const SceneObject& o = model_->scene().objects[static_cast<std::size_t>(k)];
        WorkspaceObject w;
        w.name = o.name;
        w.kind = o.model->describe();
        w.color = objectColour(static_cast<std::size_t>(k));
        w.hasMasks = t.masks.count(o.name) > 0;
        state_.objects.push_back(w);
    }
    state_.frameCount = model_->frameCount();
    for (const ImageSequence& seq : t.sequences) {
        state_.frameNames.emplace_back();
        for (int f = 0; f < state_.frameCount; ++f) state_.frameNames.back().push_back(seq.frameName(f));
    }
    state_.poses = model_->initialPoses();
    for (int k = 0; k < model_->objectCount(); ++k)
        state_.placements.push_back(defaultPlacement(model_->scene(), static_cast<std::size_t>(k)));
    state_.poseFrame = model_->cameraCount() > 1 ? PoseFrame::World : PoseFrame::Camera;
    state_.display.assign(static_cast<std::size_t>(model_->cameraCount()), DisplaySettings{});
    state_.savePath = model_->defaultSavePath().string();
    state_.warnings = t.trial.warnings;
    for (int c = 0; c < model_->cameraCount(); ++c) {
        radiographTextures_.push_back(std::make_unique<render::Texture>());
        modelTextures_.push_back(std::make_unique<render::Texture>());
    }
    state_.tracking = model_->fromTrial();
    syncCameraValues();
    if (state_.tracking) tracking_.init(*model_, state_);
    syncControls();
    buildSurfaces();
}

WorkspaceApp::~WorkspaceApp() {
    solver_.stop();
    tracking_.stop();
    sceneRenderer_.reset();
    radiographTextures_.clear();
    modelTextures_.clear();
    ImGui_ImplOpenGL3_Shutdown();
    backend_.shutdownImGui();
    ImGui::DestroyContext();
}

std::optional<RigidTransform> WorkspaceApp::pose(int object) const { return shownPose(state_, state_.frame, object); }

void WorkspaceApp::goToFrame(int frame) {
    if (frame == state_.frame || frame < 0 || frame >= state_.frameCount) return;
    try {
        model_->prepared(frame);  // a frame that cannot be read leaves the workspace where it is
    } catch (const Error& e) {
        state_.error = e.what();
        return;
    }
    // Objects without a pose there are shown where the nearest set pose puts them (ShownPose.h);
    // nothing is copied into the frame, so it stays untracked until set.
    state_.frame = frame;
    state_.error.clear();
}

bool WorkspaceApp::applyControls() {
    PoseControls& c = state_.controls;
    if (c.object < 0 || c.values == c.shown) return false;
    if (c.frameIndex != state_.frame || c.object != state_.selected) return false;  // rebased below
    state_.undo.recordEdit(model_->objectName(c.object), state_.frame, c.object, snapshot());
    state_.poses[static_cast<std::size_t>(state_.frame)][static_cast<std::size_t>(c.object)] =
        poseFromControls(c, model_->scene());
    c.shown = c.values;
    return true;
}

void WorkspaceApp::undo() {
    if (state_.solve.running || state_.track.run.running) {
        state_.undoMessage = "Undo waits: stop the running Solve or Track first";
        return;
    }
    std::optional<PoseHistory::Step> step = state_.undo.takeLast();
    if (!step) {
        state_.undoMessage = "Nothing to undo";
        return;
    }
    state_.poses = std::move(step->before.poses);
    state_.track.keyframes = std::move(step->before.keyframes);
    state_.controls.object = -1;  // rebased on the restored pose
    state_.undoMessage = "Undone: " + step->what;
}

void WorkspaceApp::syncControls() {
    const PoseControls& c = state_.controls;
    const int object = state_.selected;
    if (object < 0 || object >= model_->objectCount()) return;
    const std::optional<RigidTransform> pose = shownPose(state_, state_.frame, object);
    if (!pose) return;
    const bool same = c.object == object && c.frameIndex == state_.frame && c.frame == state_.poseFrame &&
                      c.camera == state_.poseCamera;
    if (same) return;
    const int keep = c.selected;
    rebaseControls(state_.controls, model_->scene(), object, state_.frame, state_.poseFrame, state_.poseCamera,
                   *pose);
    state_.controls.selected = keep;
}

void WorkspaceApp::processRequests() {
    WorkspaceRequests r = state_.requests;
    state_.requests = {};
    if (r.frame) goToFrame(*r.frame);
    if (r.resetView) state_.view = defaultRigView();
    if (r.stopSolve) solver_.stop();
    if (r.solve || r.find) {
        // Find needs no pose: "moved" is then measured from the one shown, if any.
        const auto start = pose(state_.selected);
        if (start || r.find)
            solver_.start(model_, state_.selected, state_.frame, start.value_or(RigidTransform{}), r.find);
        solveVersion_ = 0;
    }
    if (r.candidate) showCandidate(*r.candidate);
    if (r.save) save();
    if (r.undo) undo();
    if (r.preparation) {
        if (state_.solve.running || state_.track.run.running) {  // the workers read the prepared frames
            syncCameraValues();
            state_.error = "invert / log wait until the Solve or Track ends";
        } else {
            try {
                for (int c = 0; c < model_->cameraCount(); ++c) {
                    const auto& v = state_.cameraValues.at(static_cast<std::size_t>(c));
                    model_->setInvertAndLog(c, v.invert && !v.logTransform, v.logTransform);
                }
            } catch (const Error& e) {
                state_.error = e.what();
            }
            syncCameraValues();
            ++state_.preparationVersion;
            autoWindowFrame_ = -1;  // a new value range
        }
    }
}

void WorkspaceApp::showCandidate(int k) {
    WorkspaceSolve& w = state_.solve;
    if (w.running || k < 0 || k >= static_cast<int>(w.candidates.size()) || k == w.candidate) return;
    state_.undo.record("candidate " + std::to_string(k + 1) + " of Find", snapshot());
    state_.poses.at(static_cast<std::size_t>(w.frame)).at(static_cast<std::size_t>(w.object)) =
        w.candidates[static_cast<std::size_t>(k)];
    state_.controls.object = -1;  // rebased on it
    w.candidate = k;
}

void WorkspaceApp::pollSolver() {
    const WorkspaceSolveSnapshot s = solver_.snapshot();
    if (s.version == 0) return;
    WorkspaceSolve& w = state_.solve;
    w.running = s.running;
    w.stage = s.stage;
    w.evaluations = s.evaluations;
    w.budget = s.budget;
    w.seconds = s.seconds;
    w.object = s.object;
    w.frame = s.frame;
    if (!s.finished || s.version == solveVersion_) return;
    solveVersion_ = s.version;
    w.finished = true;
    w.stopped = s.stopped;
    w.error = s.error;
    w.start = s.start;
    w.result = s.result;
    w.similarity = s.similarity;
    w.viewCosts = s.viewCosts;
    w.find = s.find;
    w.candidates = s.candidates;
    w.candidateSimilarity = s.candidateSimilarity;
    w.candidate = 0;
    w.iou.reset();
    w.startIou.reset();
    if (!s.result) return;
    // The answer goes onto the sliders: it is the object's pose in that frame now (Undo returns
    // to the pose before).
    state_.undo.record(std::string(s.find ? "Find" : "Solve") + " of " + model_->objectName(s.object) + " in frame " +
                           std::to_string(s.frame),
                       snapshot());
    state_.poses.at(static_cast<std::size_t>(s.frame)).at(static_cast<std::size_t>(s.object)) = *s.result;
    state_.controls.object = -1;  // rebased on it
    const SceneObject& o = model_->scene().objects.at(static_cast<std::size_t>(s.object));
    const CameraPoseDifference d =
        cameraPoseDifference(model_->scene().cameras[0], s.start, *s.result, defaultPivot(*o.model));
    w.inPlaneMm = d.inPlaneMm;
    w.depthMm = d.depthMm;
    w.rotationDeg = d.rotationDeg;
    if (const Mask* m = model_->mask(s.object, s.frame)) {
        const auto silhouetteAt = [&](const RigidTransform& p) {
            return footprintMask(model_->objectImage(s.object, 0, p, true), 0.0f);
        };
        w.iou = silhouetteIoU(silhouetteAt(*s.result), *m);
        w.startIou = silhouetteIoU(silhouetteAt(s.start), *m);
    }
    AnswerEvidence evidence = s.evidence;
    evidence.iou = w.iou;
    const AnswerCheck check = checkAnswer(o, *s.result, model_->prepared(s.frame), model_->scene().cameras,
                                          evidence, model_->threads());
    w.check = check.verdict;
    w.checkText = check.text;
    w.uncertaintyText = evidence.uncertainty ? describeUncertainty(*evidence.uncertainty) : std::string();
    char line[256];
    std::snprintf(line, sizeof line, "%s %s in frame %d: similarity %.5f (%s)",
                  s.stopped ? "Stopped:" : s.find ? "Found:" : "Solved:",
                  o.name.c_str(), s.frame, s.similarity, s.note.c_str());
    w.summary = line;
    std::printf("solve       %s\n", line);
    std::printf("verdict     %s\n", w.checkText.c_str());
    if (!w.uncertaintyText.empty()) std::printf("uncertainty %s (camera 1's frame)\n", w.uncertaintyText.c_str());
    std::printf("            moved in-plane %.3f mm, depth %.3f mm, rotation %.3f deg (camera 1)\n", d.inPlaneMm,
                d.depthMm, d.rotationDeg);
    if (w.iou) std::printf("            IoU %.4f against the mask (start %.4f)\n", *w.iou, *w.startIou);
}

void WorkspaceApp::waitForSolve() {
    while (solver_.running()) {
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    frame();
}

void WorkspaceApp::waitForTrack() {
    while (tracking_.running()) {
        frame();
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    frame();  // the last frame's pose into the poses
    frame();  // ... and the panes on it
}

void WorkspaceApp::save() {
    try {
        const auto files = model_->save(state_.savePath, state_.poses);
        std::string text = "Saved";
        for (const auto& f : files) {  // appended piecewise: " " + string trips GCC 12's -Wrestrict
            text += ' ';
            text += f.string();
        }
        state_.saveMessage = files.empty() ? "Nothing to save: no object has a pose" : text;
        state_.saveFailed = false;
    } catch (const std::exception& e) {
        state_.saveMessage = std::string("Not saved (nothing was written): ") + e.what();
        state_.saveFailed = true;
    }
}

void WorkspaceApp::syncCameraValues() {
    state_.cameraValues.assign(static_cast<std::size_t>(model_->cameraCount()), {});
    for (int c = 0; c < model_->cameraCount(); ++c) {
        const FramePreparation::Values v = model_->preparation(c).spec.values;
        state_.cameraValues[static_cast<std::size_t>(c)] = {v == FramePreparation::Values::Invert,
                                                            v == FramePreparation::Values::Log};
    }
}

void WorkspaceApp::updateRawHint() {
    state_.rawHint.clear();
    if (model_->fromTrial()) return;  // one radiograph opened with register's flags
    const auto& views = model_->prepared(state_.frame);
    // The value range of each prepared frame: once per frame and preparation.
    const std::pair<int, std::uint64_t> key{state_.frame, state_.preparationVersion};
    if (rawRangesKey_ != key) {
        rawRanges_.clear();
        for (const RegistrationView& v : views) {
            const auto [low, high] = validPercentileRange(v.reference, v.valid);
            rawRanges_.push_back(double(high) - double(low));
        }
        rawRangesKey_ = key;
    }
    for (std::size_t c = 0; c < views.size(); ++c) {
        Mask footprint;
        for (int k = 0; k < model_->objectCount(); ++k) {
            const Mask& s = images_.silhouette(static_cast<int>(c), k);
            if (!state_.objects.at(static_cast<std::size_t>(k)).visible || s.inside.empty()) continue;
            if (footprint.inside.empty()) footprint = Mask(s.width, s.height, false);
            if (s.inside.size() != footprint.inside.size()) continue;
            for (std::size_t i = 0; i < s.inside.size(); ++i) footprint.inside[i] |= s.inside[i];
        }
        if (footprint.inside.empty()) continue;
        const RegistrationView& v = views[c];
        const double contrast = footprintContrast(v.reference, v.valid ? *v.valid : Mask(), footprint, rawRanges_[c]);
        if (contrast < kRawLookingContrast) {
            char text[320];
            std::snprintf(text, sizeof text,
                          "The models lie on darker pixels than around them (contrast %.2f): dense matter "
                          "is dark in a raw radiograph, bright in the DRRs the cost compares with. %s",
                          contrast, state_.cameraValues.at(c).invert ? "Is this image already inverted? Try invert off."
                                                  : "Try invert (or --invert).");
            state_.rawHint = text;
            return;
        }
    }
}

void WorkspaceApp::updateImages() {
    if (autoWindowFrame_ != state_.frame || std::any_of(state_.display.begin(), state_.display.end(),
                                                        [](const DisplaySettings& d) { return d.autoWindow; })) {
        const auto& views = model_->prepared(state_.frame);
        for (std::size_t c = 0; c < views.size(); ++c) {
            DisplaySettings& d = state_.display[c];
            if (!d.autoWindow) continue;
            const render::WindowLevel wl = autoWindowLevel(views[c]);
            d.window = wl.window;
            d.level = wl.level;
        }
        autoWindowFrame_ = state_.frame;
    }
    const auto start = std::chrono::steady_clock::now();
    if (images_.update(*model_, state_)) {
        for (std::size_t c = 0; c < images_.panes().size(); ++c) {
            const PaneImages& p = images_.panes()[c];
            radiographTextures_[c]->upload(p.width, p.height, p.radiograph);
            if (!p.model.empty()) modelTextures_[c]->upload(p.width, p.height, p.model);
        }
        ++imagesVersion_;
        state_.imageMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        rawHintStale_ = true;
        state_.iou.reset();
        const int k = state_.selected;
        if (const Mask* m = model_->mask(k, state_.frame); m && pose(k)) {
            const Mask& s = images_.silhouette(0, k);
            if (s.width == m->width && s.height == m->height) state_.iou = silhouetteIoU(s, *m);
        }
    }
    // The raw-image hint: a pass over every camera's frame, so not while a control is dragged
    // (9 ms a 1024^2 frame with its percentiles, measured); after the release.
    if (rawHintStale_ && !state_.interacting && !ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
        updateRawHint();
        rawHintStale_ = false;
    }
}

void WorkspaceApp::buildSurfaces() {
    // Meshes as they are; volume bones by their marching-cubes surface at the bone level.
    const TrialScene& t = model_->trial();
    for (int k = 0; k < model_->objectCount(); ++k) {
        const std::string& name = model_->objectName(k);
        std::shared_ptr<const Mesh> mesh;
        if (const auto m = t.meshes.find(name); m != t.meshes.end()) {
            mesh = m->second;
        } else if (const auto v = t.volumes.find(name); v != t.volumes.end()) {
            MarchingCubesOptions options;
            options.isoValue = boneIsoValue(*v->second);
            try {
                mesh = std::make_shared<const Mesh>(marchingCubes(*v->second, options));
            } catch (const Error& e) {
                state_.warnings.push_back(name + ": no surface for the 3D view: " + e.what());
            }
        }
        surfaces_.push_back(mesh);
    }
}

void WorkspaceApp::drawScene() {
    std::vector<render::SurfaceItem> surfaces;
    glm::dvec3 centre(0.0);
    int placed = 0;
    for (int k = 0; k < model_->objectCount(); ++k) {
        const auto p = pose(k);
        if (!p || !state_.objects[k].visible) continue;
        glm::dmat4 m(p->rotation);
        m[3] = glm::dvec4(p->translation, 1.0);
        const auto c = state_.objects[k].color;
        surfaces.push_back({surfaces_[k].get(), std::uint64_t(k + 1), m, glm::vec3(c[0], c[1], c[2])});
        centre += p->applyToPoint(defaultPivot(*model_->scene().objects[k].model));
        ++placed;
    }
    if (placed > 0)
        centre /= double(placed);
    else
        centre = defaultPlacement(model_->scene(), 0).applyToPoint(defaultPivot(*model_->scene().objects[0].model));
    std::vector<render::RigCamera> cameras;
    for (int c = 0; c < model_->cameraCount(); ++c) {
        const ProjectionGeometry& g = model_->scene().cameras[c];
        const DetectorGeometry& d = g.detector;
        const double w = d.size.x - 0.5, h = d.size.y - 0.5;
        // A MayaCam film is a virtual plane metres away (focal length in pixels at 1 mm each):
        // drawn along its cone at 1.25 times the objects' distance, the same rays, when nearer.
        const double scale = std::min(1.0, 1.25 * glm::length(centre - g.source) / glm::length(d.center() - g.source));
        auto onFilm = [&](double col, double row) { return g.source + scale * (d.pixelCenter(col, row) - g.source); };
        cameras.push_back({g.source,
                           {onFilm(-0.5, -0.5), onFilm(w, -0.5), onFilm(w, h), onFilm(-0.5, h)},
                           radiographTextures_[c]->empty() ? 0 : radiographTextures_[c]->id(),
                           state_.cameraNames[c]});
    }
    const bool fast = state_.interacting || ImGui::IsMouseDown(ImGuiMouseButton_Left);
    SceneKey key{state_.frame, shownPoses(state_, state_.frame), {}, state_.view.azimuthDeg, state_.view.elevationDeg,
                 state_.view.zoom, state_.view.panX, state_.view.panY, state_.view.showBone,
                 state_.view.showApparatus, ui_.sceneViewSize(), imagesVersion_, fast};
    for (const WorkspaceObject& o : state_.objects) key.visible.push_back(o.visible);
    if (sceneKey_ && *sceneKey_ == key) return;
    sceneRenderer_->drawRig(cameras, surfaces, centre, state_.view, ui_.sceneViewSize(), !fast);
    sceneKey_ = key;
    ++sceneDraws_;
}

std::optional<OpenRequest> WorkspaceApp::takeOpenRequest() {
    std::optional<OpenRequest> r = std::move(state_.openRequest);
    state_.openRequest.reset();
    return r;
}

void WorkspaceApp::openFailed(const std::string& why) {
    state_.open.shown = true;
    state_.open.error = why;
}

void WorkspaceApp::frame() {
    backend_.newFrame();
    pollSolver();
    if (state_.tracking) tracking_.poll(*model_, state_);
    ImGui_ImplOpenGL3_NewFrame();
    ImGui::NewFrame();
    state_.interacting = false;
    WorkspaceTextures textures;
    const auto& views = model_->prepared(state_.frame);
    for (int c = 0; c < model_->cameraCount(); ++c) {
        textures.radiograph.push_back(radiographTextures_[c]->empty() ? 0 : radiographTextures_[c]->id());
        textures.model.push_back(modelTextures_[c]->empty() ? 0 : modelTextures_[c]->id());
        textures.images.push_back(&views[static_cast<std::size_t>(c)].reference);
    }
    textures.scene3d = sceneRenderer_->texture();
    ui_.draw(state_, textures);

    // A pose edit lasts while its control is held: a drag is one Undo step, a nudge one each.
    if (!applyControls() && !ImGui::IsAnyItemActive()) state_.undo.editOpen = false;
    processRequests();
    if (state_.tracking) tracking_.process(model_, state_);
    syncControls();
    try {
        updateImages();
    } catch (const Error& e) {  // an object that cannot be rendered: say so, keep the rest
        state_.error = e.what();
    }
    drawScene();
    ui_.drawSceneLabels(sceneRenderer_->labels());
    presenter_.present(backend_);
    // A Solve, a Track run or playing needs no more than the background frames (10 a second:
    // the workers keep the cores); nothing moving: sleep until the next event.
    const bool busy = state_.interacting || ImGui::IsMouseDown(ImGuiMouseButton_Left);
    const bool background = state_.solve.running || tracking_.running() || state_.track.playing;
    backend_.setActivity(busy ? Activity::Busy : background ? Activity::Background : Activity::Idle);
    ++state_.frameCounter;
}

render::RgbaImage WorkspaceApp::capture() const { return captureFrame(backend_); }

}  // namespace fm::app

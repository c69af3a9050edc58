#include "workspace/WorkspaceUi.h"

#include "ui/OpenWindow.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "ui/ImagePane.h"
#include "ui/TooltipPlacement.h"
#include "ui/UiWidgets.h"

namespace fm::app {

using namespace widgets;

namespace {

constexpr float kWrapEms = 40.0f;

ImVec4 colourOf(const WorkspaceObject& o) { return ImVec4(o.color[0], o.color[1], o.color[2], 1.0f); }

std::string idOf(const std::string& prefix, const std::string& name) {
    std::string s = prefix + name;
    std::replace(s.begin(), s.end(), ' ', '-');
    return s;
}

}  // namespace

WorkspaceLayout computeWorkspaceLayout(glm::vec2 display, int cameras, bool timeline) {
    const float w = std::max(display.x, 300.0f);
    // A trial's timeline takes a strip at the bottom; the rest is laid out as without it.
    const float strip = timeline ? std::max(140.0f, std::round(display.y * 0.22f)) : 0.0f;
    const float h = std::max(display.y - strip, 200.0f);
    const float column = w / 3.0f;
    const float top = std::min(h * (timeline ? 0.62f : 0.6f), (w - column) / std::max(1, cameras) + 60.0f);
    WorkspaceLayout l;
    const float cameraWidth = (w - column) / std::max(1, cameras);
    for (int c = 0; c < cameras; ++c) l.cameras.push_back({{c * cameraWidth, 0.0f}, {cameraWidth, top}});
    l.scene3d = {{w - column, 0.0f}, {column, top}};
    l.objects = {{0.0f, top}, {column, h - top}};
    l.pose = {{column, top}, {column, h - top}};
    l.solve = {{2.0f * column, top}, {w - 2.0f * column, h - top}};
    if (timeline) l.track = {{0.0f, h}, {w, strip}};
    return l;
}

void WorkspaceUi::record(const std::string& id) {
    const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
    rects_[id] = {{a.x, a.y}, {b.x, b.y}, ImGui::IsItemVisible()};
}

std::optional<WidgetRect> WorkspaceUi::rect(const std::string& id) const {
    const auto it = rects_.find(id);
    if (it == rects_.end()) return std::nullopt;
    return it->second;
}

void WorkspaceUi::tooltip(const std::string& text) { tooltip_ = text; }

void WorkspaceUi::drawTooltip() {
    shownTooltip_ = tooltip_;
    tooltip_.clear();
    if (shownTooltip_.empty()) return;
    const ImGuiStyle& style = ImGui::GetStyle();
    const float wrap = ImGui::GetFontSize() * kWrapEms;
    const ImVec2 text = ImGui::CalcTextSize(shownTooltip_.c_str(), nullptr, false, wrap - style.WindowPadding.x);
    const glm::vec2 size(text.x + 2.0f * style.WindowPadding.x, text.y + 2.0f * style.WindowPadding.y);
    const ImGuiIO& io = ImGui::GetIO();
    std::optional<ScreenRect> avoid;
    if (const auto bar = rect("progress:solve")) avoid = ScreenRect{bar->min, bar->max};
    const glm::vec2 at = placeTooltip({io.MousePos.x, io.MousePos.y}, size, {io.DisplaySize.x, io.DisplaySize.y}, avoid);
    ImGui::SetNextWindowPos(ImVec2(at.x, at.y), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(size.x, size.y), ImGuiCond_Always);
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(wrap);
    ImGui::TextUnformatted(shownTooltip_.c_str());
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
}

void WorkspaceUi::draw(WorkspaceState& state, const WorkspaceTextures& textures) {
    rects_.clear();  // what this frame draws, as the game's Ui: a widget not drawn has no rect
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const WorkspaceLayout layout =
        computeWorkspaceLayout({display.x, display.y}, static_cast<int>(state.cameraNames.size()), state.tracking);
    state.readout.valid = false;
    for (std::size_t c = 0; c < layout.cameras.size(); ++c)
        cameraPane(state, textures, static_cast<int>(c), layout.cameras[c]);
    scenePane(state, layout.scene3d, textures.scene3d);
    objectsPane(state, layout.objects);
    posePane(state, layout.pose);
    solvePane(state, layout.solve);
    if (state.tracking) trackPane(state, layout.track);
    if (auto r = drawOpenWindow(state.open, [this](const std::string& id) { record(id); })) {
        state.open.error.clear();
        state.openRequest = std::move(r);
    }
    if (state.enlargedCamera >= 0 && state.enlargedCamera < static_cast<int>(state.cameraNames.size())) {
        // Over everything, the whole window but a margin: a 1024^2 frame at full size where the
        // layout gives it a third of its pixels.
        const float margin = 8.0f;
        cameraPane(state, textures, state.enlargedCamera,
                   Pane{{margin, margin}, {display.x - 2 * margin, display.y - 2 * margin}}, true);
    }
    keyboard(state);
    drawTooltip();
}

void WorkspaceUi::cameraPane(WorkspaceState& state, const WorkspaceTextures& textures, int camera,
                             const Pane& pane, bool enlarged) {
    const std::string name = state.cameraNames.at(static_cast<std::size_t>(camera));
    const std::string title = name + ": " +
                              state.frameNames.at(static_cast<std::size_t>(camera)).at(static_cast<std::size_t>(state.frame)) +
                              (enlarged ? " (enlarged)###" + name + "-enlarged" : "###" + name);
    if (enlarged) {  // a window of its own over the panes (theirs never come to the front)
        ImGui::SetNextWindowPos(ImVec2(pane.pos.x, pane.pos.y), ImGuiCond_Always);
        ImGui::SetNextWindowSize(ImVec2(pane.size.x, pane.size.y), ImGuiCond_Always);
        ImGui::SetNextWindowBgAlpha(1.0f);
        ImGui::SetNextWindowFocus();
        ImGui::Begin(title.c_str(), nullptr, kPaneFlags & ~ImGuiWindowFlags_NoBringToFrontOnFocus);
    } else {
        beginPane(title.c_str(), pane);
    }
    const ImVec2 avail = ImGui::GetContentRegionAvail();
    const float reserve = ImGui::GetTextLineHeightWithSpacing();
    const int images = state.sideBySide ? 2 : 1;
    const float spacing = ImGui::GetStyle().ItemSpacing.x;
    const float side = std::max(16.0f, std::min((avail.x - spacing * (images - 1)) / images, avail.y - reserve));
    ImGui::SetCursorPosX(ImGui::GetCursorPosX() + std::max(0.0f, (avail.x - images * side - (images - 1) * spacing) * 0.5f));
    const Image* image = textures.images.at(static_cast<std::size_t>(camera));
    DisplaySettings& d = state.display.at(static_cast<std::size_t>(camera));
    const ImageEdgeLetters none{};
    const std::string id = "image:" + name;
    imagePane(id, textures.radiograph.at(static_cast<std::size_t>(camera)), image, nullptr, none, side,
              state.imageView, d, state.readout);
    record(id);
    if (ImGui::IsItemHovered())
        tooltip("The radiograph as the cost compares it (prepared; blue: pixels it leaves out), " +
                std::string(state.sideBySide ? "the model beside it" : "the model over it") +
                ". Wheel: zoom, right-drag: pan, left-drag: window/level");
    if (state.sideBySide) {
        ImGui::SameLine();
        const std::string modelId = "image:" + name + "-model";
        imagePane(modelId, textures.model.at(static_cast<std::size_t>(camera)), nullptr, nullptr, none, side,
                  state.imageView, d, state.readout);
        record(modelId);
    }
    if (state.readout.valid && state.readout.pane == id)
        ImGui::TextColored(kSelected, "pixel (%d, %d)  value %.4g  zoom %.1fx", state.readout.col, state.readout.row,
                           state.readout.value, state.imageView.zoom);
    else
        ImGui::TextColored(kDim, "window %.4g  level %.4g%s", d.window, d.level, d.autoWindow ? " (auto)" : "");
    ImGui::SameLine();
    if (enlarged) {
        if (ImGui::SmallButton("Close")) state.enlargedCamera = -1;
        record("button:close-enlarged");
        ImGui::SameLine();
        ImGui::TextColored(kDim, "(or Escape)");
    } else {
        if (ImGui::SmallButton(("Enlarge##" + name).c_str())) state.enlargedCamera = camera;
        record("button:enlarge-" + name);
        if (ImGui::IsItemHovered()) tooltip("Show this camera's pane over the whole window");
    }
    ImGui::End();
}

void WorkspaceUi::scenePane(WorkspaceState& state, const Pane& pane, unsigned texture) {
    beginPane("3D view", pane);
    const ImVec2 avail = ImGui::GetContentRegionAvail();
    const float reserve = ImGui::GetFrameHeightWithSpacing();
    const ImVec2 size(std::max(16.0f, avail.x), std::max(16.0f, avail.y - reserve));
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    ImGui::InvisibleButton("##scene3d", size,
                           ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight |
                               ImGuiButtonFlags_MouseButtonMiddle);
    record("view:3d");
    const ImGuiIO& io = ImGui::GetIO();
    if (ImGui::IsItemActive()) {  // as the game's 3D view: left orbits, middle pans, right zooms
        const ImVec2 delta = io.MouseDelta;
        if (ImGui::IsMouseDragging(ImGuiMouseButton_Middle, 0.0f) ||
            (io.KeyShift && ImGui::IsMouseDragging(ImGuiMouseButton_Left, 0.0f))) {
            state.view.panX -= delta.x / size.y * 2.0f / state.view.zoom;
            state.view.panY += delta.y / size.y * 2.0f / state.view.zoom;
        } else if (ImGui::IsMouseDragging(ImGuiMouseButton_Left, 0.0f)) {
            state.view.azimuthDeg = std::remainder(state.view.azimuthDeg - delta.x * 0.4f, 360.0f);
            state.view.elevationDeg = std::clamp(state.view.elevationDeg + delta.y * 0.4f, -89.0f, 89.0f);
        } else if (ImGui::IsMouseDragging(ImGuiMouseButton_Right, 0.0f)) {
            state.view.zoom = std::clamp(state.view.zoom * std::pow(1.01f, -delta.y), 0.2f, 8.0f);
        }
    }
    if (ImGui::IsItemHovered() && io.MouseWheel != 0.0f)
        state.view.zoom = std::clamp(state.view.zoom * std::pow(1.1f, io.MouseWheel), 0.2f, 8.0f);
    if (texture)  // the offscreen GL image is bottom-up: flip vertically
        ImGui::GetWindowDrawList()->AddImage(toImTexture(texture), origin,
                                             ImVec2(origin.x + size.x, origin.y + size.y), ImVec2(0, 1), ImVec2(1, 0));
    sceneViewSize_ = {int(size.x), int(size.y)};
    sceneOrigin_ = {origin.x, origin.y};
    sceneDrawList_ = ImGui::GetWindowDrawList();
    if (ImGui::Button("Reset view")) state.requests.resetView = true;
    record("button:reset-view");
    ImGui::SameLine();
    ImGui::Checkbox("Models", &state.view.showBone);
    ImGui::SameLine();
    ImGui::Checkbox("Cameras", &state.view.showApparatus);
    ImGui::End();
}

void WorkspaceUi::drawSceneLabels(const std::vector<render::SceneLabel>& labels) {
    if (!sceneDrawList_) return;
    for (const render::SceneLabel& l : labels) {
        if (l.pixel.x < 0 || l.pixel.y < 0 || l.pixel.x > sceneViewSize_.x || l.pixel.y > sceneViewSize_.y) continue;
        sceneDrawList_->AddText(ImVec2(sceneOrigin_.x + l.pixel.x + 4.0f, sceneOrigin_.y + l.pixel.y - 6.0f),
                                ImGui::ColorConvertFloat4ToU32(ImVec4(l.color.r, l.color.g, l.color.b, l.color.a)),
                                l.text.c_str());
    }
    sceneDrawList_ = nullptr;
}

void WorkspaceUi::objectsPane(WorkspaceState& state, const Pane& pane) {
    beginPane("Objects", pane);
    if (elidedText(kDim, state.title + " (" + state.source + ")") && ImGui::IsItemHovered())
        tooltip(state.source);
    for (std::size_t k = 0; k < state.objects.size(); ++k) {
        WorkspaceObject& o = state.objects[k];
        ImGui::PushID(static_cast<int>(k));
        ImGui::ColorButton("##swatch", colourOf(o), ImGuiColorEditFlags_NoTooltip | ImGuiColorEditFlags_NoDragDrop,
                           ImVec2(ImGui::GetFrameHeight(), ImGui::GetFrameHeight()));
        ImGui::SameLine();
        ImGui::Checkbox("##visible", &o.visible);
        record(idOf("checkbox:object-", o.name));
        if (ImGui::IsItemHovered()) tooltip("Show or hide " + o.name + " in every pane");
        ImGui::SameLine();
        if (ImGui::Selectable(o.name.c_str(), state.selected == static_cast<int>(k), 0,
                              ImVec2(ImGui::CalcTextSize("wwwwwwwwwwww").x, 0)))
            state.selected = static_cast<int>(k);
        record(idOf("select:object-", o.name));
        ImGui::SameLine();
        elidedText(kDim, o.kind);
        ImGui::PopID();
    }
    ImGui::Separator();
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted("frame");
    ImGui::SameLine();
    if (ImGui::ArrowButton("##prev", ImGuiDir_Left) && state.frame > 0) state.requests.frame = state.frame - 1;
    record("button:frame-prev");
    ImGui::SameLine();
    int frame = state.frame;
    ImGui::SetNextItemWidth(std::max(40.0f, ImGui::GetContentRegionAvail().x - ImGui::GetFrameHeight() -
                                                ImGui::GetStyle().ItemSpacing.x));
    if (ImGui::SliderInt("##frame", &frame, 0, std::max(0, state.frameCount - 1)) && frame != state.frame)
        state.requests.frame = frame;
    record("slider:frame");
    ImGui::SameLine();
    if (ImGui::ArrowButton("##next", ImGuiDir_Right) && state.frame + 1 < state.frameCount)
        state.requests.frame = state.frame + 1;
    record("button:frame-next");
    elidedText(kDim, std::to_string(state.frame + 1) + " of " + std::to_string(state.frameCount) + ": " +
                         state.frameNames.at(0).at(static_cast<std::size_t>(state.frame)));
    ImGui::Separator();
    if (ImGui::RadioButton("over", !state.sideBySide)) state.sideBySide = false;
    record("radio:overlay");
    ImGui::SameLine();
    if (ImGui::RadioButton("side by side", state.sideBySide)) state.sideBySide = true;
    record("radio:side-by-side");
    ImGui::SameLine();
    ImGui::TextColored(kDim, "|");
    ImGui::SameLine();
    if (ImGui::RadioButton("outline", state.modelImage == ModelImage::Outline)) state.modelImage = ModelImage::Outline;
    record("radio:outline");
    ImGui::SameLine();
    if (ImGui::RadioButton("DRR", state.modelImage == ModelImage::Drr)) state.modelImage = ModelImage::Drr;
    record("radio:drr");
    ImGui::Checkbox("all objects", &state.allObjects);
    record("checkbox:all-objects");
    if (ImGui::IsItemHovered()) tooltip("Draw every shown object, or the selected one only");
    ImGui::SameLine();
    if (ImGui::Button("Auto window"))
        for (DisplaySettings& d : state.display) d.autoWindow = true;
    record("button:auto-window");
    ImGui::SameLine();
    if (ImGui::Button("Open...")) state.open.shown = true;
    record("button:open-workspace");
    if (ImGui::IsItemHovered()) tooltip("Open another trial or radiograph, or a CT (the matching game); Recent");
    // How each camera's radiograph is prepared, as --invert / --log would: what Solve and Track
    // compare (a trial's Save trial keeps it). One camera: "invert"; more: "invert cam2" ...
    ImGui::BeginDisabled(state.solve.running || state.track.run.running);
    for (std::size_t c = 0; c < state.cameraValues.size(); ++c) {
        WorkspaceState::CameraValues& v = state.cameraValues[c];
        const std::string suffix = state.cameraValues.size() > 1 ? " " + state.cameraNames.at(c) : "";
        const std::string idSuffix = c == 0 ? "" : ":" + state.cameraNames.at(c);
        if (ImGui::Checkbox(("invert" + suffix).c_str(), &v.invert)) {
            if (v.invert) v.logTransform = false;
            state.requests.preparation = true;
        }
        record("checkbox:invert" + idSuffix);
        if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
            tooltip("Full scale minus the value (--invert): a display signal shows dense matter dark, a DRR "
                    "bright; Solve and Track compare the image as shown");
        ImGui::SameLine();
        if (ImGui::Checkbox(("log" + suffix).c_str(), &v.logTransform)) {
            if (v.logTransform) v.invert = false;
            state.requests.preparation = true;
        }
        record("checkbox:log" + idSuffix);
        if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
            tooltip("-ln(I / I0) of raw detector intensities (--log): line integrals, like a DRR's");
    }
    ImGui::EndDisabled();
    if (!state.rawHint.empty()) {
        coloredWrapped(kWarn, state.rawHint);
        record("text:raw-hint");
    }
    for (const std::string& w : state.warnings) coloredWrapped(kWarn, w);
    ImGui::End();
}

void WorkspaceUi::posePane(WorkspaceState& state, const Pane& pane) {
    beginPane("Pose", pane);
    if (state.objects.empty()) {
        ImGui::End();
        return;
    }
    const WorkspaceObject& o = state.objects.at(static_cast<std::size_t>(state.selected));
    ImGui::TextColored(colourOf(o), "moving: %s", o.name.c_str());
    ImGui::SameLine();
    ImGui::TextColored(kDim, "in");
    ImGui::SameLine();
    if (ImGui::RadioButton("camera", state.poseFrame == PoseFrame::Camera)) state.poseFrame = PoseFrame::Camera;
    record("radio:pose-camera");
    if (ImGui::IsItemHovered())
        tooltip("x, y along the film's columns and rows, depth from the source along the view (mm, of the "
                "object's centre); rotations about the film axes and the view through its centre (deg, from "
                "where the controls were set: R = R_view R_u R_v)");
    ImGui::SameLine();
    if (ImGui::RadioButton("world", state.poseFrame == PoseFrame::World)) state.poseFrame = PoseFrame::World;
    record("radio:pose-world");
    if (ImGui::IsItemHovered())
        tooltip("x, y, z of the object's centre in the calibration's world (mm); rotations about the world "
                "axes through it (deg, from where the controls were set: R = R_z R_x R_y)");
    if (state.poseFrame == PoseFrame::Camera && state.cameraNames.size() > 1) {
        ImGui::SameLine();
        ImGui::SetNextItemWidth(ImGui::CalcTextSize("cam01 ").x + ImGui::GetFrameHeight() * 1.5f);
        if (ImGui::BeginCombo("##posecamera", state.cameraNames.at(static_cast<std::size_t>(state.poseCamera)).c_str())) {
            for (std::size_t c = 0; c < state.cameraNames.size(); ++c)
                if (ImGui::Selectable(state.cameraNames[c].c_str(), state.poseCamera == static_cast<int>(c)))
                    state.poseCamera = static_cast<int>(c);
            ImGui::EndCombo();
        }
        record("combo:pose-camera");
    }
    PoseControls& c = state.controls;
    const ParameterRowWidths widths = parameterRowWidths();
    const auto recordItem = [this](const std::string& id) { record(id); };
    for (int p = 0; p < 6 && c.object >= 0; ++p) {
        ImGui::PushID(p);
        const ParameterRowResult row = parameterRow(c.specs[p], c.values[p], p == c.selected, widths, recordItem);
        if (row.labelHovered) tooltip("Up/Down select, Left/Right (or the wheel over its slider) nudge by 1 (Shift: 0.1)");
        if (row.sliderActive) state.interacting = true;
        if (row.selected) c.selected = p;
        ImGui::PopID();
    }
    if (state.iou) ImGui::Text("silhouette IoU %.4f against the mask", *state.iou);
    ImGui::End();
}

void WorkspaceUi::solvePane(WorkspaceState& state, const Pane& pane) {
    beginPane("Solve and save", pane);
    WorkspaceSolve& s = state.solve;
    if (ImGui::Button(s.running ? "Stop" : "Solve")) {
        if (s.running)
            state.requests.stopSolve = true;
        else
            state.requests.solve = true;
    }
    record("button:solve");
    if (ImGui::IsItemHovered())
        tooltip(state.cameraNames.size() > 1
                    ? "Register the selected object in this frame from your pose, in all cameras at once "
                      "(register --trial)"
                    : "Register the selected object in this frame from your pose (register --reference: "
                      "edge distance for meshes, gradient NCC for volumes)");
    ImGui::SameLine();
    // Find: the pose with no start (docs/find.md); Stop (the button above) ends it.
    ImGui::BeginDisabled(s.running || state.track.run.running);
    if (ImGui::Button("Find")) state.requests.find = true;
    ImGui::EndDisabled();
    record("button:find");
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        tooltip(state.cameraNames.size() > 1
                    ? "Find the selected object in this frame with no start (track with no keyframe: a bone volume "
                      "in all cameras at once, a mesh in each camera, which must agree), then registered in all of "
                      "them. Undo rejects it"
                    : "Find the selected object in this frame with no start (register with no --start): the "
                      "answer is shown; Next candidate steps through the others, Undo rejects it");
    ImGui::SameLine();
    // Undo: the poses before the last Solve, Track run, keyframe or pose edit (Ctrl+Z).
    const bool canUndo = !state.undo.steps.empty() && !s.running && !state.track.run.running;
    ImGui::BeginDisabled(!canUndo);
    if (ImGui::Button("Undo")) state.requests.undo = true;
    ImGui::EndDisabled();
    record("button:undo");
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        tooltip(state.undo.steps.empty() ? std::string("Nothing to undo")
                                         : "Undo the " + state.undo.steps.back().what + " (Ctrl+Z)");
    const ImGuiIO& io = ImGui::GetIO();
    if (canUndo && io.KeyCtrl && !io.WantTextInput && ImGui::IsKeyPressed(ImGuiKey_Z, false))
        state.requests.undo = true;
    ImGui::SameLine();
    const float fraction = s.budget > 0 ? std::min(1.0f, float(s.evaluations) / float(s.budget)) : (s.running ? 0.0f : 1.0f);
    char overlay[96];
    std::snprintf(overlay, sizeof overlay, "%d / %d", s.evaluations, s.budget);
    ImGui::ProgressBar(s.running || s.finished ? fraction : 0.0f, ImVec2(-1.0f, 0.0f), s.budget > 0 ? overlay : "");
    record("progress:solve");
    // The save row before the answer's lines (they may run past the pane's foot).
    // Two saves in a trial: this one writes every object (Track's "Save <object>.tra" one): said
    // on the button.
    const char* saveLabel = state.objects.size() > 1 ? "Save all objects" : "Save";
    ImGui::SetNextItemWidth(std::max(60.0f, ImGui::GetContentRegionAvail().x - ImGui::CalcTextSize(saveLabel).x -
                                                2 * ImGui::GetStyle().FramePadding.x - ImGui::GetStyle().ItemSpacing.x));
    ImGui::InputText("##savepath", &state.savePath);
    record("input:save-path");
    if (ImGui::IsItemHovered())
        tooltip("Where Save writes every frame's poses of every object: one .tra (Autoscoper, the objects in "
                "the trial's order) for a trial; .jts (JointTrack) or .tra for one radiograph");
    ImGui::SameLine();
    if (ImGui::Button(saveLabel)) state.requests.save = true;
    record("button:save");
    if (!state.undoMessage.empty()) dimWrapped("%s", state.undoMessage.c_str());
    if (!state.saveMessage.empty()) coloredWrapped(state.saveFailed ? kBad : kGood, state.saveMessage);
    if (!state.error.empty()) coloredWrapped(kBad, state.error);
    ImGui::Separator();
    if (s.running) dimWrapped("%s", s.stage.c_str());
    if (!s.error.empty()) coloredWrapped(kBad, s.error);
    if (s.finished && s.result) {
        // Words and colour from the verdict: green only for an ok answer.
        using Check = WorkspaceSolve::Check;
        // A Find candidate other than the answer is shown unjudged: never in the answer's green.
        const ImVec4 colour = s.check == Check::Ok && !s.stopped && s.candidate == 0 ? kGood
                              : s.check == Check::Lost                                ? kBad
                                                                                      : kWarn;
        coloredWrapped(colour, s.summary);
        record("text:solve-summary");
        coloredWrapped(colour, s.checkText);
        record("text:solve-check");
        if (s.find && s.candidates.size() > 1) {
            // The finder's other answers, shown one at a time on the object (each an Undo step):
            // before the answer's details, which may run past the pane's foot.
            const int n = static_cast<int>(s.candidates.size());
            ImGui::BeginDisabled(s.running);
            if (ImGui::Button("Next candidate")) state.requests.candidate = (s.candidate + 1) % n;
            ImGui::EndDisabled();
            record("button:next-candidate");
            ImGui::SameLine();
            dimWrapped("candidate %d of %d, similarity %.4f%s", s.candidate + 1, n,
                       s.candidateSimilarity.at(static_cast<std::size_t>(s.candidate)),
                       s.candidate == 0 ? " (the answer, judged above)" : " (not judged: Solve it to judge it)");
        }
        bulletWrapped("moved in-plane %.2f mm, depth %.2f mm, rotation %.2f deg", s.inPlaneMm, s.depthMm, s.rotationDeg);
        if (s.iou) bulletWrapped("IoU %.4f against the mask (start %.4f)", *s.iou, s.startIou.value_or(0.0));
        if (!s.uncertaintyText.empty()) bulletWrapped("uncertainty %s", s.uncertaintyText.c_str());
        if (state.showTimings) bulletWrapped("%.2f s, %d evaluations", s.seconds, s.evaluations);
    }
    ImGui::End();
}

void WorkspaceUi::keyboard(WorkspaceState& state) {
    const ImGuiIO& io = ImGui::GetIO();
    if (io.WantTextInput) return;  // typing a number or a path: the keys are the field's
    const auto pressed = [](ImGuiKey key) { return ImGui::IsKeyPressed(ImGui::GetKeyIndex(key), true); };
    if (pressed(ImGuiKey_Escape)) state.enlargedCamera = -1;
    PoseControls& c = state.controls;
    if (pressed(ImGuiKey_UpArrow)) c.selected = (c.selected + 5) % 6;
    if (pressed(ImGuiKey_DownArrow)) c.selected = (c.selected + 1) % 6;
    const int direction = (pressed(ImGuiKey_RightArrow) ? 1 : 0) - (pressed(ImGuiKey_LeftArrow) ? 1 : 0);
    if (direction == 0 || c.object < 0) return;
    const ParameterSpec& spec = c.specs[c.selected];
    c.values[c.selected] = nudgedValue(c.values[c.selected], direction, io.KeyShift, spec.min, spec.max);
}

}  // namespace fm::app

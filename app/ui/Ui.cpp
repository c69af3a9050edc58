#include "ui/Ui.h"

#include "ui/OpenWindow.h"
#include "ui/UiWidgets.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>

namespace fm::app {
namespace {

using namespace widgets;

// The largest square that fits the remaining content region, centred horizontally (the
// cursor is left at its top-left corner).
float squareSide(float reserveBelow) {
    const ImVec2 avail = ImGui::GetContentRegionAvail();
    const float side = std::max(16.0f, std::min(avail.x, avail.y - reserveBelow));
    ImGui::SetCursorPosX(ImGui::GetCursorPosX() + std::max(0.0f, (avail.x - side) * 0.5f));
    return side;
}

// The caption under a 2D image: the pixel under the mouse while there is one.
bool readoutLine(const AppState& state, const std::string& pane) {
    if (!state.readout.valid || state.readout.pane != pane) return false;
    if (state.readout.hasData)
        ImGui::TextColored(kSelected, "pixel (%d, %d)  value %.4g  zoom %.1fx", state.readout.col,
                           state.readout.row, state.readout.value, state.imageView.zoom);
    else  // outside the volume's box: no value at all (shown black, but not a 0)
        ImGui::TextColored(kSelected, "pixel (%d, %d)  no data  zoom %.1fx", state.readout.col,
                           state.readout.row, state.imageView.zoom);
    return true;
}

}  // namespace

void Ui::record(const std::string& id) {
    const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
    rects_[id] = {{a.x, a.y}, {b.x, b.y}, ImGui::IsItemVisible()};
}

std::optional<WidgetRect> Ui::rect(const std::string& id) const {
    auto it = rects_.find(id);
    if (it == rects_.end()) return std::nullopt;
    return it->second;
}

void Ui::draw(AppState& state, const UiTextures& textures) {
    rects_.clear();
    sceneDrawList_ = nullptr;
    textures_ = textures;
    state.readout.valid = false;
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const Layout layout = computeLayout({display.x, display.y});
    referencePane(state, layout.reference, textures.reference);
    userPane(state, layout.user, textures.user);
    scenePane(state, layout.scene3d, textures.scene3d);
    parameterPane(state, layout.parameters);
    comparePane(state, layout.compare, textures.compare);
    matchPane(state, layout.match);
    if (state.compareEnlarged) enlargedCompare(state, textures.compare);
    if (state.showHelp) helpWindow(state);
    if (auto r = drawOpenWindow(state.open, [this](const std::string& id) { record(id); })) {
        state.open.error.clear();
        state.openRequest = std::move(r);
    }
    keyboard(state);
    drawTooltip();  // last: it knows where the progress bar is
}

void Ui::referencePane(AppState& state, const Pane& pane, unsigned texture) {
    beginPane("Reference image", pane);
    const float side = squareSide(ImGui::GetTextLineHeightWithSpacing());
    imageWidget(state, "image:reference", texture, textures_.referenceImage,
                textures_.referenceDataMask, state.referenceEdges, side);
    const FlexGame& flex = state.bones.flex;
    if (readoutLine(state, "image:reference")) {
    } else if (flex.active) {  // the bone game's reference: its bone moved, the camera yours
        const std::string bone = flex.bone >= 0 && flex.bone < int(state.bones.list.size())
                                     ? state.bones.list[static_cast<std::size_t>(flex.bone)].name
                                     : std::string("the bone");
        if (flex.revealed) {
            const auto& m = flex.hiddenMotion;
            ImGui::TextColored(kDim, "%s moved %.1f, %.1f, %.1f mm | %.1f, %.1f, %.1f deg",
                               bone.c_str(), m[0], m[1], m[2], m[3], m[4], m[5]);
        } else {
            ImGui::TextColored(kDim, "Bone game: %s moved by a hidden motion.", bone.c_str());
        }
        record("text:reference-caption");
    } else if (state.referenceRevealed) {
        poseLine(state.referencePose);
        record("text:reference-caption");
    } else {
        ImGui::TextColored(kDim, "Parameters hidden: match this image.");
        record("text:reference-caption");
    }
    ImGui::End();
}

void Ui::userPane(AppState& state, const Pane& pane, unsigned texture) {
    // One window id whatever the title says (the mode renames it).
    beginPane(state.mode == ImagingMode::Slice ? "Your slice###user" : "Your DRR###user", pane);
    const float side = squareSide(ImGui::GetTextLineHeightWithSpacing());
    imageWidget(state, "image:user", texture, textures_.userImage, textures_.userDataMask,
                state.userEdges, side);
    if (readoutLine(state, "image:user")) {
    } else if (state.solve.running) {  // the image follows the computer's best pose meanwhile
        ImGui::TextColored(kWarn, "solving:");
        ImGui::SameLine();
        if (state.referenceRevealed)
            poseLine(state.solve.bestPose);
        else  // the best pose converges on the answer
            ImGui::TextColored(kDim, "its best pose so far (numbers after Reveal)");
    } else if (state.mode == ImagingMode::Slice && state.userSliceEmpty) {
        ImGui::TextColored(kWarn, "The plane misses the volume: no data.");
    } else {
        poseLine(state.userPose);
    }
    ImGui::End();
}

void Ui::scenePane(AppState& state, const Pane& pane, unsigned texture) {
    beginPane("3D view", pane);
    // The controls under the view take one row, or two when the pane is too narrow for one.
    const ImGuiStyle& style = ImGui::GetStyle();
    const float levelWidth = ImGui::CalcTextSize("-0000").x + style.FramePadding.x * 2;
    const auto checkboxWidth = [&](const char* label) {
        return ImGui::GetFrameHeight() + style.ItemInnerSpacing.x + ImGui::CalcTextSize(label).x;
    };
    const float firstPart = ImGui::CalcTextSize("Reset view").x + style.FramePadding.x * 2 +
                            checkboxWidth("Bone") + levelWidth + style.ItemInnerSpacing.x +
                            ImGui::CalcTextSize("level").x + 2 * style.ItemSpacing.x;
    const float secondPart =
        checkboxWidth("CT box") + checkboxWidth("Source+film") + style.ItemSpacing.x;
    const bool twoRows =
        firstPart + style.ItemSpacing.x + secondPart > ImGui::GetContentRegionAvail().x;
    const float reserve = ImGui::GetFrameHeightWithSpacing() * (twoRows ? 2.0f : 1.0f);
    const ImVec2 avail = ImGui::GetContentRegionAvail();
    const ImVec2 size(std::max(16.0f, avail.x), std::max(16.0f, avail.y - reserve));
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    ImGui::InvisibleButton("##scene3d", size,
                           ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight |
                               ImGuiButtonFlags_MouseButtonMiddle);
    record("view:3d");
    const bool hovered = ImGui::IsItemHovered();
    const ImGuiIO& io = ImGui::GetIO();
    const ImVec2 delta = io.MouseDelta;
    if (ImGui::IsItemActive()) {
        // As in 3D Slicer: left orbits (Shift+left pans), middle pans, right zooms.
        const bool pan = ImGui::IsMouseDragging(ImGuiMouseButton_Middle, 0.0f) ||
                         (io.KeyShift && ImGui::IsMouseDragging(ImGuiMouseButton_Left, 0.0f));
        if (pan) {
            state.view.panX -= delta.x / size.y * 2.0f / state.view.zoom;
            state.view.panY += delta.y / size.y * 2.0f / state.view.zoom;
        } else if (ImGui::IsMouseDragging(ImGuiMouseButton_Left, 0.0f)) {
            state.view.azimuthDeg = std::remainder(state.view.azimuthDeg - delta.x * 0.4f, 360.0f);
            state.view.elevationDeg =
                std::clamp(state.view.elevationDeg + delta.y * 0.4f, -89.0f, 89.0f);
        } else if (ImGui::IsMouseDragging(ImGuiMouseButton_Right, 0.0f)) {
            state.view.zoom = std::clamp(state.view.zoom * std::pow(1.01f, -delta.y), 0.2f, 8.0f);
        }
    }
    if (hovered && ImGui::GetIO().MouseWheel != 0.0f)
        state.view.zoom =
            std::clamp(state.view.zoom * std::pow(1.1f, ImGui::GetIO().MouseWheel), 0.2f, 8.0f);
    ImDrawList* list = ImGui::GetWindowDrawList();
    if (texture)  // the offscreen GL image is bottom-up: flip vertically
        list->AddImage(toImTexture(texture), origin, ImVec2(origin.x + size.x, origin.y + size.y),
                       ImVec2(0, 1), ImVec2(1, 0));
    sceneDrawList_ = list;
    sceneViewOrigin_ = {origin.x, origin.y};
    sceneViewSize_ = {int(size.x), int(size.y)};

    if (ImGui::Button("Reset view")) state.requests.resetView = true;
    record("button:reset-view");
    ImGui::SameLine();
    ImGui::Checkbox("Bone", &state.view.showBone);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(levelWidth);
    ImGui::DragFloat("level", &state.bone.level, 5.0f, state.bone.minLevel, state.bone.maxLevel,
                     "%.0f", ImGuiSliderFlags_AlwaysClamp);
    record("drag:bone-level");
    // Rebuilt once the drag (or typed value) is done, not at every step of it.
    if (ImGui::IsItemDeactivatedAfterEdit()) state.requests.remesh = true;
    if (ImGui::IsItemHovered())
        tooltip(
            "Level of the bone surface (HU for CTs): drag, or double-click and type.\n"
            "Shown: %zu triangles at %.0f (marching cubes %.0f ms)",
            state.bone.triangles, state.bone.shownLevel, state.timings.meshMs);
    if (!twoRows) ImGui::SameLine();
    ImGui::Checkbox("CT box", &state.view.showBox);
    ImGui::SameLine();
    ImGui::Checkbox("Source+film", &state.view.showApparatus);
    ImGui::End();
}

void Ui::drawSceneLabels(const std::vector<std::pair<glm::vec2, std::string>>& labels,
                         const std::vector<glm::vec4>& colors) {
    if (!sceneDrawList_) return;
    const ImVec2 lo(sceneViewOrigin_.x, sceneViewOrigin_.y);
    const ImVec2 hi(lo.x + sceneViewSize_.x, lo.y + sceneViewSize_.y);
    sceneDrawList_->PushClipRect(lo, hi, true);
    for (std::size_t i = 0; i < labels.size(); ++i) {
        const glm::vec4 c = i < colors.size() ? colors[i] : glm::vec4(1.0f);
        sceneDrawList_->AddText(ImVec2(lo.x + labels[i].first.x + 4, lo.y + labels[i].first.y - 6),
                                ImGui::ColorConvertFloat4ToU32(ImVec4(c.r, c.g, c.b, c.a)),
                                labels[i].second.c_str());
    }
    sceneDrawList_->PopClipRect();
}

void Ui::parameterPane(AppState& state, const Pane& pane) {
    beginPane("Parameters", pane);
    const auto specs = sliderSpecs(state);
    const int target = state.bones.sliderTarget;
    const bool movingBone = target >= 0 && target < int(state.bones.list.size());
    const ParameterRowWidths widths = parameterRowWidths();
    const auto recordItem = [this](const std::string& id) { record(id); };
    for (int p = 0; p < kParameterCount; ++p) {
        const ParameterSpec& spec = specs[p];
        double& value = sliderValue(state, p);
        const double before = value;
        ImGui::PushID(p);
        const ParameterRowResult row =
            parameterRow(spec, value, p == state.selectedParameter, widths, recordItem);
        if (row.labelHovered)
            tooltip("Up/Down select a parameter, Left/Right (or the wheel over its slider) "
                    "nudge it by 1 %s (Shift: 0.1)", spec.unit);
        if (row.sliderActive) state.interacting = true;
        if (row.selected) state.selectedParameter = p;
        ImGui::PopID();
        if (value != before) state.matchIsStale = true;
    }
    if (movingBone) {
        // The sliders move one bone: name it, and give the knee's angles live while it moves.
        if (ImGui::Button("Rest")) state.bones.list[target].motion = {};
        record("button:bone-rest");
        if (ImGui::IsItemHovered()) tooltip("Put the bone back where the CT has it");
        ImGui::SameLine();
        const auto& c = state.bones.list[target].color;
        ImGui::TextColored(ImVec4(c[0], c[1], c[2], 1.0f), "moving: %s",
                           state.bones.list[target].name.c_str());
        if (ImGui::IsItemHovered())
            tooltip("Shifts along and turns about the LPS axes, through the bone's "
                              "pivot (femur, tibia: the knee's flexion axis). Bones tab: the "
                              "camera again");
        kneeAnglesLine(state);
    } else {
        if (ImGui::Button("Centre pose")) {
            state.userPose = Pose{};
            state.matchIsStale = true;
        }
        record("button:centre-pose");
        ImGui::SameLine();
        ImGui::TextColored(kDim, "frame: LPS mm");
    }
    if (ImGui::IsItemHovered())
        tooltip("Offsets in the patient frame LPS: +x Left, +y Posterior, +z "
                          "Superior (DICOM, ITK).\n3D Slicer's RAS is the same with x and y "
                          "negated: RAS = (-x, -y, z).");
    modeSwitch(state);

    ImGui::Separator();
    const float spacing = ImGui::GetStyle().ItemSpacing.x;
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted("CT");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(std::max(60.0f, ImGui::GetContentRegionAvail().x -
                                                ImGui::CalcTextSize("Open Knee ...").x - 7 * spacing));
    const bool enter =
        ImGui::InputTextWithHint("##volume", "file, DICOM folder or phantom:NAME",
                                 &state.volumePathField, ImGuiInputTextFlags_EnterReturnsTrue);
    record("input:volume");
    if (ImGui::IsItemHovered())
        tooltip(
            "Type a path and press Enter, or drop a CT file or folder onto the window");
    ImGui::SameLine();
    if ((ImGui::Button("Open") || enter) && !state.volumePathField.empty())
        state.requests.loadVolume = state.volumePathField;
    record("button:open");
    ImGui::SameLine();
    if (ImGui::Button("Knee")) state.requests.loadVolume = std::string("phantom:knee");
    record("button:knee");
    ImGui::SameLine();  // one row: the pane has no room for another
    if (ImGui::Button("...")) state.open.shown = true;
    record("button:open-workspace");
    if (ImGui::IsItemHovered())
        tooltip("Open a trial (.json, Autoscoper .cfg) or one radiograph with its calibration and "
                "models in the real X-ray workspace, or a recent file");

    const LoadStatus& load = state.load;
    if (load.loading) {
        stageProgressBar(load.progress, load.stage, load.elapsedSeconds);
        record("progress:load");
        elidedLine("text:loading", kDim, "Loading " + load.requestedSpec + " ...");
    } else {
        elidedLine("text:loaded", kDim, load.loadedSpec.empty() ? "No CT loaded" : load.loadedSpec);
        elidedLine("text:summary", kDim, load.summary);
        if (!load.loadedSpec.empty()) {
            char text[160];
            if (state.bone.displayFactor > 1)  // drawn coarser than the volume: said
                std::snprintf(text, sizeof(text),
                              "%zu surface triangles (iso %.4g; drawn from %d^3 block means, "
                              "%zu at full resolution)",
                              state.bone.triangles, state.bone.shownLevel,
                              state.bone.displayFactor, state.bone.fullTriangles);
            else
                std::snprintf(text, sizeof(text), "%zu bone triangles (iso %.4g)",
                              state.bone.triangles, state.bone.shownLevel);
            elidedLine("text:bone-triangles", kDim, text);
        }
    }
    if (!load.error.empty()) coloredWrapped(kBad, load.error);  // wraps: never cut off
    ImGui::End();
}

void Ui::drrThresholdControl(AppState& state, float width) {
    DrrThreshold& t = state.drrThreshold;
    if (ImGui::Checkbox("Bone-only DRR", &t.enabled)) state.requests.boneThreshold = true;
    record("checkbox:bone-only");
    if (ImGui::IsItemHovered())
        tooltip("Leave out of both DRRs every voxel below the level beside (%s): a CT's DRR "
                "otherwise shows mostly soft tissue. Match and Solve use the same images.",
                t.valuesInHu ? "HU" : "the volume's values");
    ImGui::BeginDisabled(!t.enabled);
    ImGui::SetNextItemWidth(width);
    ImGui::DragFloat("##bone-threshold", &t.level, 5.0f, state.bone.minLevel, state.bone.maxLevel,
                     t.valuesInHu ? "from %.0f HU" : "from %.4g", ImGuiSliderFlags_AlwaysClamp);
    // Prepared again once the drag ends or the typed value is confirmed (as the bone level).
    if (ImGui::IsItemDeactivatedAfterEdit()) state.requests.boneThreshold = true;
    record("drag:bone-threshold");
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        tooltip("The bone-only level: drag, or double-click and type (applied on release; "
                "the last preparation took %.0f ms)", t.prepareMs);
    ImGui::EndDisabled();
}

void Ui::comparePane(AppState& state, const Pane& pane, unsigned texture) {
    beginPane("Compare", pane);
    int mode = static_cast<int>(state.display.compare);
    ImGui::RadioButton("Difference", &mode, 0);
    record("radio:difference");
    ImGui::SameLine();
    ImGui::RadioButton("Overlay", &mode, 1);
    record("radio:overlay");
    ImGui::SameLine();
    ImGui::RadioButton("Checkerboard", &mode, 2);
    record("radio:checkerboard");
    state.display.compare = static_cast<CompareMode>(mode);

    const float controlsWidth = ImGui::GetContentRegionAvail().x * 0.42f;
    const ImVec2 avail = ImGui::GetContentRegionAvail();
    const float side = std::max(16.0f, std::min(avail.x - controlsWidth - 8.0f, avail.y));
    imageWidget(state, "image:compare", texture, nullptr, nullptr, state.userEdges, side);
    ImGui::SameLine();
    ImGui::BeginGroup();
    const char* legend = state.display.compare == CompareMode::Difference
                             ? "red: yours denser\nblue: reference denser"
                         : state.display.compare == CompareMode::Overlay
                             ? "magenta: reference\ngreen: yours"
                             : "tiles alternate\nreference / yours";
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + controlsWidth);
    ImGui::TextColored(kDim, "%s", legend);
    ImGui::PopTextWrapPos();
    ImGui::Checkbox("Auto window", &state.display.autoWindow);
    record("checkbox:auto-window");

    ImGui::SetNextItemWidth(controlsWidth - ImGui::CalcTextSize("Window").x - 8.0f);
    const float range = std::max(state.display.window, state.display.level) * 2.0f + 1e-6f;
    // Drag fields, not sliders: the value stays readable (a slider's grab covers it). The
    // values are the images' own: line integrals (mu x mm, or value x mm for raw volumes).
    if (ImGui::DragFloat("Window", &state.display.window, range * 2e-3f, range * 1e-3f, range,
                         "%.3g", ImGuiSliderFlags_AlwaysClamp))
        state.display.autoWindow = false;
    record("slider:window");
    // A DRR holds line integrals; a slice the volume's own values (HU, or an MRI's units).
    const char* units = state.mode == ImagingMode::Slice ? "the volume's values" : "line integral";
    if (ImGui::IsItemHovered())
        tooltip("Width of the grey range, in the images' units (%s). Or drag "
                          "left/right on an image", units);
    ImGui::SetNextItemWidth(controlsWidth - ImGui::CalcTextSize("Window").x - 8.0f);
    if (ImGui::DragFloat("Level", &state.display.level, range * 2e-3f, -range * 0.5f, range,
                         "%.3g"))
        state.display.autoWindow = false;
    record("slider:level");
    if (ImGui::IsItemHovered())
        tooltip("Centre of the grey range, in the images' units (%s). Or drag up/down "
                          "on an image", units);
    if (ImGui::SmallButton("Enlarge")) state.compareEnlarged = true;
    record("button:enlarge-compare");
    if (state.mode == ImagingMode::Xray) {
        drrThresholdControl(state, controlsWidth);
        ImGui::BeginDisabled(!state.realistic.available);
        ImGui::Checkbox("Realistic", &state.realistic.enabled);
        record("checkbox:realistic-reference");
        if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) {
            if (state.realistic.available)
                tooltip("The reference as a real radiograph: %s kVp through the CT's soft tissue and bone "
                        "(materials and density from HU), scatter, blur and quantum noise (docs/drr.md). "
                        "Your image stays a DRR; Match and Solve compare the two.",
                        state.realistic.spectrum.c_str());
            else
                tooltip("Needs a CT in HU, shown whole (no bone hidden or moved)");
        }
        ImGui::EndDisabled();
    }
    const Timings& t = state.timings;
    ImGui::Spacing();
    if (!state.showTimings) {
        ImGui::EndGroup();
        ImGui::End();
        return;
    }
    // Wrapped inside the column beside the image (they would run past the pane).
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + controlsWidth);
    dimWrapped("user %s %.1f ms %s", state.mode == ImagingMode::Slice ? "slice" : "DRR",
               t.userDrrMs, t.userDrrCoarse ? "(coarse)" : "(exact)");
    dimWrapped("exact %.1f ms, coarse/%d %.1f ms", t.lastExactMs, t.coarseFactor, t.lastCoarseMs);
    dimWrapped("frame %.1f ms", t.frameMs);
    ImGui::PopTextWrapPos();
    ImGui::EndGroup();
    ImGui::End();
}

}  // namespace fm::app

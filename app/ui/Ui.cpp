#include "ui/Ui.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdarg>
#include <cstdint>
#include <cstdio>

namespace fm::app {
namespace {

constexpr ImGuiWindowFlags kPaneFlags =
    ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
    ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBringToFrontOnFocus;
const ImVec4 kGood{0.45f, 0.90f, 0.45f, 1.0f};
const ImVec4 kWarn{1.00f, 0.70f, 0.30f, 1.0f};
const ImVec4 kBad{1.00f, 0.40f, 0.40f, 1.0f};
const ImVec4 kDim{0.65f, 0.65f, 0.70f, 1.0f};

ImTextureID toImTexture(unsigned id) {
    return reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(id));
}

bool beginPane(const char* title, const Pane& pane) {
    ImGui::SetNextWindowPos(ImVec2(pane.pos.x, pane.pos.y), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(pane.size.x, pane.size.y), ImGuiCond_Always);
    return ImGui::Begin(title, nullptr, kPaneFlags);
}

// The largest square that fits the remaining content region, centred horizontally.
float squareImage(unsigned texture, float reserveBelow) {
    const ImVec2 avail = ImGui::GetContentRegionAvail();
    const float side = std::max(16.0f, std::min(avail.x, avail.y - reserveBelow));
    ImGui::SetCursorPosX(ImGui::GetCursorPosX() + std::max(0.0f, (avail.x - side) * 0.5f));
    if (texture)
        ImGui::Image(toImTexture(texture), ImVec2(side, side));
    else
        ImGui::Dummy(ImVec2(side, side));
    return side;
}

void poseLine(const Pose& pose) {
    // Compact: it must fit under the image at 960 px wide windows.
    ImGui::Text("%.1f, %.1f, %.1f mm | %.1f, %.1f, %.1f deg", pose.offset.x, pose.offset.y,
                pose.offset.z, pose.azimuthDeg, pose.elevationDeg, pose.rotationDeg);
}

double& poseValue(Pose& pose, int parameter) {
    switch (parameter) {
        case kOffsetX:
            return pose.offset.x;
        case kOffsetY:
            return pose.offset.y;
        case kOffsetZ:
            return pose.offset.z;
        case kAzimuth:
            return pose.azimuthDeg;
        case kElevation:
            return pose.elevationDeg;
        default:
            return pose.rotationDeg;
    }
}

// A bullet whose text wraps at the window edge (BulletText does not wrap).
void bulletWrapped(const char* format, ...) IM_FMTARGS(1);
void bulletWrapped(const char* format, ...) {
    ImGui::Bullet();
    va_list args;
    va_start(args, format);
    ImGui::TextWrappedV(format, args);
    va_end(args);
}

// Dimmed text that wraps.
void dimWrapped(const char* format, ...) IM_FMTARGS(1);
void dimWrapped(const char* format, ...) {
    ImGui::PushStyleColor(ImGuiCol_Text, kDim);
    va_list args;
    va_start(args, format);
    ImGui::TextWrappedV(format, args);
    va_end(args);
    ImGui::PopStyleColor();
}

std::string idName(const char* name) {  // "x offset" -> "x-offset"
    std::string s(name);
    std::replace(s.begin(), s.end(), ' ', '-');
    return s;
}

}  // namespace

void Ui::record(const std::string& id) {
    const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
    rects_[id] = {{a.x, a.y}, {b.x, b.y}};
}

std::optional<WidgetRect> Ui::rect(const std::string& id) const {
    auto it = rects_.find(id);
    if (it == rects_.end()) return std::nullopt;
    return it->second;
}

void Ui::draw(AppState& state, const UiTextures& textures) {
    rects_.clear();
    sceneDrawList_ = nullptr;
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const Layout layout = computeLayout({display.x, display.y});
    referencePane(state, layout.reference, textures.reference);
    userPane(state, layout.user, textures.user);
    scenePane(state, layout.scene3d, textures.scene3d);
    parameterPane(state, layout.parameters);
    comparePane(state, layout.compare, textures.compare);
    matchPane(state, layout.match);
    if (state.showHelp) helpWindow(state);
}

void Ui::referencePane(AppState& state, const Pane& pane, unsigned texture) {
    beginPane("Reference image", pane);
    squareImage(texture, ImGui::GetTextLineHeightWithSpacing());
    record("image:reference");
    if (state.referenceRevealed) {
        poseLine(state.referencePose);
    } else {
        ImGui::TextColored(kDim, "Parameters hidden: match this image.");
    }
    ImGui::End();
}

void Ui::userPane(AppState& state, const Pane& pane, unsigned texture) {
    beginPane("Your DRR", pane);
    squareImage(texture, ImGui::GetTextLineHeightWithSpacing());
    record("image:user");
    if (state.solve.running) {  // the image follows the computer's best pose meanwhile
        ImGui::TextColored(kWarn, "solving:");
        ImGui::SameLine();
        poseLine(state.solve.bestPose);
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
    ImGui::InvisibleButton("##scene3d", size);
    record("view:3d");
    const bool hovered = ImGui::IsItemHovered();
    if (ImGui::IsItemActive() && ImGui::IsMouseDragging(ImGuiMouseButton_Left, 0.0f)) {
        const ImVec2 delta = ImGui::GetIO().MouseDelta;
        state.view.azimuthDeg = std::remainder(state.view.azimuthDeg - delta.x * 0.4f, 360.0f);
        state.view.elevationDeg =
            std::clamp(state.view.elevationDeg + delta.y * 0.4f, -89.0f, 89.0f);
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
        ImGui::SetTooltip(
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
    const auto specs = parameterSpecs(state.translationRangeMm);
    const float labelWidth = ImGui::CalcTextSize("elevation ").x;
    const float inputWidth =
        ImGui::CalcTextSize("-0000.00").x + 2 * ImGui::GetStyle().FramePadding.x;
    const float unitWidth = ImGui::CalcTextSize("deg").x;
    const float spacing = ImGui::GetStyle().ItemSpacing.x;
    const float sliderWidth = std::max(40.0f, ImGui::GetContentRegionAvail().x - labelWidth -
                                                  inputWidth - unitWidth - 3 * spacing);
    for (int p = 0; p < kParameterCount; ++p) {
        const ParameterSpec& spec = specs[p];
        const std::string id = idName(spec.name);
        double& value = poseValue(state.userPose, p);
        const double before = value;
        ImGui::PushID(p);
        ImGui::AlignTextToFramePadding();
        ImGui::TextUnformatted(spec.name);
        ImGui::SameLine(labelWidth + ImGui::GetStyle().WindowPadding.x);
        // Slider and number field edit the same value, so each follows the other (as in 2011).
        ImGui::SetNextItemWidth(sliderWidth);
        ImGui::SliderScalar("##slider", ImGuiDataType_Double, &value, &spec.min, &spec.max, "%.1f");
        if (ImGui::IsItemActive()) state.interacting = true;
        record("slider:" + id);
        ImGui::SameLine();
        ImGui::SetNextItemWidth(inputWidth);
        ImGui::InputDouble("##input", &value, 0.0, 0.0, "%.2f", ImGuiInputTextFlags_AutoSelectAll);
        record("input:" + id);
        ImGui::SameLine();
        ImGui::TextUnformatted(spec.unit);
        ImGui::PopID();
        if (!std::isfinite(value)) value = before;
        value = std::clamp(value, spec.min, spec.max);
        if (value != before) state.matchIsStale = true;
    }
    if (ImGui::Button("Centre pose")) {
        state.userPose = Pose{};
        state.matchIsStale = true;
    }
    record("button:centre-pose");

    ImGui::Separator();
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted("CT");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(std::max(60.0f, ImGui::GetContentRegionAvail().x -
                                                ImGui::CalcTextSize("Open Knee").x - 5 * spacing));
    const bool enter =
        ImGui::InputTextWithHint("##volume", "file, DICOM folder or phantom:NAME",
                                 &state.volumePathField, ImGuiInputTextFlags_EnterReturnsTrue);
    record("input:volume");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "Type a path and press Enter, or drop a CT file or folder onto the window");
    ImGui::SameLine();
    if ((ImGui::Button("Open") || enter) && !state.volumePathField.empty())
        state.requests.loadVolume = state.volumePathField;
    record("button:open");
    ImGui::SameLine();
    if (ImGui::Button("Knee")) state.requests.loadVolume = std::string("phantom:knee");
    record("button:knee");

    const LoadStatus& load = state.load;
    if (load.loading) {
        char overlay[160];
        std::snprintf(overlay, sizeof(overlay), "%s (%.1f s)", load.stage.c_str(),
                      load.elapsedSeconds);
        ImGui::ProgressBar(load.progress, ImVec2(-1.0f, 0.0f), overlay);
        ImGui::TextColored(kDim, "Loading %s ...", load.requestedSpec.c_str());
    } else {
        ImGui::TextColored(kDim, "%s",
                           load.loadedSpec.empty() ? "No CT loaded" : load.loadedSpec.c_str());
        ImGui::TextColored(kDim, "%s", load.summary.c_str());
        if (!load.loadedSpec.empty())
            ImGui::TextColored(kDim, "%zu bone triangles (iso %.4g)", state.bone.triangles,
                               state.bone.shownLevel);
    }
    if (!load.error.empty()) ImGui::TextColored(kBad, "%s", load.error.c_str());
    ImGui::End();
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
    if (texture)
        ImGui::Image(toImTexture(texture), ImVec2(side, side));
    else
        ImGui::Dummy(ImVec2(side, side));
    record("image:compare");
    ImGui::SameLine();
    ImGui::BeginGroup();
    const char* legend = state.display.compare == CompareMode::Difference
                             ? "red: yours denser\nblue: reference denser"
                         : state.display.compare == CompareMode::Overlay
                             ? "magenta: reference\ngreen: yours"
                             : "tiles alternate\nreference / yours";
    ImGui::TextColored(kDim, "%s", legend);
    ImGui::Checkbox("Auto window", &state.display.autoWindow);
    record("checkbox:auto-window");
    ImGui::SetNextItemWidth(controlsWidth - ImGui::CalcTextSize("Window").x - 8.0f);
    const float range = std::max(state.display.window, state.display.level) * 2.0f + 1e-6f;
    if (ImGui::SliderFloat("Window", &state.display.window, range * 1e-3f, range, "%.3g"))
        state.display.autoWindow = false;
    record("slider:window");
    ImGui::SetNextItemWidth(controlsWidth - ImGui::CalcTextSize("Window").x - 8.0f);
    if (ImGui::SliderFloat("Level", &state.display.level, -range * 0.5f, range, "%.3g"))
        state.display.autoWindow = false;
    record("slider:level");
    const Timings& t = state.timings;
    ImGui::Spacing();
    if (!state.showTimings) {
        ImGui::EndGroup();
        ImGui::End();
        return;
    }
    ImGui::TextColored(kDim, "user DRR %.1f ms %s", t.userDrrMs,
                       t.userDrrCoarse ? "(coarse)" : "(exact)");
    ImGui::TextColored(kDim, "exact %.1f ms\ncoarse/%d %.1f ms", t.lastExactMs, t.coarseFactor,
                       t.lastCoarseMs);
    ImGui::TextColored(kDim, "frame %.1f ms", t.frameMs);
    ImGui::EndGroup();
    ImGui::End();
}

void Ui::matchPane(AppState& state, const Pane& pane) {
    beginPane("Match", pane);
    // Two tabs: the pane is too short for the verdict table and the solve result together.
    if (ImGui::BeginTabBar("##match-tabs")) {
        const bool mine = ImGui::BeginTabItem("Your match");
        record("tab:match");
        if (mine) {
            matchTab(state);
            ImGui::EndTabItem();
        }
        const bool computer = ImGui::BeginTabItem("Solve");
        record("tab:solve");
        if (computer) {
            solveSection(state);
            ImGui::EndTabItem();
        }
        ImGui::EndTabBar();
    }
    ImGui::End();
}

void Ui::matchTab(AppState& state) {
    if (ImGui::Button("New reference image")) state.requests.newReference = true;
    record("button:new-reference");
    ImGui::SameLine();
    if (ImGui::Button("Match")) state.requests.match = true;
    record("button:match");
    ImGui::SameLine();
    if (ImGui::Button("Help")) state.showHelp = !state.showHelp;
    record("button:help");
    ImGui::SameLine();
    ImGui::TextColored(kDim, "attempts: %d", state.attempts);

    bool reveal = state.referenceRevealed;
    if (ImGui::Checkbox("Reveal the reference parameters", &reveal)) {
        if (reveal)
            state.requests.reveal = true;
        else
            state.referenceRevealed = false;
    }
    record("checkbox:reveal");

    if (!state.match) {
        ImGui::TextWrapped(
            "Move the six parameters until your DRR matches the reference, then "
            "press Match.");
        dimWrapped(
            "A match: every offset within %.3g mm, every angle within %.3g deg, and NCC "
            "of the images at least %.3g.",
            state.toleranceOffsetMm, state.toleranceAngleDeg, state.toleranceMinNcc);
    } else {
        const MatchOutcome& m = *state.match;
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextColored(m.matched ? kGood : kWarn, "%s", m.verdict.c_str());
        ImGui::PopTextWrapPos();
        ImGui::Text("pose error (mTRE) %.2f mm   NCC %.4f%s", m.poseErrorMm, m.ncc,
                    state.matchIsStale ? "   (pose moved since)" : "");
        const auto specs = parameterSpecs(state.translationRangeMm);
        const int columns = state.referenceRevealed ? 4 : 3;
        if (ImGui::BeginTable("hints", columns,
                              ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV)) {
            // Explicit weights: content-based widths would need an extra frame to settle.
            ImGui::TableSetupColumn("parameter", ImGuiTableColumnFlags_WidthStretch, 2.0f);
            ImGui::TableSetupColumn("error", ImGuiTableColumnFlags_WidthStretch, 1.2f);
            ImGui::TableSetupColumn("hint", ImGuiTableColumnFlags_WidthStretch, 1.0f);
            if (state.referenceRevealed)
                ImGui::TableSetupColumn("reference", ImGuiTableColumnFlags_WidthStretch, 1.0f);
            ImGui::TableHeadersRow();
            const auto reference = state.referencePose.toArray();
            for (int p = 0; p < kParameterCount; ++p) {
                ImGui::TableNextRow();
                ImGui::TableNextColumn();
                if (p == m.furthestParameter)
                    ImGui::TextColored(kWarn, "%s (furthest)", specs[p].name);
                else
                    ImGui::TextUnformatted(specs[p].name);
                ImGui::TableNextColumn();
                ImGui::Text("%+.1f %s", m.error[p], specs[p].unit);
                ImGui::TableNextColumn();
                if (m.direction[p] > 0)
                    ImGui::TextColored(kWarn, "too high");
                else if (m.direction[p] < 0)
                    ImGui::TextColored(kWarn, "too low");
                else
                    ImGui::TextColored(kGood, "ok");
                if (state.referenceRevealed) {
                    ImGui::TableNextColumn();
                    ImGui::Text("%.1f", reference[p]);
                }
            }
            ImGui::EndTable();
        }
    }
}

void Ui::solveSection(AppState& state) {
    SolveStatus& solve = state.solve;
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted("Computer:");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(ImGui::CalcTextSize("Particle swarm").x + ImGui::GetFrameHeight() +
                            2 * ImGui::GetStyle().FramePadding.x);
    if (solve.running) ImGui::BeginDisabled();
    ImGui::Combo("##method", &solve.method, kSolveMethodLabels, kSolveMethodCount);
    if (solve.running) ImGui::EndDisabled();
    record("combo:solve-method");
    ImGui::SameLine();
    if (solve.running) {
        if (ImGui::Button("Stop")) state.requests.stopSolve = true;
        record("button:stop-solve");
    } else {
        if (ImGui::Button("Solve")) state.requests.solve = true;
        record("button:solve");
    }
    if (!solve.error.empty()) ImGui::TextColored(kBad, "%s", solve.error.c_str());
    if (!solve.running && !solve.finished) {
        dimWrapped("Solve: the automatic search from your pose, to compare with your attempts.");
        return;
    }

    char overlay[160];
    std::snprintf(overlay, sizeof(overlay), "level %d/%d %s  %d/%d", solve.level + 1,
                  std::max(1, solve.levelCount), solve.stage.c_str(), solve.evaluations,
                  solve.budget);
    const float fraction =
        solve.budget > 0 ? std::min(1.0f, float(solve.evaluations) / float(solve.budget)) : 0.0f;
    ImGui::ProgressBar(solve.finished && !solve.stopped ? 1.0f : fraction, ImVec2(-1.0f, 0.0f),
                       overlay);
    record("progress:solve");
    if (!solve.costHistory.empty()) {
        ImGui::PlotLines("##cost", solve.costHistory.data(), int(solve.costHistory.size()), 0,
                         "best cost (this level)", FLT_MAX, FLT_MAX,
                         // PlotLines (1.86) takes no negative "fill" width: give it outright.
                         ImVec2(ImGui::GetContentRegionAvail().x, 40.0f));
        record("plot:solve-cost");
    }
    if (solve.running) {
        ImGui::TextColored(kDim, "candidate");
        ImGui::SameLine();
        poseLine(solve.candidate);
        if (state.showTimings) ImGui::TextColored(kDim, "%.1f s", solve.elapsedMs / 1000.0);
        return;
    }

    // Finished: the computer's answer beside the user's attempts.
    ImGui::TextColored(solve.poseErrorMm < 1.0 ? kGood : kWarn, "computer mTRE %.2f mm%s",
                       solve.poseErrorMm, solve.stopped ? " (stopped)" : "");
    ImGui::SameLine();
    if (state.showTimings)
        ImGui::TextColored(kDim, "%d evals, %.1f s", solve.evaluations, solve.elapsedMs / 1000.0);
    else
        ImGui::TextColored(kDim, "%d evals", solve.evaluations);
    poseLine(solve.bestPose);
    ImGui::TextColored(kDim, "error %+.1f %+.1f %+.1f mm | %+.1f %+.1f %+.1f deg", solve.error6[0],
                       solve.error6[1], solve.error6[2], solve.error6[3], solve.error6[4],
                       solve.error6[5]);
    if (state.bestUserPoseErrorMm)
        ImGui::Text("you: %d attempt%s, best mTRE %.2f mm", state.attempts,
                    state.attempts == 1 ? "" : "s", *state.bestUserPoseErrorMm);
    else
        ImGui::Text("you: no attempt yet");
    if (ImGui::Button(solve.applied ? "Applied" : "Apply solution"))
        state.requests.applySolution = true;
    record("button:apply-solution");
}

void Ui::helpWindow(AppState& state) {
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    // Centred, as wide as fits, as tall as its text (auto-resize), opaque.
    const float width = std::min(620.0f, display.x - 40.0f);
    ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.5f), ImGuiCond_Always,
                            ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSize(ImVec2(width, 0.0f), ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(1.0f);
    if (ImGui::Begin("Help", &state.showHelp,
                     ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse |
                         ImGuiWindowFlags_NoMove)) {
        ImGui::TextWrapped(
            "The task: the left image is a radiograph (DRR) of the CT taken from a hidden pose. "
            "Find that pose: move the six parameters until your DRR (middle) matches it, then "
            "press Match.");
        ImGui::Spacing();
        ImGui::TextUnformatted("The six parameters:");
        bulletWrapped(
            "x, y, z offset (mm): where the CT's centre sits relative to the "
            "isocenter, the point between source and film.");
        bulletWrapped(
            "azimuth (-180..180 deg) and elevation (-90..90 deg): where the X-ray "
            "source stands on its sphere around the isocenter.");
        bulletWrapped("rotation (-90..90 deg): the film's turn in its own plane.");
        ImGui::Spacing();
        ImGui::TextUnformatted("Controls:");
        bulletWrapped("Drag a slider, or type a number in the field beside it.");
        bulletWrapped(
            "Match: compares your pose with the hidden one; within tolerance the "
            "images match, otherwise each parameter gets a hint (too high / too "
            "low) and the one furthest off is named. Attempts are counted.");
        bulletWrapped(
            "A match needs every offset within %.3g mm and every angle within "
            "%.3g deg of the hidden pose, and the images to correlate (NCC >= %.3g).",
            state.toleranceOffsetMm, state.toleranceAngleDeg, state.toleranceMinNcc);
        bulletWrapped("New reference image: another hidden pose. Reveal shows its values.");
        bulletWrapped(
            "Solve: the computer searches from your pose with the chosen method (live: its "
            "best pose in your DRR, a cost curve; Stop keeps its best so far), then shows its "
            "error and time beside your attempts. Apply solution puts its pose on the sliders.");
        bulletWrapped(
            "Compare: difference, overlay or checkerboard of the two images, with "
            "window and level.");
        bulletWrapped("3D view: drag to orbit, mouse wheel to zoom, Reset view.");
        bulletWrapped(
            "Open another CT: type a path (file, DICOM folder or phantom:NAME) or "
            "drop it onto the window.");
        if (ImGui::Button("Close")) state.showHelp = false;
        record("button:close-help");
    }
    ImGui::End();
}

}  // namespace fm::app

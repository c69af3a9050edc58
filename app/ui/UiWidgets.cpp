#include "ui/UiWidgets.h"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>

namespace fm::app::widgets {

bool beginPane(const char* title, const Pane& pane) {
    ImGui::SetNextWindowPos(ImVec2(pane.pos.x, pane.pos.y), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(pane.size.x, pane.size.y), ImGuiCond_Always);
    return ImGui::Begin(title, nullptr, kPaneFlags);
}

std::string poseText(const Pose& pose, bool compact) {
    char text[160];
    std::snprintf(text, sizeof(text),
                  compact ? "%.1f,%.1f,%.1f mm|%.1f,%.1f,%.1f deg"
                          : "%.1f, %.1f, %.1f mm | %.1f, %.1f, %.1f deg",
                  pose.offset.x, pose.offset.y, pose.offset.z, pose.azimuthDeg, pose.elevationDeg,
                  pose.rotationDeg);
    return text;
}

std::array<ParameterSpec, kParameterCount> sliderSpecs(const AppState& state) {
    const int target = state.bones.sliderTarget;
    if (target >= 0 && target < int(state.bones.list.size())) return boneMotionSpecs();
    return parameterSpecs(state.translationRangeMm);
}

double& sliderValue(AppState& state, int parameter) {
    const int target = state.bones.sliderTarget;
    if (target >= 0 && target < int(state.bones.list.size()))
        return state.bones.list[target].motion[parameter];
    return poseValue(state.userPose, parameter);
}

void stageProgressBar(float fraction, const std::string& stage, double elapsedSeconds) {
    char overlay[200];
    std::snprintf(overlay, sizeof(overlay), "%s (%.1f s)", stage.c_str(), elapsedSeconds);
    ImGui::ProgressBar(fraction, ImVec2(-1.0f, 0.0f), overlay);
}

void difficultyCombo(const char* id, Difficulty& difficulty) {
    static const char* kDifficulties[] = {"easy", "medium", "hard"};
    int index = static_cast<int>(difficulty);
    ImGui::SetNextItemWidth(ImGui::CalcTextSize("medium").x + ImGui::GetFrameHeight() +
                            2 * ImGui::GetStyle().FramePadding.x);
    if (ImGui::Combo(id, &index, kDifficulties, kDifficultyCount))
        difficulty = static_cast<Difficulty>(index);
}

double& poseValue(Pose& pose, int parameter) {
    switch (parameter) {
        case 0:
            return pose.offset.x;
        case 1:
            return pose.offset.y;
        case 2:
            return pose.offset.z;
        case 3:
            return pose.azimuthDeg;
        case 4:
            return pose.elevationDeg;
        default:
            return pose.rotationDeg;
    }
}

void bulletWrapped(const char* format, ...) {
    ImGui::Bullet();
    va_list args;
    va_start(args, format);
    ImGui::TextWrappedV(format, args);
    va_end(args);
}

void dimWrapped(const char* format, ...) {
    ImGui::PushStyleColor(ImGuiCol_Text, kDim);
    va_list args;
    va_start(args, format);
    ImGui::TextWrappedV(format, args);
    va_end(args);
    ImGui::PopStyleColor();
}

void coloredWrapped(const ImVec4& color, const std::string& text) {
    ImGui::PushStyleColor(ImGuiCol_Text, color);
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextUnformatted(text.c_str());
    ImGui::PopTextWrapPos();
    ImGui::PopStyleColor();
}

bool elidedText(const ImVec4& color, const std::string& text) {
    const float avail = ImGui::GetContentRegionAvail().x;
    if (ImGui::CalcTextSize(text.c_str()).x <= avail) {
        ImGui::TextColored(color, "%s", text.c_str());
        return false;
    }
    // Keep the end (a path's file name, an error's cause) and cut the start.
    std::size_t cut = 0;
    const float dots = ImGui::CalcTextSize("...").x;
    while (cut < text.size() && ImGui::CalcTextSize(text.c_str() + cut).x + dots > avail) ++cut;
    ImGui::TextColored(color, "...%s", text.c_str() + cut);
    return true;
}

double nudgedValue(double value, int direction, bool fine, double min, double max) {
    const double step = fine ? 0.1 : 1.0;
    return std::clamp(std::round((value + direction * step) * 10.0) / 10.0, min, max);
}

ParameterRowWidths parameterRowWidths() {
    ParameterRowWidths w;
    w.label = ImGui::CalcTextSize("elevation ").x;
    w.input = ImGui::CalcTextSize("-0000.00").x + 2 * ImGui::GetStyle().FramePadding.x;
    const float unitWidth = ImGui::CalcTextSize("deg").x;
    const float spacing = ImGui::GetStyle().ItemSpacing.x;
    w.slider = std::max(40.0f, ImGui::GetContentRegionAvail().x - w.label - w.input - unitWidth - 3 * spacing);
    return w;
}

ParameterRowResult parameterRow(const ParameterSpec& spec, double& value, bool selected,
                                const ParameterRowWidths& widths,
                                const std::function<void(const std::string&)>& record) {
    ParameterRowResult r;
    const std::string id = idName(spec.name);
    const double before = value;
    ImGui::AlignTextToFramePadding();
    // The parameter the arrow keys nudge is highlighted.
    if (selected)
        ImGui::TextColored(kSelected, "%s", spec.name);
    else
        ImGui::TextUnformatted(spec.name);
    record("label:" + id);
    r.labelHovered = ImGui::IsItemHovered();
    ImGui::SameLine(widths.label + ImGui::GetStyle().WindowPadding.x);
    // Slider and number field edit the same value, so each follows the other (as in 2011).
    ImGui::SetNextItemWidth(widths.slider);
    // No text on the slider (the grab would cover it; the number field beside shows the
    // value), and no rounding by ImGui's format: the value is kept to 0.1 mm / deg here.
    if (ImGui::SliderScalar("##slider", ImGuiDataType_Double, &value, &spec.min, &spec.max, ""))
        value = std::round(value * 10.0) / 10.0;
    if (ImGui::IsItemActive()) {
        r.sliderActive = true;
        r.selected = true;
    }
    // The wheel over a slider nudges it as the arrow keys do (1 mm / 1 deg, Shift 0.1): a
    // slider pixel spans more than a millimetre of the knee's 300 mm range.
    const ImGuiIO& io = ImGui::GetIO();
    if (ImGui::IsItemHovered() && io.MouseWheel != 0.0f) {
        value = nudgedValue(value, io.MouseWheel > 0.0f ? 1 : -1, io.KeyShift, spec.min, spec.max);
        r.selected = true;
    }
    record("slider:" + id);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(widths.input);
    ImGui::InputDouble("##input", &value, 0.0, 0.0, "%.2f", ImGuiInputTextFlags_AutoSelectAll);
    record("input:" + id);
    if (ImGui::IsItemActive()) r.selected = true;
    ImGui::SameLine();
    ImGui::TextUnformatted(spec.unit);
    if (!std::isfinite(value)) value = before;
    value = std::clamp(value, spec.min, spec.max);
    return r;
}

std::string idName(const char* name) {
    std::string s(name);
    std::replace(s.begin(), s.end(), ' ', '-');
    return s;
}

}  // namespace fm::app::widgets

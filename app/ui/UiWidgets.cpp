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

std::string idName(const char* name) {
    std::string s(name);
    std::replace(s.begin(), s.end(), ' ', '-');
    return s;
}

}  // namespace fm::app::widgets

#pragma once
// Small ImGui helpers shared by the panes (app/ui/*Pane.cpp, *Panel.cpp): colours, fixed pane
// windows, wrapping text, the pose line. Only ImGui calls; no state of their own.
#include <imgui.h>

#include <cstdint>
#include <functional>
#include <string>

#include "geometry/Pose.h"
#include "state/AppState.h"
#include "ui/Layout.h"

namespace fm::app::widgets {

inline constexpr ImGuiWindowFlags kPaneFlags =
    ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
    ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBringToFrontOnFocus;
inline const ImVec4 kGood{0.45f, 0.90f, 0.45f, 1.0f};
inline const ImVec4 kWarn{1.00f, 0.70f, 0.30f, 1.0f};
inline const ImVec4 kBad{1.00f, 0.40f, 0.40f, 1.0f};
inline const ImVec4 kDim{0.65f, 0.65f, 0.70f, 1.0f};
inline const ImVec4 kSelected{0.40f, 0.75f, 1.00f, 1.0f};

inline ImTextureID toImTexture(unsigned id) {
    return reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(id));
}

// A fixed window at the pane's rectangle.
bool beginPane(const char* title, const Pane& pane);
// "x, y, z mm | az, el, rot deg"; `compact` drops the spaces (Ui::poseLine picks what fits).
std::string poseText(const Pose& pose, bool compact = false);
// The parameter (Pose::toArray() order) as a reference into the pose.
double& poseValue(Pose& pose, int parameter);
// The six slider rows: the camera's parameters, or the motion of the bone they target.
std::array<ParameterSpec, kParameterCount> sliderSpecs(const AppState& state);
// The value slider `parameter` edits: the user's pose, or the target bone's motion.
double& sliderValue(AppState& state, int parameter);
// The easy / medium / hard combo, just wide enough for "medium".
void difficultyCombo(const char* id, Difficulty& difficulty);
// `value` nudged `direction` (+1 / -1) steps of 1 mm or 1 deg (`fine`: 0.1), on the 0.1 grid
// (nudges add up exactly as shown) and clamped to [min, max]: the arrow keys and the wheel.
double nudgedValue(double value, int direction, bool fine, double min, double max);
// The widths of a parameter row (label, slider, number field), fitted to the window.
struct ParameterRowWidths {
    float label = 0, slider = 0, input = 0;
};
ParameterRowWidths parameterRowWidths();
struct ParameterRowResult {
    bool labelHovered = false;
    bool sliderActive = false;  // held: the caller previews coarsely
    bool selected = false;      // clicked, wheeled or edited: the arrow keys' parameter now
};
// One parameter row: its name (highlighted when `selected`), a slider without text (kept to
// 0.1; the wheel over it nudges as the arrow keys do), the number field and the unit, all
// editing `value` (clamped to the spec, a non-finite entry refused). `record(id)` is called
// after each item with "label:NAME", "slider:NAME", "input:NAME".
ParameterRowResult parameterRow(const ParameterSpec& spec, double& value, bool selected,
                                const ParameterRowWidths& widths,
                                const std::function<void(const std::string&)>& record);
// A bullet whose text wraps at the window edge (BulletText does not wrap).
void bulletWrapped(const char* format, ...) IM_FMTARGS(1);
// Dimmed text that wraps.
void dimWrapped(const char* format, ...) IM_FMTARGS(1);
// Coloured text that wraps.
void coloredWrapped(const ImVec4& color, const std::string& text);
// One line of text cut to the available width with "..." (the start goes: a path's file name,
// an error's cause stay). True when it was cut: the caller shows the whole text in a tooltip
// (Ui::elidedLine).
bool elidedText(const ImVec4& color, const std::string& text);
// A full-width progress bar of a background job: "stage (1.2 s)" over it.
void stageProgressBar(float fraction, const std::string& stage, double elapsedSeconds);
// "x offset" -> "x-offset" (widget ids for tests).
std::string idName(const char* name);

}  // namespace fm::app::widgets

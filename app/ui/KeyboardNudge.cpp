// The keyboard, when no text field has it: Up/Down select a parameter (or a click on its
// slider or field), Left/Right
// nudge it by one step (1 mm / 1 deg; with Shift 0.1), Enter presses Match, Escape closes Help.
#include <imgui.h>

#include <algorithm>
#include <cmath>

#include "ui/Ui.h"
#include "ui/UiWidgets.h"

namespace fm::app {

namespace {
bool pressed(ImGuiKey key) {
    return ImGui::IsKeyPressed(ImGui::GetKeyIndex(key), true);
}
}  // namespace

void Ui::keyboard(AppState& state) {
    const ImGuiIO& io = ImGui::GetIO();
    if (pressed(ImGuiKey_Escape) && (state.showHelp || state.compareEnlarged)) {
        if (state.showHelp)
            state.showHelp = false;
        else
            state.compareEnlarged = false;
        return;
    }
    if (io.WantTextInput) return;  // typing a number or a path: the keys are the field's
    if (pressed(ImGuiKey_Enter) || pressed(ImGuiKey_KeyPadEnter)) state.requests.match = true;
    int& selected = state.selectedParameter;
    if (pressed(ImGuiKey_UpArrow)) selected = (selected + kParameterCount - 1) % kParameterCount;
    if (pressed(ImGuiKey_DownArrow)) selected = (selected + 1) % kParameterCount;
    const int direction = (pressed(ImGuiKey_RightArrow) ? 1 : 0) -
                          (pressed(ImGuiKey_LeftArrow) ? 1 : 0);
    if (direction == 0) return;
    const auto specs = widgets::sliderSpecs(state);
    double& value = widgets::sliderValue(state, selected);
    const double clamped = widgets::nudgedValue(value, direction, io.KeyShift,
                                                specs[selected].min, specs[selected].max);
    if (clamped != value) {
        value = clamped;
        state.matchIsStale = true;
    }
}

}  // namespace fm::app

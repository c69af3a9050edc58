// The imaging mode switch beside "Centre pose": X-ray images (DRRs) or MRI slices
// (docs/mri.md). Chosen automatically when a volume loads (an MRI file: slices); the user may
// switch at any time, which draws a new reference of that kind.
#include <imgui.h>

#include "ui/Ui.h"

namespace fm::app {

void Ui::modeSwitch(AppState& state) {
    int mode = state.mode == ImagingMode::Slice ? 1 : 0;
    const int before = mode;
    // Beside the buttons before it when both radios fit, else on a line of their own.
    const ImGuiStyle& style = ImGui::GetStyle();
    const float radios = 2.0f * (ImGui::GetFrameHeight() + style.ItemInnerSpacing.x) +
                         ImGui::CalcTextSize("X-ray").x + ImGui::CalcTextSize("MRI").x +
                         style.ItemSpacing.x;
    ImGui::SameLine();
    if (ImGui::GetContentRegionAvail().x < radios) ImGui::NewLine();
    ImGui::RadioButton("X-ray", &mode, 0);
    record("radio:mode-xray");
    if (ImGui::IsItemHovered()) tooltip("Radiographs (DRRs) of the volume");
    ImGui::SameLine();
    ImGui::RadioButton("MRI", &mode, 1);
    record("radio:mode-slice");
    if (ImGui::IsItemHovered())
        tooltip(
            "MRI slice mode: planar slices of the volume; the same six parameters place the plane");
    if (mode != before) state.requests.mode = mode == 1 ? ImagingMode::Slice : ImagingMode::Xray;
}

}  // namespace fm::app

// The Bones tab's source of bones: a label map (path and optional label table, as the CT's path
// field) or the CT's connected components; progress while they are built, the reason when they
// cannot be (the scene is then as it was).
#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>

#include "scene/LabelledBones.h"
#include "ui/Ui.h"
#include "ui/UiWidgets.h"

namespace fm::app {

using namespace widgets;

void Ui::labelsSection(AppState& state) {
    LabelsLoad& labels = state.labels;
    // Fields as wide as the row leaves beside the label and the wider button.
    const ImGuiStyle& style = ImGui::GetStyle();
    const float fieldWidth =
        std::max(60.0f, ImGui::GetContentRegionAvail().x - ImGui::CalcTextSize("table ").x -
                            ImGui::CalcTextSize("Components").x - 2 * style.FramePadding.x -
                            2 * style.ItemSpacing.x);
    ImGui::BeginDisabled(labels.loading);
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted("labels");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(fieldWidth);
    const bool enter = ImGui::InputTextWithHint("##labels", "label map on the CT's grid",
                                                &labels.pathField,
                                                ImGuiInputTextFlags_EnterReturnsTrue);
    record("input:labels");
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        tooltip("A label map (any volume file: one whole number per voxel, 0 = none) on the CT's "
                "grid, or resampled onto it by nearest neighbour; Enter or Open");
    ImGui::SameLine();
    if (ImGui::Button("Open##labels") || enter)
        state.requests.loadLabels = {labels.pathField, labels.tableField};
    record("button:open-labels");
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted("table ");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(fieldWidth);
    ImGui::InputTextWithHint("##label-table", "optional: JSON or CSV names", &labels.tableField);
    record("input:label-table");
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        tooltip("Names of the labels to show as bones: {\"femur_right\": 76, ...} or lines "
                "label,name. Without it every label is a bone, named by its number");
    ImGui::SameLine();
    if (ImGui::Button("Components")) state.requests.components = true;
    record("button:components");
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        tooltip("Bones without a label map: voxels at or above the surface level (%.0f) split "
                "into connected pieces, the %d largest of %zu voxels or more",
                state.bone.shownLevel, kMaxComponentBones, kMinComponentVoxels);
    ImGui::EndDisabled();
    if (labels.loading) {
        stageProgressBar(labels.progress, labels.stage, labels.elapsedSeconds);
        record("progress:labels");
    } else if (!labels.loaded.empty()) {
        elidedLine("text:labels-loaded", kDim, "bones from " + labels.loaded);
    }
    if (!labels.error.empty()) {
        coloredWrapped(kBad, labels.error);
        record("text:labels-error");
    }
}

}  // namespace fm::app

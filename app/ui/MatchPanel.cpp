// The Match pane: the user's attempts (verdict and hints) and, in a second tab, the computer's
// (SolvePanel.cpp).
#include <imgui.h>

#include "ui/Ui.h"
#include "ui/UiWidgets.h"

namespace fm::app {

using namespace widgets;

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
        const bool bones = ImGui::BeginTabItem("Bones");
        record("tab:bones");
        if (bones) {
            bonesTab(state);
            ImGui::EndTabItem();
        }
        ImGui::EndTabBar();
    }
    ImGui::End();
}

void Ui::matchTab(AppState& state) {
    if (ImGui::Button("New reference")) state.requests.newReference = true;
    record("button:new-reference");
    if (ImGui::IsItemHovered())
        tooltip("Another hidden pose, drawn around a clinical view at the difficulty "
                          "beside");
    ImGui::SameLine();
    difficultyCombo("##difficulty", state.difficulty);
    record("combo:difficulty");
    if (ImGui::IsItemHovered())
        tooltip("Difficulty of the next reference: easy hides 2 parameters near a "
                          "clinical view, medium 4, hard all 6 and further off");
    ImGui::SameLine();
    if (ImGui::Button("Match")) state.requests.match = true;
    record("button:match");
    ImGui::SameLine();
    if (ImGui::Button("Help")) state.showHelp = !state.showHelp;
    record("button:help");

    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted("Hints:");
    ImGui::SameLine();
    int wording = static_cast<int>(state.hintWording);
    ImGui::RadioButton("direction", &wording, 0);
    record("radio:hints-direction");
    ImGui::SameLine();
    ImGui::RadioButton("bands", &wording, 1);
    record("radio:hints-bands");
    if (ImGui::IsItemHovered())
        tooltip("Also say how far: very close (within 3 tolerances), close (within "
                          "10), far");
    state.hintWording = static_cast<HintWording>(wording);
    ImGui::SameLine();
    bool reveal = state.referenceRevealed;
    if (ImGui::Checkbox("Reveal", &reveal)) {
        if (reveal)
            state.requests.reveal = true;
        else
            state.referenceRevealed = false;
    }
    record("checkbox:reveal");
    if (ImGui::IsItemHovered())
        tooltip("Show the hidden parameters and the exact errors");

    if (!state.match) {
        ImGui::TextWrapped("Move the six parameters until your %s matches the reference, then "
                           "press Match.",
                           state.mode == ImagingMode::Slice ? "slice" : "DRR");
        dimWrapped("A match: every offset within %.3g mm and every angle within %.3g deg of the "
                   "hidden pose.",
                   state.toleranceOffsetMm, state.toleranceAngleDeg);
        return;
    }
    const MatchOutcome& m = *state.match;
    coloredWrapped(m.assisted ? kDim : m.matched ? kGood : kWarn, m.verdict);
    record("text:match-verdict");
    const char* band = closenessName(m.judged.closeness);
    if (m.numbersShown)
        ImGui::Text("attempt %d: mTRE %.2f mm (%s)%s", m.attempt, m.poseErrorMm, band,
                    state.matchIsStale ? ", pose moved since" : "");
    else
        ImGui::Text("attempt %d: the pose as a whole is %s%s", m.attempt, band,
                    state.matchIsStale ? ", pose moved since" : "");
    if (ImGui::IsItemHovered())
        tooltip("Mean distance of the bone points between your pose and the hidden "
                          "one (mTRE): very close < 3 mm, close < 10 mm, far beyond");
    const auto specs = parameterSpecs(state.translationRangeMm);
    const int columns = state.referenceRevealed ? 3 : 2;
    if (ImGui::BeginTable("hints", columns,
                          ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV)) {
        // Explicit weights: content-based widths would need an extra frame to settle.
        ImGui::TableSetupColumn("parameter", ImGuiTableColumnFlags_WidthStretch, 1.6f);
        ImGui::TableSetupColumn("hint", ImGuiTableColumnFlags_WidthStretch, 2.0f);
        if (state.referenceRevealed)
            ImGui::TableSetupColumn("reference", ImGuiTableColumnFlags_WidthStretch, 0.9f);
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
            // Wrapped in its column: after Reveal a third column takes room, and a hint with
            // its numbers ("too high, close (+18.4 mm)") was cut off.
            ImGui::PushStyleColor(ImGuiCol_Text, m.direction[p] == 0 ? kGood : kWarn);
            ImGui::TextWrapped("%s", m.hintCells[p].c_str());
            ImGui::PopStyleColor();
            if (state.referenceRevealed) {
                ImGui::TableNextColumn();
                ImGui::Text("%.1f", reference[p]);
            }
        }
        ImGui::EndTable();
    }
}

}  // namespace fm::app

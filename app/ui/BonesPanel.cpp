// The Bones tab: the bone list (colour as in the 3D view, shown or hidden in both DRRs and the
// 3D view, which one the sliders move), the knee's Grood-Suntay angles live, and the bone game:
// the hidden reference moves one bone (the knee: flexes it, the tibia moved; other bones: the
// chosen one, the move game), the user moves that bone to find the motion.
#include <imgui.h>

#include <array>
#include <cmath>
#include <cstdio>

#include "bones/BoneMotionGame.h"
#include "bones/KneeMotionGame.h"
#include "ui/Ui.h"
#include "ui/UiWidgets.h"

namespace fm::app {

using namespace widgets;

void Ui::kneeAnglesLine(const AppState& state) {
    const BonesState& bones = state.bones;
    if (!bones.isKnee) return;
    if (!bones.anglesValid) {
        ImGui::TextColored(kWarn, "knee angles: none (not a knee pose)");
        return;
    }
    std::array<double, 6> a = bones.angles;  // kneeAngleArray order: 3 mm, then 3 deg
    for (double& v : a) v = std::abs(v) < 0.05 ? 0.0 : v;  // no "-0.0"
    ImGui::TextColored(kSelected, "flexion %.1f  varus %.1f  int.rot %.1f deg", a[3], a[4], a[5]);
    record("text:knee-angles");
    if (ImGui::IsItemHovered())
        tooltip("The knee's Grood-Suntay angles, tibia relative to femur "
                          "(docs/bones.md):\nflexion about the femur's x axis, varus about the "
                          "floating axis, internal rotation about the tibia's long axis");
    ImGui::TextColored(kDim, "shift %.1f  drawer %.1f  distr. %.1f mm", a[0], a[1], a[2]);
    if (ImGui::IsItemHovered())
        tooltip("Grood-Suntay translations of the tibia's origin in the femur's frame (mm):\n"
                "shift: medial (+) or lateral along the femur's medio-lateral axis (e1)\n"
                "drawer: anterior (+) or posterior along the floating axis (e2), as in the "
                "drawer test\n"
                "distr.: distraction, the tibia pulled away (+) from the femur along its long "
                "axis (e3); negative is compression");
    record("text:knee-translations");
}

void Ui::bonesTab(AppState& state) {
    BonesState& bones = state.bones;
    // Where bones come from: first while there are none, else after the list and the game.
    if (bones.list.empty()) {
        labelsSection(state);
        ImGui::Separator();
    }
    if (bones.canGrow) {
        // Bones of a CT without labels: grown from a click, one at a time.
        ImGui::Checkbox("Grow a bone: click it in your DRR", &bones.growArmed);
        record("checkbox:grow");
        if (ImGui::IsItemHovered())
            tooltip("The first voxel at or above the surface level (%.0f) on the ray "
                              "through the clicked pixel seeds it; it grows over the connected "
                              "voxels at or above that level, never into another bone",
                              state.bone.shownLevel);
        if (!bones.growMessage.empty()) dimWrapped("%s", bones.growMessage.c_str());
    }
    if (bones.list.empty()) {
        dimWrapped("This CT is one object until you open its label map, press Components or "
                   "grow a bone. The knee phantom (Knee) has its femur, tibia and patella as "
                   "bones of their own.");
        return;
    }
    int& target = bones.sliderTarget;
    // During a bone game the list folds under a header: the game's hints need the pane.
    bool listShown = true;
    if (bones.flex.active) {
        ImGui::SetNextItemOpen(bones.listUnfolded, ImGuiCond_Always);
        listShown = bones.listUnfolded = ImGui::CollapsingHeader("bones (show, hide, move)");
        record("header:bone-list");
    }
    if (listShown && ImGui::BeginTable("bones", 3, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV)) {
        ImGui::TableSetupColumn("bone", ImGuiTableColumnFlags_WidthStretch, 2.0f);
        ImGui::TableSetupColumn("sliders", ImGuiTableColumnFlags_WidthStretch, 1.0f);
        ImGui::TableSetupColumn("view", ImGuiTableColumnFlags_WidthStretch, 1.2f);
        ImGui::TableHeadersRow();
        for (int i = 0; i < int(bones.list.size()); ++i) {
            BoneView& b = bones.list[i];
            ImGui::PushID(i);
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::ColorButton("##colour", ImVec4(b.color[0], b.color[1], b.color[2], 1.0f),
                               ImGuiColorEditFlags_NoTooltip | ImGuiColorEditFlags_NoPicker);
            record("swatch:" + b.name);
            ImGui::SameLine();
            ImGui::Checkbox(b.name.c_str(), &b.visible);
            record("checkbox:bone-" + b.name);
            ImGui::TableNextColumn();
            if (ImGui::RadioButton("moves", target == i)) target = i;
            record("radio:moves-" + b.name);
            ImGui::TableNextColumn();
            if (ImGui::SmallButton("only")) {
                for (BoneView& other : bones.list) other.visible = &other == &b;
                bones.restVisible = false;
            }
            record("button:only-" + b.name);
            if (ImGui::IsItemHovered())
                tooltip("Show %s alone (no soft tissue)", b.name.c_str());
            ImGui::PopID();
        }
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::Checkbox("soft tissue", &bones.restVisible);
        record("checkbox:bone-rest");
        ImGui::TableNextColumn();
        if (ImGui::RadioButton("camera", target < 0)) target = -1;
        record("radio:moves-camera");
        ImGui::TableNextColumn();
        if (ImGui::SmallButton("all")) {
            for (BoneView& b : bones.list) b.visible = true;
            bones.restVisible = true;
        }
        record("button:show-all");
        ImGui::EndTable();
    }
    kneeAnglesLine(state);
    boneGame(state);
    ImGui::Separator();
    labelsSection(state);
}

void Ui::boneGame(AppState& state) {
    BonesState& bones = state.bones;
    const bool knee = bones.isKnee;
    ImGui::Separator();
    FlexGame& flex = bones.flex;
    const char* start = knee ? (flex.active ? "New flexion" : "Flex game")
                             : (flex.active ? "New motion" : "Move game");
    if (ImGui::Button(start)) state.requests.newFlex = true;
    record("button:new-flex");
    if (ImGui::IsItemHovered()) {
        if (knee)
            tooltip("The reference knee is flexed by a hidden motion of the tibia: move the "
                    "tibia to find it");
        else
            tooltip("The reference moves the bone the sliders move (else the first) by a hidden "
                    "motion: move it to find that motion");
    }
    ImGui::SameLine();
    difficultyCombo("##flex-difficulty", flex.difficulty);
    record("combo:flex-difficulty");
    if (ImGui::IsItemHovered()) {
        if (knee)
            tooltip("easy: flexion only; medium: also varus and rotation; hard: also "
                    "shifts, and deeper flexion");
        else
            tooltip("shifts and turns up to %.0f mm / deg (easy), %.0f (medium), %.0f (hard)",
                    boneMotionSpread(Difficulty::Easy), boneMotionSpread(Difficulty::Medium),
                    boneMotionSpread(Difficulty::Hard));
    }
    if (!flex.active || flex.bone < 0 || flex.bone >= int(bones.list.size())) return;
    const std::string& bone = bones.list[flex.bone].name;
    ImGui::SameLine();
    if (ImGui::Button("Check")) state.requests.checkFlex = true;
    record("button:check-flex");
    ImGui::SameLine();
    ImGui::Checkbox("Reveal##flex", &flex.revealed);
    record("checkbox:reveal-flex");
    ImGui::SameLine();
    if (ImGui::Button("End")) state.requests.endFlex = true;
    record("button:end-flex");

    if (!flex.outcome) {
        if (knee)
            dimWrapped("The reference knee is flexed: move the tibia (its sliders) until your "
                       "DRR matches, then Check. Within %.3g deg and %.3g mm per joint angle.",
                       state.toleranceAngleDeg, state.toleranceOffsetMm);
        else
            dimWrapped("The reference moves %s: move it (its sliders) until your DRR matches, "
                       "then Check. Within %.3g mm and %.3g deg per motion number.",
                       bone.c_str(), state.toleranceOffsetMm, state.toleranceAngleDeg);
        if (flex.revealed && knee)
            ImGui::Text("reference: flexion %.1f  varus %.1f  int. rot. %.1f deg",
                        flex.referenceAngles[3], flex.referenceAngles[4], flex.referenceAngles[5]);
        else if (flex.revealed)
            ImGui::TextWrapped("reference: %s moved %.1f, %.1f, %.1f mm | %.1f, %.1f, %.1f deg",
                               bone.c_str(), flex.hiddenMotion[0], flex.hiddenMotion[1],
                               flex.hiddenMotion[2], flex.hiddenMotion[3], flex.hiddenMotion[4],
                               flex.hiddenMotion[5]);
        return;
    }
    const MatchOutcome& m = *flex.outcome;
    coloredWrapped(m.matched ? kGood : kWarn, m.verdict);
    record("text:flex-verdict");
    ImGui::Text("attempt %d%s", m.attempt,
                flex.outcomeIsStale ? (", " + bone + " moved since").c_str() : "");
    record("text:flex-attempt");
    // Two numbers a row (the translations beside the rotations): six rows did not fit the pane
    // of a 960 x 600 window. After Reveal a hint is its signed error (the words in its tooltip);
    // the reference's own motion is under the reference image.
    if (ImGui::BeginTable("flex-hints", 4, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV)) {
        for (int half = 0; half < 2; ++half) {
            ImGui::TableSetupColumn(knee ? "joint" : "motion", ImGuiTableColumnFlags_WidthStretch, 1.3f);
            ImGui::TableSetupColumn("hint", ImGuiTableColumnFlags_WidthStretch, 1.6f);
        }
        ImGui::TableHeadersRow();
        for (int row = 0; row < kParameterCount / 2; ++row) {
            ImGui::TableNextRow();
            for (const int p : {row, row + kParameterCount / 2}) {
                const char* name = knee ? kneeComponentName(p) : boneMotionComponentName(p);
                ImGui::TableNextColumn();
                if (p == m.furthestParameter)
                    ImGui::TextColored(kWarn, "%s*", name);
                else
                    ImGui::TextUnformatted(name);
                if (ImGui::IsItemHovered())
                    tooltip(p == m.furthestParameter ? "%s: furthest off" : "%s", name);
                ImGui::TableNextColumn();
                ImGui::PushStyleColor(ImGuiCol_Text, m.direction[p] == 0 ? kGood : kWarn);
                if (m.numbersShown)  // the signed error says the direction: one short line
                    ImGui::Text("%s%+.1f %s", m.direction[p] == 0 ? "ok " : "", m.error[p],
                                isAngleParameter(p) ? "deg" : "mm");
                else
                    ImGui::TextWrapped("%s", m.hintCells[p].c_str());
                ImGui::PopStyleColor();
                if (m.numbersShown && ImGui::IsItemHovered()) tooltip("%s", m.hintCells[p].c_str());
            }
        }
        ImGui::EndTable();
        record("table:flex-hints");
    }

}

}  // namespace fm::app

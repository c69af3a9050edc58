// The Solve tab: the computer's search from the user's pose, live, then its answer judged like a
// user's attempt (match / no match, in words); the numbers against the truth only after Reveal.
#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <cstdio>

#include "ui/Ui.h"
#include "ui/UiWidgets.h"

namespace fm::app {

using namespace widgets;

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
        // Find: the camera's pose from nothing (the X-ray mode, the camera as the target).
        const BonesState& bones = state.bones;
        const bool cameraTarget = bones.sliderTarget < 0 || bones.sliderTarget >= int(bones.list.size());
        if (state.mode == ImagingMode::Xray && cameraTarget && !bones.flex.active) {
            ImGui::SameLine();
            if (ImGui::Button("Find")) state.requests.find = true;
            record("button:find");
            if (ImGui::IsItemHovered())
                tooltip("Find the camera's pose from nothing: the CT's DRR from every direction, "
                        "turned, scaled and shifted over the reference, the best refined and "
                        "registered (azimuth any, elevation +-45, rotation +-30 deg, offsets +-40 mm)");
        }
    }
    solveTarget(state);
    if (!solve.error.empty()) coloredWrapped(kBad, solve.error);
    if (!solve.running && !solve.finished) {
        const BonesState& bones = state.bones;
        const int target = bones.sliderTarget >= 0 ? bones.sliderTarget : bones.flex.bone;
        if (bones.flex.active && target >= 0 && target < int(bones.list.size()))
            dimWrapped("Solve: %s registered alone from where you have it, the other bones "
                       "where they are, against the %s game's reference.",
                       bones.list[target].name.c_str(), bones.isKnee ? "flex" : "move");
        else
            dimWrapped("Solve: the automatic search from your pose, to compare with your "
                       "attempts. Find: the same with no start, from nothing.");
        return;
    }

    char overlay[160];
    if (solve.find && solve.running)  // the finder's stages have no budget to count against
        std::snprintf(overlay, sizeof(overlay), "%s", solve.stage.c_str());
    else
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
    const bool bone = solve.bone >= 0 && solve.bone < int(state.bones.list.size());
    if (solve.running) {
        ImGui::TextColored(kDim, "candidate");
        ImGui::SameLine();
        if (bone)  // the bone's search numbers are no 2011 pose
            ImGui::TextUnformatted(state.bones.list[solve.bone].name.c_str());
        else if (state.referenceRevealed)
            poseLine(solve.candidate);
        else  // the candidates converge on the answer: numbers only after Reveal
            ImGui::TextColored(kDim, "hidden until Reveal");
        if (state.showTimings) ImGui::TextColored(kDim, "%.1f s", solve.elapsedMs / 1000.0);
        return;
    }

    // Finished: the computer's answer, judged like a user's attempt.
    // "close to", "far from": the search looks around your pose, so a miss suggests a closer start.
    std::string verdict =
        solve.matched ? "The computer's answer matches the reference."
                      : std::string("No match: the computer's answer is ") +
                            closenessName(solve.closeness) +
                            (solve.closeness == Closeness::Far ? " from" : " to") + " the reference." +
                            (solve.find ? " The reference may lie outside Find's search space, or look alike "
                                          "from another side: Solve from a pose near it."
                                        : " It searches around your pose: start closer and Solve again.");
    if (solve.stopped) verdict += " (stopped)";
    coloredWrapped(solve.matched ? kGood : kWarn, verdict);
    record("text:solve-verdict");
    if (state.showTimings)
        ImGui::TextColored(kDim, "%d evals, %.1f s", solve.evaluations, solve.elapsedMs / 1000.0);
    else
        ImGui::TextColored(kDim, "%d evals", solve.evaluations);
    ImGui::SameLine();
    if (bone) {
        const auto& m = solve.boneMotion;
        if (state.bones.flex.revealed)
            ImGui::TextWrapped("%s %.1f, %.1f, %.1f mm | %.1f, %.1f, %.1f deg",
                               state.bones.list[solve.bone].name.c_str(), m[0], m[1], m[2], m[3],
                               m[4], m[5]);
        else
            ImGui::TextWrapped("%s: its motion is hidden until Reveal",
                               state.bones.list[solve.bone].name.c_str());
        record("text:solve-bone-motion");
        // Judged as a Check (the knee's tibia on the joint angles); the numbers once the game's
        // reference is revealed.
        const bool kneeAngles = state.bones.isKnee && state.bones.flex.bone == solve.bone;
        if (state.bones.flex.revealed)
            ImGui::TextWrapped("mTRE %.2f mm, %s error %+.1f %+.1f %+.1f mm | %+.1f %+.1f %+.1f deg",
                        solve.poseErrorMm, kneeAngles ? "knee" : "motion", solve.error6[0],
                        solve.error6[1], solve.error6[2], solve.error6[3], solve.error6[4],
                        solve.error6[5]);
        else
            dimWrapped("Reveal (Bones tab) shows its error against the hidden motion.");
    } else if (state.referenceRevealed) {
        poseLine(solve.bestPose);
        record("text:solve-pose");
    } else {  // the computer's pose is the answer: shown with the reference's, after Reveal
        ImGui::TextColored(kDim, "pose hidden until Reveal (it is the answer)");
        record("text:solve-pose-hidden");
    }
    if (!bone && state.referenceRevealed) {
        ImGui::TextWrapped("mTRE %.2f mm, error %+.1f %+.1f %+.1f mm | %+.1f %+.1f %+.1f deg",
                    solve.poseErrorMm, solve.error6[0], solve.error6[1], solve.error6[2],
                    solve.error6[3], solve.error6[4], solve.error6[5]);
        if (state.bestUserPoseErrorMm)
            ImGui::Text("you: %d attempt%s, best mTRE %.2f mm", state.attempts,
                        state.attempts == 1 ? "" : "s", *state.bestUserPoseErrorMm);
    }
    if (!bone && (!state.referenceRevealed || !state.bestUserPoseErrorMm)) {
        if (state.attempts > 0)
            ImGui::Text("you: %d attempt%s%s", state.attempts, state.attempts == 1 ? "" : "s",
                        !state.match || !state.match->matched ? ""
                        : state.match->assisted               ? ", matched with the computer's help"
                                                              : ", matched");
        else
            ImGui::Text("you: no attempt yet");
    }
    if (ImGui::Button(solve.applied ? "Applied" : "Apply solution"))
        state.requests.applySolution = true;
    record("button:apply-solution");
    if (ImGui::IsItemHovered())
        tooltip("Move your sliders to the computer's answer; a Match from there is marked as "
                "assisted, not counted as yours");
}

void Ui::solveTarget(AppState& state) {
    // What Solve moves: the camera, or one bone (the sliders' target: one choice for both).
    BonesState& bones = state.bones;
    if (bones.list.empty() || state.mode != ImagingMode::Xray) return;
    int& target = bones.sliderTarget;
    const std::string shown = target >= 0 && target < int(bones.list.size())
                                  ? bones.list[target].name
                                  : std::string("camera");
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted("Solve for:");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(std::min(ImGui::GetContentRegionAvail().x * 0.45f,
                                     ImGui::CalcTextSize("femur_right++").x +
                                         ImGui::GetFrameHeight()));
    ImGui::BeginDisabled(state.solve.running);
    if (ImGui::BeginCombo("##solve-target", shown.c_str())) {
        if (ImGui::Selectable("camera", target < 0)) target = -1;
        for (int i = 0; i < int(bones.list.size()); ++i)
            if (ImGui::Selectable(bones.list[i].name.c_str(), target == i)) target = i;
        ImGui::EndCombo();
    }
    record("combo:solve-target");
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        tooltip("A bone is registered alone against the bone game's reference (the others "
                "stay); it is also the bone the sliders move");
    ImGui::SameLine();
    ImGui::Checkbox("biplane", &bones.biplaneSolve);
    record("checkbox:solve-biplane");
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        tooltip("A bone's solve also compares the reference seen from 90 deg around (as biplane "
                "fluoroscopy): one view hardly sees a motion along its rays");
    ImGui::EndDisabled();
}

}  // namespace fm::app

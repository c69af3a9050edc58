// The workspace's Track pane (WorkspaceUi::trackPane): play / pause, keyframe set / clear for the
// selected object at the current frame, Track back / forward from it with live progress and Stop,
// Save .tra and the keyframes, and the six curves of the object's pose over the frames with the
// current frame marked (TrackState.h; WorkspaceTracking does the work).
#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "ui/UiWidgets.h"
#include "workspace/WorkspaceUi.h"

namespace fm::app {

using namespace widgets;

namespace {

const ImU32 kCurveColours[PoseCurves::kCount] = {
    IM_COL32(240, 90, 90, 255),  IM_COL32(110, 220, 110, 255), IM_COL32(100, 150, 255, 255),
    IM_COL32(240, 170, 80, 255), IM_COL32(200, 120, 240, 255), IM_COL32(90, 210, 220, 255)};

}  // namespace

void WorkspaceUi::trackPane(WorkspaceState& state, const Pane& pane) {
    const std::string title =
        state.selected >= 0 && state.selected < static_cast<int>(state.objects.size())
            ? "Track: " + state.objects[static_cast<std::size_t>(state.selected)].name + "###track"
            : std::string("Track###track");
    beginPane(title.c_str(), pane);
    // Controls on the left, the plot over the rest of the strip.
    const float controlsWidth = std::min(ImGui::GetContentRegionAvail().x * 0.4f, ImGui::GetFontSize() * 36.0f);
    ImGui::BeginChild("##trackcontrols", ImVec2(controlsWidth, 0.0f), false, ImGuiWindowFlags_NoScrollbar);
    TrackState& t = state.track;
    TrackRequests& r = t.requests;
    const bool haveObject = state.selected >= 0 && state.selected < static_cast<int>(state.objects.size());
    const bool running = t.run.running;
    const auto object = static_cast<std::size_t>(state.selected);
    const bool isKeyframe =
        haveObject && object < t.keyframes.size() && t.keyframes[object].count(state.frame) > 0;

    if (ImGui::Button(t.playing ? "Pause" : "Play")) r.togglePlay = true;
    record("button:play");
    if (ImGui::IsItemHovered()) tooltip("Step through the frames (and round again)");
    ImGui::SameLine();
    ImGui::BeginDisabled(!haveObject);
    if (ImGui::Button("Set keyframe")) r.setKeyframe = true;
    record("button:keyframe-set");
    if (ImGui::IsItemHovered())
        tooltip("The selected object's pose in this frame becomes a keyframe: tracking starts from it here");
    ImGui::SameLine();
    ImGui::BeginDisabled(!isKeyframe);
    if (ImGui::Button("Clear")) r.clearKeyframe = true;
    record("button:keyframe-clear");
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::TextColored(isKeyframe ? kGood : kDim, isKeyframe ? "keyframe" : "no keyframe");

    if (running) {
        if (ImGui::Button("Stop")) r.stop = true;
        record("button:track-stop");
        if (ImGui::IsItemHovered()) tooltip("End after the frame being tracked; every finished frame stays");
    } else {
        if (ImGui::Button("<< Track back")) r.back = true;
        record("button:track-back");
        if (ImGui::IsItemHovered())
            tooltip("Track the selected object from this frame back to the first (fluoromatch track --reverse)");
        ImGui::SameLine();
        if (ImGui::Button("Track forward >>")) r.forward = true;
        record("button:track-forward");
        if (ImGui::IsItemHovered())
            tooltip("Track the selected object from this frame to the last, each frame from the ones before "
                    "(fluoromatch track: keyframes restart it)");
    }
    ImGui::EndDisabled();
    ImGui::SameLine();
    const TrackRunView& v = t.run;
    // The last run's status belongs to its object: another object selected shows its own (none).
    const bool runOfSelected = v.running || (state.selected >= 0 && state.selected < int(state.objects.size()) &&
                                             state.objects[static_cast<std::size_t>(state.selected)].name == v.object);
    char overlay[160];
    if (v.total > 0 && runOfSelected)
        std::snprintf(overlay, sizeof overlay, "%s %d/%d", v.object.c_str(), v.done, v.total);
    else
        std::snprintf(overlay, sizeof overlay, "not tracked yet");
    ImGui::ProgressBar(v.total > 0 && runOfSelected ? float(v.done) / float(v.total) : 0.0f, ImVec2(-1.0f, 0.0f),
                       overlay);
    record("progress:track");
    if (v.total > 0 && runOfSelected) {
        char line[200], seconds[48] = "";
        if (state.showTimings) std::snprintf(seconds, sizeof seconds, "  %.2f s/frame", v.secondsPerFrame);
        const std::string where = v.running && v.currentFrame >= 0 ? ", frame " + std::to_string(v.currentFrame) : "";
        std::snprintf(line, sizeof line, "%s%s%s%s  cost %.4f",
                      v.running ? "tracking " : (v.stopped ? "stopped " : "tracked "),
                      v.backwards ? "back" : "forward", where.c_str(), seconds, v.lastCost);
        if (elidedText(v.running ? kSelected : kDim, line) && ImGui::IsItemHovered()) tooltip(line);
        record("text:track-status");
        // How sure the frames are: green only when every frame is ok.
        if (v.ok + v.doubtful + v.lost > 0) {
            std::string verdicts = std::to_string(v.ok) + " ok, " + std::to_string(v.doubtful) + " doubtful, " +
                                   std::to_string(v.lost) + " lost";
            if (!v.notOk.empty()) {
                verdicts += " (frames";
                for (std::size_t i = 0; i < v.notOk.size() && i < 8; ++i) {  // piecewise: GCC 12's -Wrestrict
                    verdicts += ' ';
                    verdicts += std::to_string(v.notOk[i]);
                }
                verdicts += v.notOk.size() > 8 ? " ...)" : ")";
            }
            const ImVec4 colour = v.worst == AnswerVerdict::Ok ? kGood : v.worst == AnswerVerdict::Lost ? kBad : kWarn;
            if (elidedText(colour, verdicts) && ImGui::IsItemHovered()) tooltip(verdicts);
            record("text:track-verdicts");
        }
        if (!v.lastNote.empty() && elidedText(kDim, v.lastNote) && ImGui::IsItemHovered()) tooltip(v.lastNote);
    }
    if (!v.error.empty()) coloredWrapped(kBad, v.error);

    // This save writes the selected object alone (the Solve pane's writes them all): named on it.
    const std::string saveTraLabel =
        "Save " + (haveObject ? state.objects[static_cast<std::size_t>(state.selected)].name : std::string("object")) +
        ".tra###save-tra";
    ImGui::SetNextItemWidth(std::max(60.0f, ImGui::GetContentRegionAvail().x -
                                                ImGui::CalcTextSize(saveTraLabel.c_str(), nullptr, true).x -
                                                ImGui::CalcTextSize("Save keyframes").x -
                                                4 * ImGui::GetStyle().FramePadding.x -
                                                2 * ImGui::GetStyle().ItemSpacing.x));
    ImGui::InputTextWithHint("##trapath", "<trial>_<object>.tra", &t.traPath);
    record("input:tra-path");
    if (ImGui::IsItemHovered())
        tooltip("Where Save <object>.tra writes the selected object's poses (Autoscoper's .tra, NaN where none; the "
                "bytes fluoromatch track writes). Empty: beside the save path, <name>_<object>.tra");
    ImGui::SameLine();
    ImGui::BeginDisabled(!haveObject);
    if (ImGui::Button(saveTraLabel.c_str())) r.saveTra = true;
    record("button:save-tra");
    ImGui::EndDisabled();
    ImGui::SameLine();
    if (ImGui::Button("Save keyframes")) r.saveKeyframes = true;
    record("button:save-keyframes");
    if (ImGui::IsItemHovered()) tooltip("Write the trial as our JSON with every object's keyframes and each camera's preparation (invert / log as set)");
    if (!t.message.empty() && elidedText(t.messageFailed ? kBad : kGood, t.message) && ImGui::IsItemHovered())
        tooltip(t.message);

    ImGui::EndChild();
    ImGui::SameLine();
    posePlot(state);
    ImGui::End();
}

void WorkspaceUi::posePlot(WorkspaceState& state) {
    const TrackState& t = state.track;
    const ImVec2 avail = ImGui::GetContentRegionAvail();
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const float rowHeight = std::max(12.0f, avail.y / PoseCurves::kCount);
    const ImVec2 size(std::max(40.0f, avail.x), rowHeight * PoseCurves::kCount);
    ImGui::InvisibleButton("##poseplot", size);
    record("plot:pose");
    const bool hovered = ImGui::IsItemHovered();
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const int frames = std::max(1, state.frameCount);
    const float labelWidth = ImGui::CalcTextSize("pitch -888.8").x;
    const float x0 = origin.x + labelWidth, x1 = origin.x + size.x - 4.0f;
    const auto xOf = [&](int f) { return frames > 1 ? x0 + (x1 - x0) * float(f) / float(frames - 1) : 0.5f * (x0 + x1); };
    // A click (or drag) in the plot goes to that frame.
    if (hovered && ImGui::IsMouseDown(ImGuiMouseButton_Left) && frames > 1) {
        const int f = std::clamp(int(std::lround((ImGui::GetIO().MousePos.x - x0) / (x1 - x0) * (frames - 1))), 0,
                                 frames - 1);
        if (f != state.frame) state.requests.frame = f;
    }
    const auto object = static_cast<std::size_t>(state.selected);
    for (int c = 0; c < PoseCurves::kCount; ++c) {
        const float top = origin.y + rowHeight * c, bottom = top + rowHeight - 2.0f;
        draw->AddRectFilled(ImVec2(x0, top), ImVec2(x1, bottom), IM_COL32(30, 30, 36, 255));
        const std::vector<float>& values = t.curves.values[static_cast<std::size_t>(c)];
        const auto [lo, hi] = t.curves.range(c);
        const float span = std::max(hi - lo, c < 3 ? 1.0f : 1.0f);  // at least 1 mm / 1 deg tall
        const float mid = 0.5f * (lo + hi);
        const auto yOf = [&](float v) { return bottom - 2.0f - (bottom - top - 4.0f) * ((v - mid) / span + 0.5f); };
        // Segments join neighbouring frames that both have a pose; a lone pose is a dot.
        for (std::size_t f = 0; f < values.size(); ++f) {
            if (!std::isfinite(values[f])) continue;
            const ImVec2 p(xOf(static_cast<int>(f)), yOf(values[f]));
            if (f + 1 < values.size() && std::isfinite(values[f + 1]))
                draw->AddLine(p, ImVec2(xOf(static_cast<int>(f + 1)), yOf(values[f + 1])), kCurveColours[c], 1.5f);
            draw->AddCircleFilled(p, frames <= 60 ? 2.5f : 1.0f, kCurveColours[c]);
        }
        if (object < t.keyframes.size())
            for (const auto& [f, pose] : t.keyframes[object])
                draw->AddTriangleFilled(ImVec2(xOf(f) - 3.0f, bottom), ImVec2(xOf(f) + 3.0f, bottom),
                                        ImVec2(xOf(f), bottom - 5.0f), IM_COL32(120, 230, 120, 255));
        char label[48];
        const std::size_t at = static_cast<std::size_t>(state.frame);
        const float now = at < values.size() ? values[at] : NAN;
        std::string name = PoseCurves::name(c);
        name = name.substr(0, name.find(' '));
        if (std::isfinite(now))
            std::snprintf(label, sizeof label, "%s %.1f", name.c_str(), now);
        else
            std::snprintf(label, sizeof label, "%s -", name.c_str());
        draw->AddText(ImVec2(origin.x, top + 0.5f * (rowHeight - ImGui::GetFontSize()) - 1.0f),
                      ImGui::GetColorU32(ImGuiCol_Text), label);
    }
    const float xf = xOf(state.frame);
    draw->AddLine(ImVec2(xf, origin.y), ImVec2(xf, origin.y + size.y - 2.0f), IM_COL32(255, 230, 80, 200), 1.0f);
    if (t.run.running && t.run.currentFrame >= 0) {
        const float xc = xOf(t.run.currentFrame);
        draw->AddLine(ImVec2(xc, origin.y), ImVec2(xc, origin.y + size.y - 2.0f), IM_COL32(100, 180, 255, 160), 1.0f);
    }
    if (hovered)
        tooltip("The selected object's pose over the frames (its .tra pose, Autoscoper's volume frame): x, y, z "
                "(mm), yaw, pitch, roll (deg, R = Rz Ry Rx, unwrapped); each curve scaled to its own range. "
                "Yellow: this frame; blue: the frame being tracked; triangles: keyframes. Click: go to a frame");
}

}  // namespace fm::app

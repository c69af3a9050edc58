// The Help window: the task, the parameters, the controls, the rule of a match and what the
// hints say.
#include <imgui.h>

#include <algorithm>

#include "ui/Ui.h"
#include "ui/UiWidgets.h"

namespace fm::app {

using namespace widgets;

void Ui::helpWindow(AppState& state) {
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    // Centred, as wide as fits, at most as tall as the window (scrolls beyond), opaque.
    const float width = std::min(640.0f, display.x - 40.0f);
    ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.5f), ImGuiCond_Always,
                            ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSizeConstraints(ImVec2(width, 0.0f), ImVec2(width, display.y - 20.0f));
    ImGui::SetNextWindowBgAlpha(1.0f);
    if (ImGui::Begin("Help", &state.showHelp,
                     ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse |
                         ImGuiWindowFlags_NoMove | ImGuiWindowFlags_AlwaysAutoResize)) {
        // At the top: the text is taller than a small window, and a Close below it scrolled away.
        if (ImGui::Button("Close")) state.showHelp = false;
        record("button:close-help");
        ImGui::SameLine();
        ImGui::TextColored(kDim, "(or Escape)");
        ImGui::TextWrapped(
            "The task: the left image is a radiograph (DRR) of the CT taken from a hidden pose. "
            "Find that pose: move the six parameters until your DRR (middle) matches it, then "
            "press Match (or Enter).");
        ImGui::Spacing();
        ImGui::TextUnformatted("The six parameters:");
        bulletWrapped(
            "x, y, z offset (mm): where the CT's centre sits relative to the isocenter, the "
            "point between source and film (LPS: x towards patient left, y posterior, z "
            "superior).");
        bulletWrapped(
            "azimuth (-180..180 deg) and elevation (-90..90 deg): where the X-ray source stands "
            "on its sphere around the isocenter (azimuth 0: anterior, AP).");
        bulletWrapped("rotation (-90..90 deg): the film's turn in its own plane.");
        ImGui::Spacing();
        ImGui::TextUnformatted("Match and hints:");
        bulletWrapped(
            "A match: every offset within %.3g mm and every angle within %.3g deg of the hidden "
            "pose. Nothing else decides.",
            state.toleranceOffsetMm, state.toleranceAngleDeg);
        bulletWrapped(
            "Hints: 'direction' says too high / too low per parameter and names the one "
            "furthest off; 'bands' also says how far (very close: within 3 tolerances, close: "
            "within 10, far). The exact errors appear only after a match or Reveal.");
        bulletWrapped(
            "'The pose as a whole' is the mean distance of the bone points between your pose "
            "and the hidden one (mTRE): very close < 3 mm, close < 10 mm, far beyond.");
        bulletWrapped(
            "New reference: another hidden pose around a clinical view (AP, lateral, oblique, "
            "...). Difficulty: easy hides 2 parameters, medium 4, hard all 6, further off.");
        bulletWrapped(
            "Solve: the computer searches from your pose (live; Stop keeps its best so far); "
            "its answer is judged like yours, its pose hidden until Reveal. Apply solution puts "
            "it on the sliders; a Match from there is marked as assisted, not yours.");
        ImGui::Spacing();
        ImGui::TextUnformatted("Bones (the Bones tab):");
        bulletWrapped(
            "The CT's bones as objects: show or hide each (in both DRRs and the 3D view), and "
            "choose what the sliders move: the camera, or one bone (its offsets and turns).");
        bulletWrapped(
            "Knee: the Grood-Suntay angles of the tibia against the femur, live: flexion, "
            "varus, internal rotation (deg); medial shift, anterior drawer, distraction (mm).");
        bulletWrapped(
            "The flex game (knee): New flexion hides a flexion of the tibia (femur and patella "
            "stay); move the tibia until your DRR matches, then Check. Hints name the angle "
            "furthest off; numbers after a match or Reveal.");
        bulletWrapped(
            "The move game (other bones: a label map, components, a grown region): one bone is "
            "moved by a hidden motion; move it back with the sliders, then Check.");
        bulletWrapped(
            "Solve for a bone registers that bone alone against the bone game's reference "
            "(the others stay), optionally biplane.");
        ImGui::Spacing();
        ImGui::TextUnformatted("Controls:");
        bulletWrapped("Drag a slider, or type a number in the field beside it.");
        bulletWrapped(
            "Keyboard: Up/Down select a parameter (highlighted; a click on its slider does "
            "too), Left/Right nudge it by 1 mm or 1 deg, with Shift by 0.1. Enter: Match. "
            "Escape: close this window.");
        bulletWrapped(
            "Compare: difference, overlay or checkerboard of the two images, with window and "
            "level.");
        bulletWrapped(
            "3D view: drag to orbit, middle-drag (or Shift+drag) to pan, right-drag or wheel to "
            "zoom; Reset view frames the whole set-up.");
        bulletWrapped(
            "Images: X-ray or MRI slice. In the slice mode both panes show planar slices of the "
            "volume: the offsets move the volume against the plane, azimuth and elevation tilt "
            "the plane, rotation turns it; an MRI file opens in this mode.");
        bulletWrapped(
            "Open another CT: type a path (file, DICOM folder or phantom:NAME) or drop it onto "
            "the window.");
    }
    ImGui::End();
}

}  // namespace fm::app

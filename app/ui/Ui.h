#pragma once
// The ImGui user interface: panes that read and edit AppState. No engine calls here: buttons
// set AppState::requests, sliders edit the poses; the App does the work after the UI pass.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/Image.h"
#include "similarity/Mask.h"
#include "state/AppState.h"
#include "ui/Layout.h"

struct ImDrawList;
struct ImVec4;

namespace fm::app {

// GL textures the panes show (0 = nothing yet).
struct UiTextures {
    unsigned reference = 0, user = 0, compare = 0, scene3d = 0;
    // The images behind the first two (for the pixel readout); null when none yet.
    const Image* referenceImage = nullptr;
    const Image* userImage = nullptr;
    // Slice mode: the pixels of those images that hold data (null: every pixel does).
    const Mask* referenceDataMask = nullptr;
    const Mask* userDataMask = nullptr;
};

// A widget's screen rectangle (pixels, top-left origin), for scripted tests.
struct WidgetRect {
    glm::vec2 min{0.0f}, max{0.0f};
    bool visible = true;  // not clipped away by its pane (a click there would land elsewhere)
    glm::vec2 center() const { return 0.5f * (min + max); }
};

class Ui {
  public:
    void draw(AppState& state, const UiTextures& textures);

    // Where the 3D view image sits (for the renderer's size and the overlay labels).
    glm::ivec2 sceneViewSize() const { return sceneViewSize_; }
    // Text drawn over the 3D view at pixel positions inside it (after the scene is drawn).
    void drawSceneLabels(const std::vector<std::pair<glm::vec2, std::string>>& labels,
                         const std::vector<glm::vec4>& colors);

    // Rectangles of named widgets from the last frame: "slider:azimuth", "input:azimuth",
    // "button:match", "button:new-reference", "button:help", "view:3d", ...
    std::optional<WidgetRect> rect(const std::string& id) const;
    void record(const std::string& id);  // the last ImGui item, under `id`
    // The tooltip drawn in the last frame ("" if none); its window is rect("tooltip").
    const std::string& shownTooltip() const { return shownTooltip_; }

  private:
    void referencePane(AppState& state, const Pane& pane, unsigned texture);
    void userPane(AppState& state, const Pane& pane, unsigned texture);
    void scenePane(AppState& state, const Pane& pane, unsigned texture);
    void parameterPane(AppState& state, const Pane& pane);
    void comparePane(AppState& state, const Pane& pane, unsigned texture);
    void matchPane(AppState& state, const Pane& pane);
    void matchTab(AppState& state);      // MatchPanel.cpp: the user's attempts ...
    void solveSection(AppState& state);  // SolvePanel.cpp
    void solveTarget(AppState& state);   // SolvePanel.cpp: camera or a bone, biplane
    void bonesTab(AppState& state);      // BonesPanel.cpp: the bone list and ...
    void boneGame(AppState& state);
    void labelsSection(AppState& state);  // LabelsPanel.cpp: label map, table, components      // ... the bone game (the knee's flex game, the move game)
    void kneeAnglesLine(const AppState& state);  // BonesPanel.cpp: Grood-Suntay, live: ... and the computer's
    void helpWindow(AppState& state);    // HelpWindow.cpp
    void modeSwitch(AppState& state);    // ModeSwitch.cpp: X-ray / MRI slice
    void keyboard(AppState& state);      // KeyboardNudge.cpp: arrows, Enter, Escape
    // ImagePane.cpp: a square 2D image with zoom (wheel), pan (right or middle drag),
    // window/level (left drag), pixel readout and orientation letters.
    // `dataMask` (may be null) marks the pixels that hold data; the readout says "no data"
    // elsewhere.
    void imageWidget(AppState& state, const std::string& id, unsigned texture, const Image* image,
                     const Mask* dataMask, const ImageEdgeLetters& edges, float side);
    void enlargedCompare(AppState& state, unsigned texture);
    void drrThresholdControl(AppState& state, float width);  // Compare pane: bone-only DRRs
    // Tooltip.cpp: the hovered item's tooltip (the last request of a frame wins), drawn by
    // drawTooltip after every pane, never over the load progress bar.
    void tooltip(const char* format, ...) __attribute__((format(printf, 2, 3)));
    void drawTooltip();
    // One line cut to the pane's width with "...", the whole text in a tooltip; rect(id).
    void elidedLine(const std::string& id, const ImVec4& color, const std::string& text);
    // A pose in one line that fits what is left of the line: spaced, else compact, else cut
    // with the whole pose in a tooltip.
    void poseLine(const Pose& pose);

    std::map<std::string, WidgetRect> rects_;
    UiTextures textures_;  // this frame's
    std::string tooltip_, shownTooltip_;  // requested this frame / drawn last frame
    glm::ivec2 sceneViewSize_{320, 320};
    glm::vec2 sceneViewOrigin_{0.0f};
    ImDrawList* sceneDrawList_ = nullptr;
};

}  // namespace fm::app

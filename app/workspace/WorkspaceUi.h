#pragma once
// The ImGui panes of the real X-ray workspace, reading and editing WorkspaceState (no engine
// calls: buttons set its requests). Layout (fixed for a display size):
//   top row:    one pane per camera (the prepared radiograph with the model over or beside it)
//               | the 3D view
//   bottom row: Objects and frames | Pose (six controls) | Solve and Save
//   a trial's timeline strip below: the Track pane (TrackPanel.cpp: play, keyframes, Track
//               forward / back, the pose plot)
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/Image.h"
#include "render/SceneRenderer.h"
#include "ui/Layout.h"
#include "ui/Ui.h"
#include "workspace/WorkspaceState.h"

struct ImDrawList;

namespace fm::app {

struct WorkspaceTextures {
    std::vector<unsigned> radiograph, model;  // per camera (0: none)
    std::vector<const Image*> images;         // per camera: the prepared radiograph (readout)
    unsigned scene3d = 0;
};

struct WorkspaceLayout {
    std::vector<Pane> cameras;
    Pane scene3d, objects, pose, solve;
    Pane track;  // empty without the timeline
};
WorkspaceLayout computeWorkspaceLayout(glm::vec2 display, int cameras, bool timeline = false);

class WorkspaceUi {
  public:
    void draw(WorkspaceState& state, const WorkspaceTextures& textures);
    std::optional<WidgetRect> rect(const std::string& id) const;
    glm::ivec2 sceneViewSize() const { return sceneViewSize_; }
    // The 3D view's labels (camera names at their sources), drawn over it after it is drawn.
    void drawSceneLabels(const std::vector<render::SceneLabel>& labels);
    const std::string& shownTooltip() const { return shownTooltip_; }

  private:
    // `enlarged`: drawn over the whole window (Enlarge), with a Close.
    void cameraPane(WorkspaceState& state, const WorkspaceTextures& textures, int camera, const Pane& pane,
                    bool enlarged = false);
    void scenePane(WorkspaceState& state, const Pane& pane, unsigned texture);
    void objectsPane(WorkspaceState& state, const Pane& pane);
    void posePane(WorkspaceState& state, const Pane& pane);
    void solvePane(WorkspaceState& state, const Pane& pane);
    void trackPane(WorkspaceState& state, const Pane& pane);  // TrackPanel.cpp
    void posePlot(WorkspaceState& state);                     // ... its six curves
    void keyboard(WorkspaceState& state);
    void record(const std::string& id);
    void tooltip(const std::string& text);
    void drawTooltip();

    std::map<std::string, WidgetRect> rects_;
    std::string tooltip_, shownTooltip_;
    glm::ivec2 sceneViewSize_{320, 320};
    glm::vec2 sceneOrigin_{0.0f};
    ImDrawList* sceneDrawList_ = nullptr;
};

}  // namespace fm::app

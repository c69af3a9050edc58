#pragma once
// The real X-ray workspace's frame loop (the window and the headless screenshot share it, as the
// game's App does): the UI pass, then the requests (frame, Solve, Save), the pose controls
// written into the current frame's pose, the pane images brought up to date, the 3D view drawn.
#include <memory>
#include <vector>

#include "mesh/Mesh.h"
#include "platform/RenderBackend.h"
#include "render/Screenshot.h"
#include "ui/PresentFrame.h"
#include "ui/ScriptableApp.h"
#include "workspace/WorkspaceImages.h"
#include "workspace/WorkspaceModel.h"
#include "workspace/WorkspaceSolver.h"
#include "workspace/WorkspaceState.h"
#include "workspace/WorkspaceTracking.h"
#include "workspace/WorkspaceUi.h"

namespace fm::render {
class Texture;
class SceneRenderer;
}  // namespace fm::render

namespace fm::app {

struct WorkspaceOptions {
    bool showTimings = true;  // golden images turn them off (they vary)
};

class WorkspaceApp : public ScriptableApp {
  public:
    WorkspaceApp(RenderBackend& backend, std::shared_ptr<WorkspaceModel> model, WorkspaceOptions options = {});
    ~WorkspaceApp() override;
    WorkspaceApp(const WorkspaceApp&) = delete;
    WorkspaceApp& operator=(const WorkspaceApp&) = delete;

    void frame() override;
    std::optional<OpenRequest> takeOpenRequest() override;
    void openFailed(const std::string& why) override;
    void setRecent(std::vector<OpenRequest> recent) override { state_.open.recent = std::move(recent); }
    RenderBackend& backend() override { return backend_; }
    std::optional<WidgetRect> widgetRect(const std::string& id) const override { return ui_.rect(id); }
    render::RgbaImage capture() const;

    WorkspaceState& state() { return state_; }
    const WorkspaceState& state() const { return state_; }
    const WorkspaceModel& model() const { return *model_; }
    const WorkspaceImages& images() const { return images_; }
    const WorkspaceUi& ui() const { return ui_; }
    const WorkspaceSolver& solver() const { return solver_; }
    const WorkspaceTracking& tracking() const { return tracking_; }
    const render::SceneRenderer& sceneRenderer() const { return *sceneRenderer_; }
    FramePresenter& presenter() { return presenter_; }  // what each frame redraws
    int sceneDraws() const { return sceneDraws_; }  // how often the 3D view was drawn
    // Where `object` is shown in the current frame: its own pose there, else the one carried
    // over (ShownPose.h).
    std::optional<RigidTransform> pose(int object) const;
    // Draws frames until a running Solve has ended and its result is shown (tests, headless).
    void waitForSolve();
    // Draws frames until a running Track run has ended and its last frame is shown.
    void waitForTrack();

  private:
    void goToFrame(int frame);
    // Returns whether the controls changed the pose (an edit, recorded for Undo).
    bool applyControls();
    void undo();
    PoseSnapshot snapshot() const { return {state_.poses, state_.track.keyframes}; }
    void syncControls();
    void processRequests();
    // Find's candidate k onto the object's pose in the Find's frame (an Undo step).
    void showCandidate(int k);
    void pollSolver();
    void save();
    void syncCameraValues();  // the toggles from the model's preparations
    void updateImages();
    // state_.rawHint from the shown models' footprints on the prepared radiographs.
    void updateRawHint();
    void buildSurfaces();
    void drawScene();

    RenderBackend& backend_;
    std::shared_ptr<WorkspaceModel> model_;
    WorkspaceOptions options_;
    WorkspaceState state_;
    WorkspaceUi ui_;
    WorkspaceImages images_;
    std::vector<std::unique_ptr<render::Texture>> radiographTextures_, modelTextures_;
    std::unique_ptr<render::SceneRenderer> sceneRenderer_;
    FramePresenter presenter_;
    std::vector<std::shared_ptr<const Mesh>> surfaces_;  // per object, its own frame (null: none)
    // What the 3D view shows, to redraw it only on change.
    struct SceneKey {
        int frame = -1;
        std::vector<std::optional<RigidTransform>> poses;
        std::vector<bool> visible;
        float azimuth = 0, elevation = 0, zoom = 0, panX = 0, panY = 0;
        bool models = true, cameras = true;
        glm::ivec2 size{0};
        std::uint64_t images = 0;
        bool fast = false;
        bool operator==(const SceneKey& o) const {
            auto same = [](const std::optional<RigidTransform>& a, const std::optional<RigidTransform>& b) {
                return a.has_value() == b.has_value() &&
                       (!a || (a->rotation == b->rotation && a->translation == b->translation));
            };
            if (poses.size() != o.poses.size()) return false;
            for (std::size_t i = 0; i < poses.size(); ++i)
                if (!same(poses[i], o.poses[i])) return false;
            return frame == o.frame && visible == o.visible && azimuth == o.azimuth && elevation == o.elevation &&
                   zoom == o.zoom && panX == o.panX && panY == o.panY && models == o.models &&
                   cameras == o.cameras && size == o.size && images == o.images && fast == o.fast;
        }
    };
    std::optional<SceneKey> sceneKey_;
    std::uint64_t imagesVersion_ = 0;
    int sceneDraws_ = 0;
    int autoWindowFrame_ = -1;
    // The raw-image hint (updateRawHint): due after the panes changed; each frame's value range
    // kept for its (frame, preparation version).
    bool rawHintStale_ = false;
    std::pair<int, std::uint64_t> rawRangesKey_{-1, 0};
    std::vector<double> rawRanges_;
    std::uint64_t solveVersion_ = 0;
    // Last: joined first (their workers hold the model).
    WorkspaceTracking tracking_;
    WorkspaceSolver solver_;
};

}  // namespace fm::app

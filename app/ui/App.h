#pragma once
// The matching app: one frame loop shared by the window and the headless screenshot. The
// backend (GLFW or OSMesa) is chosen by the caller; everything else is identical.
#include <array>
#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <random>
#include <string>

#include "core/Image.h"
#include "platform/RenderBackend.h"
#include "render/ImageDisplay.h"
#include "render/Screenshot.h"
#include "ui/PresentFrame.h"
#include "render/SurfaceItem.h"
#include "scene/BonesLoader.h"
#include "scene/DrrCache.h"
#include "scene/NewestWins.h"
#include "scene/ObjectPoseParameterization.h"
#include "scene/SceneLoader.h"
#include "scene/Solver.h"
#include "state/AppState.h"
#include "ui/ScriptableApp.h"
#include "ui/Ui.h"

namespace fm::render {
class Texture;
class SceneRenderer;
}  // namespace fm::render

namespace fm::app {

struct AppOptions {
    std::string volumeSpec = "phantom:knee";
    std::optional<Pose> userPose;
    std::optional<ImagingMode> mode;    // otherwise chosen from the volume (MRI: slices)
    std::optional<Pose> referencePose;  // otherwise chosen by chooseReference(seed)
    std::optional<View3d> view;
    std::uint64_t seed = 1;   // reference choice; the window passes the clock
    int drrThreads = 0;       // 0 = all cores
    bool showTimings = true;  // golden images turn them off (they vary)
    // The user's DRR on a worker: frames show the newest finished one and never wait for it
    // (the window). Off: each frame waits for the DRR of its own state, so headless screenshots
    // and scripted tests do not depend on timing.
    bool userDrrOffThread = false;
    // Not empty: the reference as a realistic radiograph at this spectrum (`--spectrum`).
    std::string spectrum;
    // Bones of the first scene from this label map (and table), built once it is loaded.
    std::string labelsSpec, labelTable;
};

class App : public ScriptableApp {
  public:
    App(RenderBackend& backend, AppOptions options);
    ~App() override;
    App(const App&) = delete;
    App& operator=(const App&) = delete;

    // One whole frame: input, UI, requests, DRRs, 3D view, ImGui draw, present.
    void frame() override;
    std::optional<OpenRequest> takeOpenRequest() override;
    void openFailed(const std::string& why) override;
    void setRecent(std::vector<OpenRequest> recent) override { state_.open.recent = std::move(recent); }
    // Blocks until the background loader is idle and its result is installed (headless runs).
    void waitForLoad();
    // The last drawn frame (call after frame(), before the next one).
    render::RgbaImage capture() const;

    AppState& state() { return state_; }
    const AppState& state() const { return state_; }
    Ui& ui() { return ui_; }
    const LoadedScene* scene() const { return scene_.get(); }
    const Image& userDrr() const { return userDrr_; }
    const Image& referenceDrr() const { return referenceDrr_; }
    // How many user DRRs were actually rendered (not served from the cache), by kind.
    int exactUserRenders() const { return exactUserRenders_; }
    int coarseUserRenders() const { return coarseUserRenders_; }
    int sceneDraws() const { return sceneDraws_; }
    // The user's DRR on its worker (frames never wait for it) or waited for by each frame.
    void setUserDrrOffThread(bool on) { options_.userDrrOffThread = on; }
    bool userDrrPending() const { return userDrrWorker_->busy(); }  // asked for, not yet taken  // how often the 3D view was redrawn
    const Mesh* boneMesh() const { return bone_.get(); }  // null when the scene has bones
    // With bones: each bone's surface (the order of the bone list).
    const std::vector<std::shared_ptr<const Mesh>>& boneSurfaces() const { return boneSurfaces_; }
    // The surfaces the 3D view draws (one per shown bone, or the CT's one surface).
    std::vector<render::SurfaceItem> surfaces() const;
    int remeshes() const { return remeshes_; }  // surfaces built for a new bone level
    const Solver& solver() const { return solver_; }
    // The pose whose DRR the user pane shows: the solver's best so far while it runs.
    const Pose& shownUserPose() const;
    RenderBackend& backend() override { return backend_; }
    std::optional<WidgetRect> widgetRect(const std::string& id) const override { return ui_.rect(id); }
    const render::SceneRenderer& sceneRenderer() const { return *sceneRenderer_; }
    FramePresenter& presenter() { return presenter_; }  // what each frame redraws

  private:
    void installLoadResult(SceneLoader::Result result);
    void processRequests();
    void refreshMatchTexts();
    void updateImages();
    void updateUserDrr(const DrrKey& key);
    // Shows a finished user image (`inputTime`: when the input that asked for it was read).
    void showUserDrr(const DrrKey& key, DrrRender render,
                     std::chrono::steady_clock::time_point inputTime);
    ImageEdgeLetters edgeLetters(const Pose& pose) const;  // of the image at `pose` (mode's)
    void newReference();
    // Solve (from the user's pose) or Find (the camera's pose from nothing: X-ray mode, the camera).
    void startSolve(bool find = false);
    Image xrayReference();  // the reference as Solve and Find compare with it (full film, realistic or not)
    void startXraySolve(int method);
    void startFind(int method);  // the camera's pose found from nothing (find/ViewFinder)
    void recordAttempt(MatchOutcome outcome);  // counts it as the latest, best-so-far tracked
    void pollSolver();
    // `factor`, `fullTriangles`: the display surface's coarsening (scene/DisplaySurface.h).
    void showBone(std::shared_ptr<const Mesh> mesh, double level, int factor = 1,
                  std::size_t fullTriangles = 0);
    void remesh();
    // AppBones.cpp: the bones of the scene (shown, moved), the joint angles and the flex game.
    void installBones();
    ObjectStates userObjects() const;       // the user's DRR: the list's visibility and motions
    ObjectStates referenceObjects() const;  // the reference: unmoved, or the hidden flexion
    // The realistic reference (AppState::realistic): whether the scene allows it, its spectrum
    // when shown (empty: a DRR), and the objects the reference image is made of then.
    bool realisticReferenceAvailable() const;
    std::string referenceSpectrum() const;
    ObjectStates shownReferenceObjects() const;
    const Pose& referenceCamera() const;    // the flex game's reference follows the user's camera
    void updateBones();                     // live joint angles, once per frame
    void newFlex();
    void checkFlex();
    void growAt(const std::array<int, 4>& pixel);  // region growing from a clicked pixel
    // AppLabels.cpp: bones from a label map or components, built on bonesLoader_.
    void startLabels(const std::string& labels, const std::string& table);
    void startComponents();
    void pollLabels();
    void installLabelledBones(BonesLoader::Result result);
    void replaceBones(std::shared_ptr<const SceneBones> bones);  // a new scene with them
    // A bone game's verdict on `motion` of `bone` (the knee's tibia: on the joint angles; any
    // other: its motion numbers against the game's truth). Throws at the knee's gimbal lock.
    MatchVerdict judgeBoneMotion(int bone, const BoneMotion& motion) const;
    int boneToSolve() const;  // the bone Solve registers alone, or -1: the camera
    void startBoneSolve(int method, int bone);  // registerBone on the worker
    void judgeBoneSolve();                      // ... its answer judged as a Check
    // The scene shown: `plain` (without the bone-only threshold), or a copy with bone-only
    // DRRs when AppState::drrThreshold is on (a new generation, same poses).
    void showScene(std::shared_ptr<LoadedScene> plain);
    void applyDrrThreshold();

    RenderBackend& backend_;
    AppOptions options_;
    AppState state_;
    Ui ui_;
    SceneLoader loader_;
    std::shared_ptr<LoadedScene> scene_;
    // The scene without the bone-only threshold (as loaded, plus grown bones); scene_ is it,
    // or its copy with bone-only DRRs (AppState::drrThreshold).
    std::shared_ptr<LoadedScene> plainScene_;
    // The bone surface shown: the scene's until the user picks another level.
    std::shared_ptr<const Mesh> bone_;
    // With bones: their surfaces (the scene's until the user picks another level), same order.
    std::vector<std::shared_ptr<const Mesh>> boneSurfaces_;
    std::uint64_t boneGeneration_ = 0;  // changes with every new surface (GPU upload key)
    int remeshes_ = 0;
    DrrCache referenceCache_{2}, userCache_{6};
    Image referenceDrr_, userDrr_;
    Mask referenceDataMask_, userDataMask_;  // slice mode: pixels with data; empty for DRRs
    std::uint64_t referenceVersion_ = 0, userVersion_ = 0;
    std::optional<DrrKey> referenceKey_, userKey_;  // what referenceDrr_ / userDrr_ hold
    // The user's image: the newest asked for (on the worker unless cached), numbered so an older
    // one finishing late never replaces a newer one on screen.
    struct UserDrrRequest {
        std::shared_ptr<const LoadedScene> scene;
        DrrKey key;
        int threads = 0;
        std::uint64_t number = 0;
        std::chrono::steady_clock::time_point inputTime;
    };
    struct UserDrrResult {
        UserDrrRequest request;
        DrrRender render;
        std::string error;
    };
    std::optional<DrrKey> userRequested_;
    std::uint64_t userRequests_ = 0, userShownNumber_ = 0;
    std::chrono::steady_clock::time_point frameInputTime_;  // this frame's input was read
    std::optional<std::chrono::steady_clock::time_point> userShownInputTime_;  // shown this frame
    std::uint64_t nextSeed_ = 1;
    bool firstScene_ = true;
    int exactUserRenders_ = 0, coarseUserRenders_ = 0;
    std::unique_ptr<render::Texture> referenceTexture_, userTexture_, compareTexture_;
    std::unique_ptr<render::SceneRenderer> sceneRenderer_;
    FramePresenter presenter_;
    // What the textures show, to re-upload only on change.
    struct DisplayKey {
        std::uint64_t reference = 0, user = 0;
        float window = 0, level = 0;
        CompareMode compare = CompareMode::Difference;
        bool operator==(const DisplayKey&) const = default;
    } shownKey_;
    render::WindowLevel autoWindow_;  // the reference's full range (auto window) ...
    std::uint64_t autoWindowOf_ = 0;  // ... of this reference version (0: none yet)
    struct SceneKey {
        std::uint64_t generation = 0, boneSurface = 0;
        std::array<double, 6> pose{};
        float azimuth = 0, elevation = 0, zoom = 0, panX = 0, panY = 0;
        bool bone = false, box = false, apparatus = false;
        glm::ivec2 size{0};
        std::uint64_t film = 0;
        float window = 0, level = 0;
        bool fast = false;
        ImagingMode mode = ImagingMode::Xray;
        ObjectStates objects;  // the bones shown and their poses
        bool operator==(const SceneKey&) const = default;
    } sceneKey_;
    int sceneDraws_ = 0;
    BonesLoader bonesLoader_;  // joined before the scenes it reads go
    std::unique_ptr<NewestWins<UserDrrRequest, UserDrrResult>> userDrrWorker_;
    // Last: destroyed first, so its worker (which holds the scene) is joined before the rest.
    Solver solver_;
    std::uint64_t solveVersion_ = 0;
    bool solveJudged_ = false;            // the finished result's mTRE was computed
    std::optional<Pose> solveShownPose_;  // best-so-far pose on screen while solving
    // A bone solve: which bone, and the numbers its search moves (to read its answer).
    int solveBone_ = -1;
    std::shared_ptr<const ObjectPoseParameterization> solveBoneParameterization_;
    std::uint64_t solveShownFrame_ = 0;
};

}  // namespace fm::app

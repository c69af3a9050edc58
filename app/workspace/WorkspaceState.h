#pragma once
// The real-X-ray workspace of the app (docs/app.md, "Real radiographs"), as plain data: the
// objects, the current frame, every frame's pose of every object, the six pose controls, what
// the panes show, and the requests the UI makes. The UI panes read and edit it; WorkspaceApp
// carries out the requests; WorkspaceModel computes every image. Nothing here draws.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "scene/RigidTransform.h"
#include "xray/AnswerCheck.h"
#include "state/AppState.h"
#include "state/OpenRequest.h"
#include "workspace/PoseHistory.h"
#include "workspace/TrackState.h"

namespace fm::app {

// Which frame the six pose controls move the selected object in.
enum class PoseFrame {
    Camera,  // a camera's frame: x, y along the film, depth along the view, rotations about
             // the film axes and the view (ObjectPoseParameterization), the default for one camera
    World,   // the calibration's world: x, y, z and rotations about its axes, the default for
             // several cameras (biplane)
};

// What is drawn over (or beside) each radiograph.
enum class ModelImage { Outline, Drr };

// The 3D view the workspace opens with (and Reset view gives): about the objects, the cameras'
// sources at the edge of the view.
inline View3d defaultRigView() {
    View3d v;
    v.zoom = 1.0f;
    return v;
}

struct WorkspaceObject {
    std::string name;
    std::string kind;  // "mesh, 12412 triangles", "volume 120 x 80 x 200"
    bool visible = true;
    std::array<float, 3> color{};
    bool hasMasks = false;  // label masks: the silhouette IoU is shown
};

// The six controls of the selected object: values in the frame `frame` (camera `camera`),
// relative to the object's pose `reference` at which the three angles are 0. Rebased (reference
// = the current pose, angles 0, ranges centred) whenever the object, the frame index, the pose
// frame or camera changes, or the pose is replaced (Solve's answer, a load).
struct PoseControls {
    int object = -1, frameIndex = -1, camera = 0;
    PoseFrame frame = PoseFrame::Camera;
    RigidTransform reference;
    std::array<double, 6> values{};
    std::array<double, 6> shown{};  // what the pose was made from (edits are told by a change)
    std::array<ParameterSpec, 6> specs{};
    int selected = 0;  // the control the arrow keys nudge
};

// The Solve of the selected object in the current frame, copied from the worker each frame.
struct WorkspaceSolve {
    bool running = false, finished = false, stopped = false;
    std::string error;
    int object = -1, frame = -1;
    std::string stage;
    int evaluations = 0, budget = 0;
    double seconds = 0.0;
    std::optional<RigidTransform> start, result;
    double similarity = 0.0;  // single camera: -cost at the finest level; biplane: summed
    std::vector<double> viewCosts;
    // Against the start, in camera 1's frame (the pivot's in-plane and depth parts).
    double inPlaneMm = 0.0, depthMm = 0.0, rotationDeg = 0.0;
    std::optional<double> iou, startIou;  // against the object's mask, when there is one
    std::string summary;                  // one line: how it ended
    // How far the answer can be trusted (xray/AnswerCheck.h): only an ok answer is shown as good.
    using Check = AnswerVerdict;
    Check check = Check::Doubtful;
    std::string checkText;  // "ok: 2 of 2 searches from different starts end here", "doubtful: ..."
    std::string uncertaintyText;  // per coordinate, camera 1's frame; "" when not measured
    // Find (no start): the answer and the finder's other answers, best first; the one shown.
    bool find = false;
    std::vector<RigidTransform> candidates;
    std::vector<double> candidateSimilarity;
    int candidate = 0;
};


struct WorkspaceRequests {
    bool solve = false, stopSolve = false;
    bool find = false;                // Find: the selected object's pose with no start
    std::optional<int> candidate;     // show Find's candidate k
    bool undo = false;
    bool save = false;
    std::optional<int> frame;  // go to this frame
    bool preparation = false;  // a camera's invert / logTransform changed
    bool resetView = false;
};

struct WorkspaceState {
    std::string title;   // "trial jtml-knee" or the radiograph's file name
    std::string source;  // the trial file, or the reference image
    std::vector<std::string> cameraNames;
    std::vector<WorkspaceObject> objects;
    int selected = 0;
    bool allObjects = true;  // draw every shown object's image, or the selected one's only
    int frame = 0, frameCount = 1;
    std::vector<std::vector<std::string>> frameNames;  // [camera][frame]: the file (or page)
    // poses[frame][object]: worldFromObject (the object's own frame to the world) where one was
    // set (keyframe, edit, Solve, Track, load); nullopt: none, and Save writes NaN. What a frame
    // shows without one is derived (ShownPose.h), never written here.
    std::vector<std::vector<std::optional<RigidTransform>>> poses;
    std::vector<RigidTransform> placements;  // per object: shown where no frame sets a pose
    PoseFrame poseFrame = PoseFrame::Camera;
    int poseCamera = 0;
    PoseControls controls;

    ModelImage modelImage = ModelImage::Outline;
    bool sideBySide = false;  // radiograph and model image side by side, not over each other
    // Each camera's preparation's invert and log, toggled in the Objects pane (what Solve and
    // Track compare; a trial's Save keyframes writes them into the trial JSON); each change a new version (the panes are
    // made again).
    struct CameraValues {
        bool invert = false, logTransform = false;
    };
    std::vector<CameraValues> cameraValues;
    std::uint64_t preparationVersion = 0;
    std::string rawHint;  // "" or why the radiograph looks raw (RawImageHint.h)
    int enlargedCamera = -1;  // a camera's pane shown over the whole window (-1: none)
    std::vector<DisplaySettings> display;  // per camera: window/level of the radiograph
    ImageView imageView;                   // shared zoom and pan of the camera panes
    PixelReadout readout;
    View3d view = defaultRigView();

    OpenPanel open;                          // the Open window (ui/OpenWindow.h)
    std::optional<OpenRequest> openRequest;  // ... what it asked the shell to open
    WorkspaceSolve solve;
    PoseHistory undo;         // Undo: the poses before each change
    std::string undoMessage;  // what the last Undo undid
    std::string savePath;  // .tra (trial) or .jts (one model) / .tra (several) for one image
    std::string saveMessage;
    bool saveFailed = false;
    std::string error;    // the last failure (kept until the next success)
    std::vector<std::string> warnings;
    std::optional<double> iou;  // the selected object's silhouette IoU against its mask, now
    bool showTimings = true;
    double imageMs = 0.0;  // the last pane images
    bool interacting = false;
    std::uint64_t frameCounter = 0;
    WorkspaceRequests requests;
    // The trial controls (play, keyframes, Track forward / back, the pose plot): trials only.
    bool tracking = false;
    TrackState track;
};

}  // namespace fm::app

#pragma once
// Everything the app shows and the user edits, as plain data. The UI panels read and edit it;
// the App turns requests into engine calls; nothing here draws or computes.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "geometry/PatientDirection.h"
#include "geometry/Pose.h"
#include "match/MatchVerdict.h"
#include "match/ReferenceDraw.h"
#include "state/OpenRequest.h"

namespace fm::app {

// The six parameters in Pose::toArray() order.
enum Parameter {
    kOffsetX = 0,
    kOffsetY,
    kOffsetZ,
    kAzimuth,
    kElevation,
    kRotation,
    kParameterCount
};

struct ParameterSpec {
    const char* name;  // "x offset", "azimuth", ...
    const char* unit;  // "mm" or "deg"
    double min, max;
};

// The 2011 ranges for the angles; the translation range is set per volume (fits the CT).
std::array<ParameterSpec, kParameterCount> parameterSpecs(double translationRangeMm);

// Throws fm::Error naming the first parameter of `pose` outside its slider range. A pose given
// on the command line must be one the sliders can reach: it is refused, not silently clamped.
// `what` names the pose in the message ("--reference-pose").
void checkPoseWithinSliders(const Pose& pose, double translationRangeMm, const std::string& what);

enum class CompareMode { Difference, Overlay, Checkerboard };

// Zoom and pan of the 2D images, shared by the reference, user and compare images so that
// they stay side by side at the same place (texture coordinates of the view's centre).
struct ImageView {
    float zoom = 1.0f;  // 1: the whole image
    float centerU = 0.5f, centerV = 0.5f;
};

// The pixel under the mouse in a 2D pane (position and value, in the image's units).
struct PixelReadout {
    bool valid = false;
    std::string pane;  // "image:reference", "image:user"
    int col = 0, row = 0;
    float value = 0.0f;
    bool hasData = true;  // false: a slice pixel outside the volume (value meaningless)
};

struct DisplaySettings {
    bool autoWindow = true;  // window/level follow the reference DRR's range
    float window = 1.0f;     // width of the displayed value range
    float level = 0.5f;      // centre of the displayed value range
    CompareMode compare = CompareMode::Difference;
};

// The orbit camera of the 3D view (degrees around the isocenter; zoom 1 frames the scene).
struct View3d {
    float azimuthDeg = 35.0f;
    float elevationDeg = 25.0f;
    float zoom = 1.6f;
    float panX = 0.0f, panY = 0.0f;  // view centre moved along the screen, in scene radii
    bool showBone = true;
    bool showBox = true;
    bool showApparatus = true;  // source, film and ray cone
    static View3d defaults() { return {}; }
    // What Reset view shows: the whole set-up (source, CT box and film) framed, not panned.
    static View3d framed() {
        View3d v;
        v.zoom = 1.0f;
        return v;
    }
};

// What Match reported, kept for display (all numbers come from engine/match).
struct MatchOutcome {
    bool matched = false;
    MatchVerdict judged;                           // the engine's verdict
    std::array<double, kParameterCount> error{};   // user minus reference, per parameter
    std::array<int, kParameterCount> direction{};  // +1 too high, -1 too low, 0 within tolerance
    int furthestParameter = -1;                    // the one furthest off (-1 when matched)
    double poseErrorMm = 0.0;                      // mean target registration error over the bone
    double ncc = 0.0;                              // image similarity (information only)
    int attempt = 0;                               // which attempt this was
    bool assisted = false;  // made from the computer's answer (Apply solution): not the user's own
    // The texts shown, worded by the hint mode; numbers only after a match or Reveal
    // (App::refreshMatchTexts).
    std::string verdict;                                  // one line
    std::array<std::string, kParameterCount> hintCells;   // per parameter
    bool numbersShown = false;
};

struct LoadStatus {
    bool loading = false;
    std::string requestedSpec;  // what is being loaded
    std::string stage;          // "reading", "preparing DRR volume", "meshing"
    float progress = 0.0f;      // 0..1 over the stages
    double elapsedSeconds = 0.0;
    std::string loadedSpec;  // the scene on screen
    std::string summary;     // dims, spacing, triangles of the scene on screen
    std::string error;       // the reader's message when the last load failed
};

struct Timings {
    double userDrrMs = 0.0;      // last user DRR render
    bool userDrrCoarse = false;  // ... and whether it was the coarse preview
    double lastExactMs = 0.0;
    double lastCoarseMs = 0.0;
    double referenceDrrMs = 0.0;
    double frameMs = 0.0;  // CPU time of the last whole frame
    double meshMs = 0.0;   // last bone surface (marching cubes)
    int coarseFactor = 2;  // detector downsampling while dragging
    // Input latency of the last user DRR shown: from reading the input that asked for it to the
    // end of the frame that showed it; and how many were shown so far.
    double userDrrLatencyMs = 0.0;
    int userDrrsShown = 0;
};

// The Solve section: the computer's search, as the App copies it from the Solver each frame.
struct SolveStatus {
    int method = 3;  // index into kSolveMethods (default CMA-ES)
    bool running = false;
    bool find = false;      // a search with no start (Find), not from the user's pose (Solve)
    bool finished = false;  // a result is shown (completed or stopped)
    bool stopped = false;
    std::string error;
    std::string stage;
    int level = 0, levelCount = 0, evaluations = 0, budget = 0;
    std::vector<float> costHistory;  // best cost per batch of the current level
    Pose bestPose, candidate;
    double elapsedMs = 0.0;
    // When finished: the final pose judged like a user's attempt (engine/match); the numbers
    // (mTRE, error per parameter) are shown only once the reference is revealed.
    bool matched = false;
    Closeness closeness = Closeness::Far;
    double poseErrorMm = 0.0;
    std::array<double, kParameterCount> error6{};  // solution minus reference, per parameter
    bool applied = false;                          // the user took the solution onto the sliders
    // A bone registered alone (the sliders' target in a bone game): its index and the motion
    // found; then error6 is in the knee's joint angles (kneeAngleArray order) for the knee's
    // tibia, else in the bone's motion numbers, and bestPose is unused.
    int bone = -1;
    std::array<double, 6> boneMotion{};
};

// The global search methods offered by the Solve combo (SearchMethod names, engine order).
inline constexpr const char* kSolveMethods[] = {"mc", "pso", "bees", "cmaes"};
inline constexpr const char* kSolveMethodLabels[] = {"Monte Carlo", "Particle swarm", "Bees",
                                                     "CMA-ES"};
inline constexpr int kSolveMethodCount = 4;

// What the panes show: X-ray images (DRRs) or planar slices of the volume (the MRI slice mode,
// docs/mri.md). The same six parameters, game and search either way.
enum class ImagingMode { Xray, Slice };

// Things the UI asks for; the App consumes them after the UI pass.
struct Requests {
    bool newReference = false;
    bool match = false;
    bool solve = false;          // start the search (stops a running one first)
    bool find = false;           // the same with no start: the pose found from nothing
    bool stopSolve = false;      // end it, keeping the best pose so far
    bool applySolution = false;  // set the sliders to the solver's pose
    bool reveal = false;
    bool resetView = false;
    bool remesh = false;  // rebuild the bone surface at BoneSurface::level
    bool boneThreshold = false;  // apply DrrThreshold (toggled, or its level edited)
    std::optional<std::string> loadVolume;
    std::optional<ImagingMode> mode;  // switch X-ray / MRI slice (a new reference in that mode)
    bool newFlex = false;    // start the flex game, or draw another hidden flexion
    bool checkFlex = false;  // judge the tibia's motion against the hidden one
    bool endFlex = false;
    // Bones from a label map (path, table: may be empty), or the CT's connected components.
    std::optional<std::array<std::string, 2>> loadLabels;
    bool components = false;
    // A click on your DRR while growing: column, row and the image's width and height.
    std::optional<std::array<int, 4>> growAtPixel;
};

// The bone surface of the 3D view: the level the user asks for, and what is shown.
struct BoneSurface {
    float level = 300.0f;                    // asked for (HU for CTs); rebuilt when a drag ends
    float minLevel = 0.0f, maxLevel = 1.0f;  // the volume's value range
    double shownLevel = 0.0;                 // the level of the surface drawn
    std::size_t triangles = 0;               // ... and its size
    int displayFactor = 1;                   // 1, or n: drawn from n^3 block means (DisplaySurface)
    std::size_t fullTriangles = 0;           // the full-resolution surface's size
};

// One bone of the scene in the bone list (app/scene/SceneBones: the articulated knee).
struct BoneView {
    std::string name;
    std::array<float, 3> color{};  // its surface's colour in the 3D view, and its list swatch
    bool visible = true;           // shown in both DRRs and in the 3D view
    // Its motion from where the CT has it (engine/bones BoneMotion: tx, ty, tz mm; turns about
    // world x, y, z deg through the bone's pivot), edited by the sliders when it is their target.
    std::array<double, 6> motion{};
};

// The bone game: the hidden reference moves one bone from where the CT has it, seen from the
// user's camera; the user (or Solve) must find that motion. For the knee it is the flex game
// (the tibia moved relative to the femur, judged on the Grood-Suntay angles); for any other
// bones the move game (the chosen bone, judged on its six motion numbers).
struct FlexGame {
    bool active = false;
    Difficulty difficulty = Difficulty::Easy;
    int bone = -1;                         // the bone the reference moves (knee: the tibia)
    std::array<double, 6> hiddenMotion{};  // ... by this motion (BoneMotion)
    // The knee: the reference knee's angles (engine kneeAngleArray order: 3 mm, then 3 deg).
    std::array<double, 6> referenceAngles{};
    bool revealed = false;
    int attempts = 0;
    std::optional<MatchOutcome> outcome;  // the last Check, worded like the camera game's
    bool outcomeIsStale = false;          // the bone moved since
    std::array<double, 6> motionAtCheck{};  // ... from this motion
};

struct BonesState {
    std::vector<BoneView> list;  // empty: the CT is one object
    bool restVisible = true;     // everything that is not one of the bones (soft tissue)
    int sliderTarget = -1;       // -1: the camera (the 2011 parameters); else a bone of `list`
    bool isKnee = false;         // femur and tibia with anatomical frames: joint angles
    bool canGrow = true;         // no bones yet, or grown ones (not from labels or the knee)
    bool anglesValid = false;
    // The user's knee, live (kneeAngleArray order: medial shift, anterior drawer, distraction
    // mm; flexion, varus, internal rotation deg).
    std::array<double, 6> angles{};
    FlexGame flex;
    // The bone list unfolded: folded while a bone game runs (its hints need the room), the user
    // may unfold it.
    bool listUnfolded = true;
    // A bone's Solve also compares a second view of the reference, 90 deg around in azimuth
    // (as biplane fluoroscopy): one view hardly sees a motion along its rays.
    bool biplaneSolve = false;
    // Region growing: the next click on your DRR grows a bone from the voxel it hits.
    bool growArmed = false;
    std::string growMessage;  // what the last grow did, or why it could not
};

// Bone surfaces and swatches, in the order of the bones.
inline constexpr std::array<std::array<float, 3>, 6> kBoneColors{{{0.93f, 0.89f, 0.80f},
                                                                   {0.55f, 0.75f, 0.98f},
                                                                   {0.98f, 0.62f, 0.42f},
                                                                   {0.60f, 0.90f, 0.55f},
                                                                   {0.85f, 0.62f, 0.92f},
                                                                   {0.95f, 0.85f, 0.40f}}};

// The slider ranges of a bone's motion (shifts along and turns about the world axes).
std::array<ParameterSpec, kParameterCount> boneMotionSpecs();

// Bone-only DRRs for real CTs, whose DRRs otherwise show mostly soft tissue: voxels whose
// stored value (HU for CTs) is below `level` are left out of the DRR volume, so of both images,
// Match and Solve. Off by default; the level starts at the scene's bone level on every load.
// The reference image as a realistic radiograph (engine/spectral: a tube spectrum through the
// CT's materials, scatter, blur, noise) instead of a DRR; X-ray mode on a CT in HU, the whole CT.
struct RealisticReference {
    bool enabled = false;
    bool available = false;      // the scene has HU (and no bones are shown)
    std::string spectrum = "80";  // `drr --spectrum` text
};

struct DrrThreshold {
    bool enabled = false;
    float level = 300.0f;
    bool valuesInHu = true;  // the volume's values are HU (else "value": stored units)
    double prepareMs = 0.0;  // the last preparation of the thresholded DRR volume
};

// Bones from a label map or the CT's connected components (the Bones tab, or --labels on the
// command line), built on a worker; the scene stays as it was until they are ready.
struct LabelsLoad {
    std::string pathField, tableField;  // what the user typed (label map, label table)
    bool loading = false;
    std::string what, stage;  // what is being built, and its stage
    float progress = 0.0f;
    double elapsedSeconds = 0.0;
    std::string loaded;  // where the bones shown come from ("" : none loaded)
    std::string error;   // why the last one failed (nothing changed)
};

struct AppState {
    // The Open window (a trial or a radiograph: the workspace; the shell opens it) and what it
    // asked for.
    OpenPanel open;
    std::optional<OpenRequest> openRequest;
    // Chosen on load (slices for an MRI file, X-rays otherwise) and by the user.
    ImagingMode mode = ImagingMode::Xray;
    bool userSliceEmpty = false;  // slice mode: the user's plane misses the volume (no data)
    Pose userPose;
    Pose referencePose;
    bool referenceRevealed = false;
    int attempts = 0;
    std::optional<double> bestUserPoseErrorMm;  // the user's best mTRE over this reference
    // The sliders took the computer's answer (Apply solution) for this reference: a match from
    // there is assisted, never counted as the user's own.
    bool assisted = false;
    std::optional<MatchOutcome> match;
    bool matchIsStale = false;    // the pose moved since the last Match
    std::string referenceSource;  // "random around AP (medium)", "given on the command line"
    HintWording hintWording = HintWording::Direction;
    Difficulty difficulty = Difficulty::Medium;  // of the next New reference image

    double translationRangeMm = 100.0;
    // The judge's tolerances (engine/match), shown with the verdict and in Help.
    double toleranceOffsetMm = 0.0, toleranceAngleDeg = 0.0;
    DisplaySettings display;
    ImageView imageView;
    PixelReadout readout;
    bool compareEnlarged = false;
    // Orientation letters at the image edges (engine/geometry PatientDirection), per pose.
    ImageEdgeLetters referenceEdges, userEdges;
    View3d view;
    BoneSurface bone;
    DrrThreshold drrThreshold;
    RealisticReference realistic;
    bool showHelp = false;
    // The parameter the arrow keys nudge (KeyboardNudge): Up/Down or a click select it.
    int selectedParameter = kOffsetX;
    bool showTimings = true;  // off for golden images: timings differ run to run
    std::string volumePathField;
    LoadStatus load;
    Timings timings;
    SolveStatus solve;
    BonesState bones;
    LabelsLoad labels;

    bool interacting = false;         // a parameter slider is being dragged: coarse preview
    bool coarseWhileDragging = true;  // off: exact DRRs even while dragging (for measuring)
    std::uint64_t frame = 0;
    Requests requests;
};

}  // namespace fm::app

#pragma once
// Tracking one bone through a sequence: each frame is a registration of the bone's pose in all
// cameras at once (the cost is the sum over the cameras that see the bone), started from a
// guess made from the frames already done (InitialGuess.h).
//
// Per frame (numbered as in Tracker::trackFrame):
//   1. the start pose: the guess for this frame
//   2. the views: a camera takes part only if the bone's box, projected at the start pose,
//      lies mostly on its image (minInViewFraction); a frame seen by one camera is tracked in
//      that one, keeping the predicted depth, and reported as single-view; seen by none, it is
//      skipped
//   3. the registration: the bone's pose in the first taking camera's frame
//      (ObjectPoseParameterization, pivot at the bone's centre), search around the start;
//      (coarse levels only), 3b. a fresh Nelder-Mead simplex at full resolution from its result
//   4. the record: pose, cost per camera (NaN where not used), evaluations, time
//   5. how sure it is: the cost's curvature at the answer (search/PoseUncertainty, in the first
//      taking camera's frame) and the verdict (xray/AnswerCheck): the similarity against what
//      the bone scored in its last good frames (or at the keyframe's own pose in its frame, when
//      the answer stays by it); with neither, a second search from a start drawn around the
//      start must end at the same pose (within 1 mm and 2 deg)
// run() searches a frame that is not ok once more, wider (TrackSettings::researchScale), and
// on a lost one stops, searches again, goes on, or (a frame still not ok) finds the bone in that
// frame with no start and registers it from there, as TrackSettings::onLost says; a lost pose is never a later
// frame's start.
// Frames inside a run stay sequential: each one starts from the poses before it.
// Deterministic: frame k's seed is a function of (seed, k) only, so a resumed run gives the
// same poses as an uninterrupted one.
#include <atomic>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "scene/Scene.h"
#include "search/Registration.h"
#include "track/InitialGuess.h"
#include "xray/AnswerCheck.h"

namespace fm {

// A frame's prepared radiographs, one view per camera that has an image of it (camera index set
// in each view). Throws fm::Error for a frame it cannot read: the tracker reports and skips it.
using FrameViews = std::function<std::vector<RegistrationView>(int frame)>;

// What a run does with a frame whose verdict is lost: Find also searches it again (as Search),
// and then a frame still not ok (lost, or doubtful: a jump between sparse frames may leave either)
// is found with no start (TrackSettings::findFrame) and registered from the found pose; the
// better record is kept (not in a keyframe's frame: its start is the user's or a find's pose).
enum class OnLost { Stop, Search, Continue, Find };
const char* toString(OnLost onLost);  // "stop", "search", "continue", "find"
// fm::Error naming `option` for anything else.
OnLost parseOnLost(const std::string& text, const char* option);

// A bone found in one frame with no start (issue 29; the caller's find, e.g. findTrialBone): the
// pose when the find's verdict is ok, else none; its verdict line either way.
struct FrameFind {
    std::optional<RigidTransform> pose;
    std::string verdictText;
};
using FindFrame = std::function<FrameFind(int frame, const std::atomic<bool>* stop)>;

struct TrackSettings {
    RegistrationSettings registration = defaultTrackingRegistration();
    // The similarity follows the tracked bone's model (defaultSimilarityFor: edge distance for
    // meshes, gradient NCC for volumes) instead of registration.similarity. A mesh's chords
    // would be traced for gradient NCC: 5.3 s a frame on the JTML femur against ~0.5 s.
    bool similarityByModel = true;
    InitMode init = InitMode::Extrapolate;
    // A camera takes part when at least this fraction of the bone's projected box lies on its
    // image at the start pose.
    double minInViewFraction = 0.5;
    // Step 3b: the full-resolution search, a fresh Nelder-Mead simplex around the coarse
    // levels' answer with this radius (mm and deg: the coarse levels leave up to 0.3 mm and
    // 1.3 deg, docs/tracking.md) and budget (0 = none: the coarse answer is the frame's).
    // A fresh simplex of that size moves there in fewer evaluations than a polish that
    // shrinks on from the coarse levels' simplexes, and it does not stall where those have
    // collapsed along one direction (the rotation about a long bone's axis).
    double refineRadius = 1.0;
    int refineEvaluations = 150;
    // A frame seen by one camera keeps the predicted depth along that camera's view (searched
    // within this radius, mm): one view hardly constrains depth, and a depth that drifts would
    // be carried into the next frames' starts by the extrapolation.
    double singleViewDepthRadius = 0.25;
    // Step 5: the per-frame uncertainty (73 evaluations at full resolution: 0.62 of the femur's 2.2 s
    // a frame on an AVX2 machine, docs/benchmarks.md).
    bool uncertainty = true;
    // Step 5: with no reference, a second search confirms the answer (or not).
    bool confirmWithoutReference = true;
    // A frame that is not ok is searched again from the same start with the search radii and
    // budgets times researchScale (another seed); the better verdict (then similarity) is kept.
    // Lost frames only as onLost says (Search: the default).
    double researchScale = 2.0;
    OnLost onLost = OnLost::Search;
    // OnLost::Find's find (required then, refused otherwise: the Tracker's constructor throws).
    FindFrame findFrame;

    // Local search around the start: Autoscoper's PSO box is +-3 mm / +-3 deg; CMA-ES global
    // search at 1/4 resolution, Nelder-Mead polish at 1/4 and 1/2, cropped to the bone (then
    // step 3b at full resolution).
    static RegistrationSettings defaultTrackingRegistration();
};

struct FrameRecord {
    enum class Status { Tracked, NoStart, NotInView, BadFrame, Stopped };
    int frame = 0;
    Status status = Status::NoStart;
    std::string note;                             // "biplane", "single view: camera 2", the error
    std::optional<RigidTransform> worldFromBone;  // when tracked
    std::vector<double> viewCost;                 // per camera, NaN when not used
    int camerasUsed = 0;
    int evaluations = 0;
    double seconds = 0.0;
    EvaluationProfile profile;  // where its searches' evaluations spent their time
    // How sure it is (tracked frames): never ok without something that confirms it.
    AnswerVerdict verdict = AnswerVerdict::Doubtful;
    std::string verdictText;                     // "ok: similarity 0.99 of the last good frames' ..."
    AnswerEvidence evidence;  // its uncertainty (first taking camera's frame) and similarity ratio
    // The uncertainty along the bone's own axes (its volume's x, y, z; mm and deg), when measured.
    SearchPoint boneFrameSd{};
    int searches = 0;                            // 2 when searched again
    // OnLost::Find: the frame was not ok after its searches and the bone was searched for with no
    // start; the find's verdict line (the record is the registration from its pose when that
    // one is better).
    std::optional<std::string> found;
    // -cost summed over the cameras it used (0 when none): what two records of a frame compare by.
    double similarity() const;
    // A pose to keep: tracked and not lost (a lost pose is neither written nor a later start).
    bool answered() const { return status == Status::Tracked && worldFromBone && verdict != AnswerVerdict::Lost; }
};

// A camera's cost as the track CSV holds it (kStoredCostDecimals decimals). The frames after an
// ok one are judged against its costs in this form, so that a resumed run, which reads the kept
// frames' costs back from the CSV, judges them with the very numbers an uninterrupted run used
// (as storedObjectPose does for the poses the next frames start from).
inline constexpr int kStoredCostDecimals = 6;
double storedCost(double cost);

// What a frame is judged against.
struct FrameContext {
    // Per camera, the similarity (-cost) the bone scored in its last good frames (NaN: unknown).
    std::vector<double> referenceSimilarity;
    // The start is the user's pose for this very frame (a keyframe): when the answer stays
    // within the agreement bounds of it, the keyframe's similarity is the reference.
    bool startIsKeyframe = false;
    // This search is itself the confirmation of another (no confirmation of its own).
    bool confirming = false;
};
const char* toString(FrameRecord::Status status);

class Tracker {
  public:
    // `bone` names the scene object to track; the others stay where they are (and are seen).
    // Throws fm::Error if there is no such object or no camera, or when settings.findFrame is
    // missing for OnLost::Find or given for another.
    Tracker(Scene scene, std::string bone, FrameViews frames, TrackSettings settings);

    // One frame from `start` (steps 2-4). `progress` (optional) is called as the registration
    // goes, over both its searches: evaluations so far out of the frame's budget, and the level
    // among the coarse levels and the full-resolution one (the app's biplane Solve shows it).
    FrameRecord trackFrame(int frame, const RigidTransform& start,
                           const std::atomic<bool>* stop = nullptr,
                           const RegistrationCallback& progress = {},
                           const FrameContext& context = {}) const;

    // Tracks `frames` in the given order. `tracked` holds poses already found (a resumed run)
    // and receives every new one; `keyframes` are the user's. afterFrame is called after every
    // frame (to write results at once). Stops after the current frame when *stop is set.
    // A frame of `frames` already in `tracked` (a resumed run's) is not tracked again; its record
    // in `kept` (the verdict and costs its run gave it, when known) judges the frames after it as
    // it did in that run, so the resumed run's poses and verdicts are the uninterrupted run's.
    void run(const std::vector<int>& frames, const std::map<int, RigidTransform>& keyframes,
             std::map<int, RigidTransform>& tracked,
             const std::function<void(const FrameRecord&)>& afterFrame,
             const std::atomic<bool>* stop = nullptr, const std::map<int, FrameRecord>& kept = {}) const;

    // The fraction of `bone`'s projected box (at `pose`) that lies on camera `camera`'s image
    // (0 when a corner is behind the source).
    double inViewFraction(std::size_t camera, const RigidTransform& pose) const;

    const Scene& scene() const { return scene_; }
    const TrackSettings& settings() const { return settings_; }

  private:
    // `frames` is where the frame's images come from: frames_, or the images already read for it
    // (a confirming or a repeated search reads nothing again).
    FrameRecord trackFrameWith(const TrackSettings& settings, const FrameViews& frames, int frame,
                               const RigidTransform& start, const std::atomic<bool>* stop,
                               const RegistrationCallback& progress, const FrameContext& context) const;
    // OnLost::Find on a frame not ok after its searches: the find, then the registration from its
    // pose; the better of that and `searched`, with the find's line.
    FrameRecord findAndTrack(const FrameViews& frames, int frame, FrameRecord searched, const std::atomic<bool>* stop,
                             FrameContext context) const;
    Scene scene_;
    std::size_t bone_ = 0;
    FrameViews frames_;
    TrackSettings settings_;
};

// frames "A:B[:STEP]" (inclusive, 0-based) of a sequence of `count` frames, in order, reversed
// when `reverse`. fm::Error naming --frames for anything else.
std::vector<int> parseFrameRange(const std::string& text, int count, bool reverse);

}  // namespace fm

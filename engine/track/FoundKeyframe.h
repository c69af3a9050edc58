#pragma once
// A bone with no keyframe (issue 29): its pose in one frame found with no start, so that tracking
// starts there as from a keyframe. The tracker then registers the frame in every camera from it.
//   - A bone volume in two or more cameras: found in all of them at once (find/BiplaneFinder.h:
//     orientations x 3D positions scored by every camera's gradient correlation, the best
//     polished, the verdict from the best rival basin). A bone among other bones is told apart by
//     what the cameras see of it together; its outline in one camera is lost among theirs.
//   - Otherwise (one camera, or a mesh, tracked by its outline) in each camera alone
//     (find/FoundRegistration: found, confirmed, judged, in that camera's frame), its depth
//     searched where the other cameras' views cross this one's (find/SharedView.h) unless the
//     search space gives a band in mm. With two or more cameras the answers found independently
//     must agree in 3D (orientation within kCamerasAgreeDeg, centres on rays passing within
//     kCamerasAgreeMm of one point: what confirms a find where no outline ratio can); the
//     bone's centre is then where the rays meet, its orientation the better answer's.
#include <optional>
#include <string>
#include <vector>

#include "find/BiplaneFinder.h"
#include "find/FoundRegistration.h"
#include "track/Tracker.h"
#include "track/TrialScene.h"
#include "xray/AnswerCheck.h"
#include "xray/ObjectRegistration.h"

namespace fm {

// Two cameras' independent answers agree (the centre depth one view fixes weakly is what the
// other camera sees best, so a few mm of ray miss is expected).
inline constexpr double kCamerasAgreeDeg = 10.0;
inline constexpr double kCamerasAgreeMm = 10.0;

struct CameraFind {
    std::size_t camera = 0;
    FindSpace space;           // searched (with other cameras: the depths their views share)
    FoundRegistration result;  // of one object, the bone (index 0)
    AnswerCheck check;
};

struct FoundKeyframe {
    int frame = 0;
    FindSpace space;                 // as asked (the biplane find's, or each camera's before its depths)
    RigidTransform pose;             // the bone's worldFromObject
    std::optional<FoundBiplane> biplane;  // found in all the cameras at once (then `cameras` is empty)
    std::vector<CameraFind> cameras;  // per camera that had an image, each found alone
    std::size_t best = 0;            // index into cameras of the one whose orientation is used
    // With several cameras: the agreeing pair's largest distance (mm) from the centre to its rays,
    // and the angle between their orientations; unset when no pair agrees.
    std::optional<double> rayMissMm;
    double camerasAgreeDeg = 0.0;
    // Found at once: the finder's verdict. One camera: its verdict. Several found alone: ok when
    // two cameras' answers agree, else lost.
    AnswerVerdict verdict = AnswerVerdict::Lost;
    std::string verdictText;  // why, in one line
};

// `scene`: the bone alone (sceneOfBoneAlone). `find` is for cameras found alone, `biplane` for
// all at once (a band in mm in its space replaces the depths the cameras share); `onStage` as
// findBiplanePose's (the biplane find's stages only). Throws
// fm::Error when the frame has no image, or as findObjectPose and findBiplanePose.
FoundKeyframe findKeyframe(const Scene& scene, const std::string& bone, const FrameViews& frames, int frame,
                           const RegistrationSettings& settings, const FindSettings& find,
                           const BiplaneFindSettings& biplane = {}, const ConfirmationSettings& confirmation = {},
                           const std::atomic<bool>* stop = nullptr, const FindStageCallback& onStage = {});

// A trial's bone with no start found in `frame` as `track` and its Python twin find it: the bone
// alone, the registration settings its model takes on real radiographs (realXraySettings, `seed`,
// `threads`), `cameras` (empty = all) and `findSpace` as typed ("" = the defaults; errors name
// `option`). The caller refuses an answer that is not ok (refuseUnlessOk).
FoundKeyframe findTrialBone(const TrialScene& scene, const std::string& bone, const std::vector<std::size_t>& cameras,
                            int frame, const std::string& findSpace, const char* option, std::uint64_t seed,
                            int threads, const std::atomic<bool>* stop = nullptr);

// findTrialBone as a tracker's way to find a lost frame (TrackSettings::findFrame, OnLost::Find):
// the pose when the find is ok. `findSpace` is checked here, before any frame is tracked; `scene`
// must outlive the finder.
FindFrame trialBoneFinder(const TrialScene& scene, const std::string& bone, const std::vector<std::size_t>& cameras,
                          const std::string& findSpace, const char* option, std::uint64_t seed, int threads);

// Throws fm::Error unless `found` is ok, naming the bone, the frame, the verdict and what the user
// can give instead (`startHint`: "a keyframe (--start)"; `spaceOption`: "--find-space"). A pose that
// may be wrong is no start: the frames tracked from it would be judged against it and called ok (a
// doubtful find on the default simulated femur trial, whose cameras see the two femurs overlap:
// 10 frames tracked from it, none within 1 mm of the truth, each "ok").
void refuseUnlessOk(const FoundKeyframe& found, const std::string& bone, const char* startHint, const char* spaceOption);

}  // namespace fm

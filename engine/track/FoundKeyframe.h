#pragma once
// A bone with no keyframe (issue 29): its pose in one frame found with no start, so that tracking
// starts there as from a keyframe. In each camera with an image of the frame the bone is found
// alone (find/FoundRegistration: found, confirmed, judged, in that camera's frame); one view fixes
// depth weakly, so with two or more cameras whose answers are not lost the bone's centre is where
// their rays through the found centres pass closest (least squares), the orientation the
// best-scoring camera's. The tracker then registers the frame in every camera from that pose.
#include <optional>
#include <string>
#include <vector>

#include "find/FoundRegistration.h"
#include "track/Tracker.h"
#include "xray/AnswerCheck.h"
#include "xray/ObjectRegistration.h"

namespace fm {

struct CameraFind {
    std::size_t camera = 0;
    FoundRegistration result;  // of one object, the bone (index 0)
    AnswerCheck check;
};

struct FoundKeyframe {
    int frame = 0;
    RigidTransform pose;             // the bone's worldFromObject
    std::vector<CameraFind> cameras;  // per camera that had an image
    std::size_t best = 0;            // index into cameras of the one whose orientation is used
    // With several cameras: the largest distance (mm) from the chosen centre to a camera's ray.
    std::optional<double> rayMissMm;
    AnswerVerdict verdict = AnswerVerdict::Lost;  // the best camera's
};

// `scene`: the bone alone (sceneOfBoneAlone). Throws fm::Error when the frame has no image or
// as findObjectPose.
FoundKeyframe findKeyframe(const Scene& scene, const std::string& bone, const FrameViews& frames, int frame,
                           const RegistrationSettings& settings, const FindSettings& find,
                           const ConfirmationSettings& confirmation = {}, const std::atomic<bool>* stop = nullptr);

}  // namespace fm

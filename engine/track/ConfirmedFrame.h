#pragma once
// One frame of a trial registered in its cameras from independent starts, as register --model
// confirms a model (xray/ConfirmedRegistration.h): the first search from the start, the others
// from starts drawn around it (seed + r), until two end within the agreement bounds of the best
// (the bone's centre and its rotation, in 3D: biplane fixes depth) or maxRuns have run; the
// verdict weighs that with the best run's own evidence. `register --trial` and the workspace's
// biplane Solve use it.
#include <atomic>
#include <string>
#include <vector>

#include "track/Tracker.h"
#include "xray/ConfirmedRegistration.h"

namespace fm {

struct ConfirmedFrame {
    FrameRecord answer;  // the best run; evaluations, seconds and profile are the runs' sums
    std::vector<FrameRecord> runs;
    AnswerEvidence evidence;  // the answer's own, with runs and agreeing
    AnswerCheck check;
};

// Throws fm::Error when a run cannot track the frame (not in view, unreadable), naming it.
// `progress` is the first run's.
ConfirmedFrame registerFrameConfirmed(const Scene& scene, const std::string& bone, const FrameViews& views,
                                      const TrackSettings& settings, int frame, const RigidTransform& start,
                                      const FrameContext& context, const ConfirmationSettings& confirmation,
                                      const std::atomic<bool>* stop = nullptr,
                                      const RegistrationCallback& progress = {});

}  // namespace fm

#pragma once
// One keyframe segment (TrackSegments.h) tracked as `fluoromatch track` tracks it: the frames of
// the segment not found before (`done`, e.g. a resumed run's) in order, each started from the
// segment's keyframes and the frames of the segment found so far. Every new pose is kept as
// `stored` returns it (the pose as the .tra holds it, storedObjectPose) before the next frames
// start from it, so a run from a file and an uninterrupted one compute the same numbers. The CLI
// and the app's track runner both track through this, so their poses agree.
#include <atomic>
#include <functional>
#include <map>
#include <vector>

#include "track/TrackSegments.h"
#include "track/Tracker.h"

namespace fm {

// The frames of `segment` not in `done`, in tracking order.
std::vector<int> framesToTrack(const TrackSegment& segment, const std::map<int, RigidTransform>& done);

// afterFrame gets every frame's record (the pose as found, not as stored) once it is done;
// stops after the current frame when *stop is set. `kept`: the records of `done` frames as their
// run left them (verdict and costs, e.g. from its CSV), which judge the frames after them as they
// did in that run (Tracker::run); a done frame without one judges nothing (its verdict unknown).
void trackSegment(const Tracker& tracker, const TrackSegment& segment,
                  const std::map<int, RigidTransform>& done,
                  const std::function<RigidTransform(const RigidTransform&)>& stored,
                  const std::function<void(const FrameRecord&)>& afterFrame,
                  const std::atomic<bool>* stop = nullptr, const std::map<int, FrameRecord>& kept = {});

}  // namespace fm

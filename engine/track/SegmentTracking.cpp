#include "track/SegmentTracking.h"

namespace fm {

std::vector<int> framesToTrack(const TrackSegment& segment, const std::map<int, RigidTransform>& done) {
    std::vector<int> todo;
    for (int f : segment.frames)
        if (done.count(f) == 0) todo.push_back(f);
    return todo;
}

void trackSegment(const Tracker& tracker, const TrackSegment& segment,
                  const std::map<int, RigidTransform>& done,
                  const std::function<RigidTransform(const RigidTransform&)>& stored,
                  const std::function<void(const FrameRecord&)>& afterFrame,
                  const std::atomic<bool>* stop, const std::map<int, FrameRecord>& kept) {
    std::map<int, RigidTransform> tracked;  // this segment's frames only
    for (int f : segment.frames)
        if (const auto d = done.find(f); d != done.end()) tracked[f] = d->second;
    // Every frame in order: the done ones are kept, and those with a record judge the frames after
    // them as in the run that tracked them.
    tracker.run(
        segment.frames, segment.keyframes, tracked,
        [&](const FrameRecord& r) {
            if (r.answered())
                tracked[r.frame] = stored ? stored(*r.worldFromBone) : *r.worldFromBone;
            if (afterFrame) afterFrame(r);
        },
        stop, kept);
}

}  // namespace fm

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
    // Every frame in order, each done one as a kept record (an unknown verdict: judges nothing),
    // so that the frames after a kept one are judged as in the run that tracked it.
    std::map<int, FrameRecord> keptHere;
    for (int f : segment.frames)
        if (const auto d = done.find(f); d != done.end()) {
            tracked[f] = d->second;
            const auto k = kept.find(f);
            FrameRecord& r = keptHere[f];
            if (k != kept.end()) {
                r = k->second;
            } else {
                r.frame = f;
                r.verdict = AnswerVerdict::Lost;  // not known: no later frame is judged by it
            }
        }
    tracker.run(
        segment.frames, segment.keyframes, tracked,
        [&](const FrameRecord& r) {
            if (r.answered())
                tracked[r.frame] = stored ? stored(*r.worldFromBone) : *r.worldFromBone;
            if (afterFrame) afterFrame(r);
        },
        stop, keptHere);
}

}  // namespace fm

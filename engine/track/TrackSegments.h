#pragma once
// The independent pieces of a tracking run: the frames (in tracking order) cut at every frame
// that has a keyframe. Each segment starts from its own keyframe and knows nothing of the frames
// of the other segments, so segments can run in any order, on any process, and give the same
// poses (docs/distributed.md). Frames inside a segment stay sequential: each one starts from the
// poses found before it in the segment (that is what keeps tracking fast and robust).
//
// Segment 0 holds the frames before the first keyframe in the list (none if the list starts on
// a keyframe); it sees the keyframes outside the list (a run of frames 5:9 may start from a
// keyframe at frame 0). Every later segment sees only its own keyframe: from the frame after a
// keyframe, "extrapolate" starts from that keyframe alone, never from the frames before it.
#include <map>
#include <vector>

#include "scene/RigidTransform.h"

namespace fm {

struct TrackSegment {
    std::vector<int> frames;                  // in tracking order
    std::map<int, RigidTransform> keyframes;  // the keyframes this segment may start from
};

// Every frame of `frames` lands in exactly one segment, in order; empty segments are not made.
std::vector<TrackSegment> splitAtKeyframes(const std::vector<int>& frames,
                                           const std::map<int, RigidTransform>& keyframes);

}  // namespace fm

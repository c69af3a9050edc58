#include "track/TrackSegments.h"

#include <set>

namespace fm {

std::vector<TrackSegment> splitAtKeyframes(const std::vector<int>& frames,
                                           const std::map<int, RigidTransform>& keyframes) {
    const std::set<int> inList(frames.begin(), frames.end());
    TrackSegment leading;
    for (const auto& [frame, pose] : keyframes)
        if (inList.count(frame) == 0) leading.keyframes[frame] = pose;
    std::vector<TrackSegment> segments;
    TrackSegment current = std::move(leading);
    for (int frame : frames) {
        if (const auto k = keyframes.find(frame); k != keyframes.end()) {
            if (!current.frames.empty()) segments.push_back(std::move(current));
            current = TrackSegment{};
            current.keyframes[frame] = k->second;
        }
        current.frames.push_back(frame);
    }
    if (!current.frames.empty()) segments.push_back(std::move(current));
    return segments;
}

}  // namespace fm

#include "scene/BonePoses.h"

#include <string>

#include "core/Error.h"

namespace fm::app {

BonePoses::BonePoses(int frameCount, const std::map<int, RigidTransform>& keyframes) {
    if (frameCount < 0) throw Error("bone poses: frame count " + std::to_string(frameCount));
    poses_.resize(static_cast<std::size_t>(frameCount));
    for (const auto& [frame, pose] : keyframes) {
        check(frame);
        keyframes_[frame] = pose;
    }
}

void BonePoses::check(int frame) const {
    if (frame < 0 || frame >= frameCount())
        throw Error("bone poses: frame " + std::to_string(frame) + " is not one of the trial's 0.." +
                    std::to_string(frameCount() - 1));
}

const std::optional<RigidTransform>& BonePoses::framePose(int frame) const {
    check(frame);
    return poses_[static_cast<std::size_t>(frame)];
}

std::optional<RigidTransform> BonePoses::pose(int frame) const {
    if (const auto& p = framePose(frame)) return p;
    if (const auto k = keyframes_.find(frame); k != keyframes_.end()) return k->second;
    return std::nullopt;
}

bool BonePoses::isKeyframe(int frame) const {
    check(frame);
    return keyframes_.count(frame) != 0;
}

void BonePoses::setPose(int frame, const RigidTransform& pose) {
    check(frame);
    poses_[static_cast<std::size_t>(frame)] = pose;
}

void BonePoses::clearPose(int frame) {
    check(frame);
    poses_[static_cast<std::size_t>(frame)].reset();
}

void BonePoses::setKeyframe(int frame, const RigidTransform& pose) {
    check(frame);
    keyframes_[frame] = pose;
    poses_[static_cast<std::size_t>(frame)].reset();
}

bool BonePoses::clearKeyframe(int frame) {
    check(frame);
    return keyframes_.erase(frame) != 0;
}

void BonePoses::apply(const FrameRecord& record) {
    if (!record.answered()) return;
    setPose(record.frame, *record.worldFromBone);
}

}  // namespace fm::app

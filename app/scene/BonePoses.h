#pragma once
// One bone's poses over a trial's frames, as the app's trial view holds them: per frame the pose
// found by tracking or set by hand (nothing where neither happened), and the user's keyframes.
// Poses are object poses (worldFromVolume in our volume frame, TrialScene.h); TrialPoseFiles.h
// turns them into .tra rows and trial keyframes.
#include <map>
#include <optional>
#include <vector>

#include "scene/RigidTransform.h"
#include "track/Tracker.h"

namespace fm::app {

class BonePoses {
  public:
    // `keyframes` (frame -> pose) must lie in 0..frameCount-1: fm::Error otherwise.
    BonePoses(int frameCount, const std::map<int, RigidTransform>& keyframes = {});

    int frameCount() const { return static_cast<int>(poses_.size()); }
    // The frame's pose: tracked or set, else its keyframe, else none.
    std::optional<RigidTransform> pose(int frame) const;
    bool hasPose(int frame) const { return pose(frame).has_value(); }
    // The tracked or set pose alone (no keyframe fallback).
    const std::optional<RigidTransform>& framePose(int frame) const;
    const std::map<int, RigidTransform>& keyframes() const { return keyframes_; }
    bool isKeyframe(int frame) const;

    // A pose set by hand (or tracked) for the frame.
    void setPose(int frame, const RigidTransform& pose);
    void clearPose(int frame);
    // A keyframe there; it is also the frame's pose from now on (a tracked pose there is
    // replaced: the user has put the bone somewhere else).
    void setKeyframe(int frame, const RigidTransform& pose);
    // Removes the keyframe (the frame keeps a tracked or set pose if it has one). False when
    // there was none.
    bool clearKeyframe(int frame);
    // A tracking result: a tracked frame's pose is kept, any other status changes nothing.
    void apply(const FrameRecord& record);

  private:
    void check(int frame) const;
    std::vector<std::optional<RigidTransform>> poses_;
    std::map<int, RigidTransform> keyframes_;
};

}  // namespace fm::app

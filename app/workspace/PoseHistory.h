#pragma once
// Undo for the workspace: every change of the poses (a pose edit, which is one drag or one
// nudge; a Solve's answer; a Track run; a keyframe set or cleared) is one step back to the poses
// and keyframes as they were before it. Plain data, kept in WorkspaceState.
#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "scene/RigidTransform.h"

namespace fm::app {

struct PoseSnapshot {
    std::vector<std::vector<std::optional<RigidTransform>>> poses;  // [frame][object]
    std::vector<std::map<int, RigidTransform>> keyframes;           // per object
};

// Steps kept: a step of a 1000-frame trial of 3 objects holds ~0.3 MB.
inline constexpr std::size_t kMaxUndoSteps = 50;

struct PoseHistory {
    struct Step {
        std::string what;  // "Solve of femur in frame 0"
        PoseSnapshot before;
    };
    std::vector<Step> steps;  // oldest first
    // A pose edit in progress (a drag): its frames make one step.
    bool editOpen = false;
    int editFrame = -1, editObject = -1;

    // A change is about to be made: remember the poses before it (the oldest step goes beyond
    // kMaxUndoSteps). Ends an open edit.
    void record(std::string what, PoseSnapshot before);
    // A pose edit of (frame, object) is about to be applied: a step when it starts an edit.
    void recordEdit(const std::string& object, int frame, int objectIndex, const PoseSnapshot& before);
    // The last step, removed; nullopt when there is none.
    std::optional<Step> takeLast();
};

}  // namespace fm::app

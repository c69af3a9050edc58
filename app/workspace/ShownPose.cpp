#include "workspace/ShownPose.h"

namespace fm::app {

bool hasSetPose(const WorkspaceState& state, int frame, int object) {
    return state.poses.at(static_cast<std::size_t>(frame)).at(static_cast<std::size_t>(object)).has_value();
}

std::optional<RigidTransform> shownPose(const WorkspaceState& state, int frame, int object) {
    const auto k = static_cast<std::size_t>(object);
    const int frames = static_cast<int>(state.poses.size());
    for (int f = frame; f >= 0; --f)
        if (const auto& p = state.poses[static_cast<std::size_t>(f)].at(k)) return p;
    for (int f = frame + 1; f < frames; ++f)
        if (const auto& p = state.poses[static_cast<std::size_t>(f)].at(k)) return p;
    if (k < state.placements.size()) return state.placements[k];
    return std::nullopt;
}

std::vector<std::optional<RigidTransform>> shownPoses(const WorkspaceState& state, int frame) {
    std::vector<std::optional<RigidTransform>> poses(state.objects.size());
    for (std::size_t k = 0; k < poses.size(); ++k) poses[k] = shownPose(state, frame, static_cast<int>(k));
    return poses;
}

}  // namespace fm::app

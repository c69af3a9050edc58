#include "workspace/PoseHistory.h"

namespace fm::app {

void PoseHistory::record(std::string what, PoseSnapshot before) {
    steps.push_back({std::move(what), std::move(before)});
    if (steps.size() > kMaxUndoSteps) steps.erase(steps.begin());
    editOpen = false;
}

void PoseHistory::recordEdit(const std::string& object, int frame, int objectIndex,
                             const PoseSnapshot& before) {
    if (editOpen && editFrame == frame && editObject == objectIndex) return;
    record("pose edit of " + object + " in frame " + std::to_string(frame), before);
    editOpen = true;
    editFrame = frame;
    editObject = objectIndex;
}

std::optional<PoseHistory::Step> PoseHistory::takeLast() {
    if (steps.empty()) return std::nullopt;
    Step last = std::move(steps.back());
    steps.pop_back();
    editOpen = false;
    return last;
}

}  // namespace fm::app

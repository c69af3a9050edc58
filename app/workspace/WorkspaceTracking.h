#pragma once
// The workspace's trial controls at work (TrackState.h is what the UI sees): play / pause over
// the frames, keyframes of the selected object, Track forward / back from the current frame on
// the TrackRunner (the path of `fluoromatch track`), its frames written into the workspace's
// poses as they come with the panes following the frame just tracked, the pose curves, and
// saving the object's .tra and the trial's keyframes.
#include <chrono>
#include <cstdint>
#include <memory>

#include "scene/BonePoses.h"
#include "scene/TrackRunner.h"
#include "workspace/WorkspaceModel.h"
#include "workspace/WorkspaceState.h"

namespace fm::app {

// The workspace's poses of `object` over the frames with its keyframes, as the track runner and
// the files take them.
BonePoses bonePosesOf(const WorkspaceState& state, int object);

class WorkspaceTracking {
  public:
    // The trial's keyframes of every object (TrialScene keyframes, object poses).
    void init(const WorkspaceModel& model, WorkspaceState& state);
    // Before the UI pass: the runner's new frames into the poses, the view following them,
    // playing advanced, the selected object's curves.
    void poll(const WorkspaceModel& model, WorkspaceState& state);
    // After the UI pass: the Track pane's requests.
    void process(const std::shared_ptr<const WorkspaceModel>& model, WorkspaceState& state);
    void stop() { runner_.stop(); }
    bool running() const { return runner_.running(); }

  private:
    void start(const std::shared_ptr<const WorkspaceModel>& model, WorkspaceState& state, bool backwards);
    void save(const WorkspaceModel& model, WorkspaceState& state, bool keyframes);

    TrackRunner runner_;
    std::uint64_t version_ = 0, run_ = 0;
    std::size_t applied_ = 0;  // records of run_ written into the poses
    int runObject_ = -1;
    std::chrono::steady_clock::time_point lastStep_{};
};

}  // namespace fm::app

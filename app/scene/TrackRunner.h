#pragma once
// The trial view's Track forward / Track back: tracks one bone of a trial through its frames on a
// worker thread, as `fluoromatch track` does (the frames cut at the keyframes, each segment
// tracked by engine trackSegment, later frames started from the poses as the .tra holds them),
// and publishes every frame's result as it comes, as plain data the UI draws while the run goes
// on. One run at a time: the newest request wins (start() stops a running one first); stop()
// ends it after the frame it is on and keeps every frame finished before.
//
// The same frames, keyframes, seed and settings give the poses `fluoromatch track --frames ...
// [--reverse] --start keyframes.tra --seed N` gives (tests/app/TrackRunnerTest.cpp).
#include <atomic>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "scene/BonePoses.h"
#include "track/Tracker.h"
#include "track/TrialScene.h"

namespace fm::app {

struct TrackRequest {
    std::string bone;
    std::vector<int> frames;                  // in tracking order
    std::map<int, RigidTransform> keyframes;  // object poses
    TrackSettings settings;                   // the CLI's defaults: seed 1, extrapolate
};

// Frames from `from` to the last one, or back to 0 when `backwards`.
std::vector<int> framesFrom(int from, int frameCount, bool backwards);

// Track forward / back from `from`: the bone's keyframes, and the pose at `from` as one more
// when that frame is no keyframe (the bone where the user put it, or where it was tracked).
TrackRequest trackRequestFrom(const std::string& bone, const BonePoses& poses, int from,
                              bool backwards, int threads);

// A copy of the runner's state at one moment.
struct TrackSnapshot {
    bool running = false;
    bool finished = false;  // a run ended (all frames, or stopped): its records are below
    bool stopped = false;   // ... because stop() was called
    std::string error;      // why the run failed
    std::string bone;
    std::vector<int> frames;           // the run's frames, in tracking order
    std::vector<FrameRecord> records;  // one per frame done, in tracking order; a frame cut
                                       // short by stop() last, with status Stopped
    int currentFrame = -1;             // the frame being tracked, -1 when idle
    double elapsedSeconds = 0.0;
    std::uint64_t run = 0;      // counts the runs started
    std::uint64_t version = 0;  // changes with every published update

    // Frames finished (any status but Stopped), their mean time, the last one's summed cost.
    int framesDone() const;
    double secondsPerFrame() const;
    double lastCost() const;  // NaN before the first tracked frame
};

class TrackRunner {
  public:
    TrackRunner() = default;
    ~TrackRunner();
    TrackRunner(const TrackRunner&) = delete;
    TrackRunner& operator=(const TrackRunner&) = delete;

    // Stops a running run, then tracks `request` in `trial`. fm::Error (and nothing started)
    // for a bone the trial has not loaded, no frames, or frames or keyframes outside the trial.
    void start(std::shared_ptr<const TrialScene> trial, TrackRequest request);
    // Ends the run after its current frame and waits for it. Does nothing when idle.
    void stop();
    bool running() const;
    TrackSnapshot snapshot() const;

  private:
    mutable std::mutex mutex_;
    std::thread worker_;
    std::atomic<bool> stopFlag_{false};
    TrackSnapshot snapshot_;
};

}  // namespace fm::app

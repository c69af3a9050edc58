#pragma once
// The app's Solve button: runs the automatic pose search (fm::Registration) on a worker thread
// against the reference DRR, from the user's pose, and publishes its progress as plain data so
// the UI can draw it while the search runs. One solve at a time; stop() ends it after the
// current batch and keeps the best pose found so far.
#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "core/Image.h"
#include "find/ViewFinder.h"
#include "geometry/Pose.h"
#include "scene/LoadedScene.h"
#include "search/Registration.h"
#include "slice/SliceRegistration.h"

namespace fm::app {

// A copy of the solver's state at one moment (everything the UI shows).
struct SolveSnapshot {
    bool running = false;
    bool finished = false;  // a run ended (completed or stopped) and its result is below
    bool stopped = false;   // ... it ended because stop() was called
    std::string error;      // the engine's message when the search could not start
    SearchMethod method = SearchMethod::CmaEs;
    std::string stage;  // "global", "polish", "depth"
    int level = 0, levelCount = 0, factor = 1;
    int evaluations = 0, budget = 0;
    // Best cost after every batch of the current level (costs of different levels are not
    // comparable, so the curve restarts with each level).
    std::vector<float> costHistory;
    double bestCost = 0.0;
    Pose start, bestPose, candidate;
    double elapsedMs = 0.0;
    std::uint64_t version = 0;  // changes with every published update
};

class Solver {
  public:
    Solver() = default;
    ~Solver();
    Solver(const Solver&) = delete;
    Solver& operator=(const Solver&) = delete;

    // Stops any running solve, then searches `scene` for the pose whose DRR matches `reference`
    // (an exact full-film DRR of the scene), starting from `start`. Deterministic for the
    // settings' seed and thread count.
    void start(std::shared_ptr<const LoadedScene> scene, Image reference, const Pose& start,
               RegistrationSettings settings);
    // The same with no start (engine findScenePose): the pose found from nothing over the search
    // space of `find`, its stages ("find: scan", ...) as the snapshot's stage; the snapshot's
    // start is the centre pose. The best candidate is the answer.
    void startFind(std::shared_ptr<const LoadedScene> scene, Image reference, RegistrationSettings settings,
                   ViewFindSettings find);
    // One bone of `scene` registered alone against `references` (one per camera of the scene,
    // camera 0 the user's), the others where they are (engine registerBone). The snapshot's
    // poses are then the bone's six search numbers (boneParameterization(scene, bone)), not a
    // 2011 pose.
    void startBone(Scene scene, std::string bone, std::vector<Image> references,
                   RegistrationSettings settings);
    // The same in the MRI slice mode: slice-to-volume registration (SliceRegistration) of
    // `reference` (a slice of the scene, with its data mask). The volume's B-spline
    // coefficients are computed on the worker ("preparing").
    void startSlice(std::shared_ptr<const LoadedScene> scene, Image reference, Mask mask,
                    const Pose& start, SliceRegistrationSettings settings);
    // Asks the search to end after its current batch and waits for it (the best pose so far is
    // kept in the snapshot). Does nothing when idle.
    void stop();
    bool running() const;
    SolveSnapshot snapshot() const;

  private:
    void join();
    // What a worker runs: registers from `start`, reporting through the callback; `budget`
    // is called once the search knows its total budget and level count.
    using Search = std::function<RegistrationResult(
        const std::function<void(int budget, int levels)>& prepared,
        const RegistrationCallback& progress, const std::atomic<bool>* stop)>;
    void launch(SearchMethod method, const Pose& start, Search search);
    void publishStage(std::string stage);

    mutable std::mutex mutex_;
    std::thread worker_;
    std::atomic<bool> stopFlag_{false};
    SolveSnapshot snapshot_;
};

// The app's search settings for `method`: the engine defaults (coarse to fine 4, 2, 1), a fixed
// seed so the same start always gives the same answer, `threads` as DrrRenderOptions.
RegistrationSettings appSolveSettings(SearchMethod method, int threads);

}  // namespace fm::app

#pragma once
// Builds the bones of a loaded CT on a background thread (label map or components: resampling,
// per-bone DRR volumes, surfaces), so the UI keeps drawing, as SceneLoader does for the CT.
// One job at a time: a new start() waits for the running one to end and drops its result.
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "scene/SceneBones.h"

namespace fm::app {

class BonesLoader {
  public:
    BonesLoader() = default;
    ~BonesLoader();
    BonesLoader(const BonesLoader&) = delete;
    BonesLoader& operator=(const BonesLoader&) = delete;

    // What the worker runs: builds the bones, reporting progress; throws fm::Error on bad input.
    using Job = std::function<std::shared_ptr<const SceneBones>(const BonesProgress& progress)>;
    // `sceneGeneration`: the scene the bones are for (a result for another one is stale).
    void start(std::uint64_t sceneGeneration, std::string what, Job job);

    struct Progress {
        bool busy = false;
        std::string what, stage;
        float fraction = 0.0f;
        double elapsedSeconds = 0.0;
    };
    Progress progress() const;

    struct Result {
        std::uint64_t sceneGeneration = 0;
        std::string what;
        std::shared_ptr<const SceneBones> bones;  // null on error
        std::string error;
    };
    // The finished job's result, once.
    std::optional<Result> poll();
    // Blocks until the job ends, then returns its result (headless runs, tests).
    std::optional<Result> wait();

  private:
    void join();

    mutable std::mutex mutex_;
    std::thread worker_;
    bool busy_ = false;
    std::string what_, stage_;
    float fraction_ = 0.0f;
    std::chrono::steady_clock::time_point started_;
    std::optional<Result> finished_;
};

}  // namespace fm::app

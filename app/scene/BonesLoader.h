#pragma once
// Builds the bones of a loaded CT on a background thread (label map or components: resampling,
// per-bone DRR volumes, surfaces), so the UI keeps drawing, as SceneLoader does for the CT.
// One job at a time: a new start() waits for the running one to end and drops its result.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "scene/BackgroundJob.h"
#include "scene/SceneBones.h"

namespace fm::app {

class BonesLoader {
  public:
    // What the worker runs: builds the bones, reporting progress; throws fm::Error on bad input.
    using Job = std::function<std::shared_ptr<const SceneBones>(const BonesProgress& progress)>;
    // `sceneGeneration`: the scene the bones are for (a result for another one is stale).
    void start(std::uint64_t sceneGeneration, std::string what, Job job);

    using Progress = JobProgress;  // `what`: the label map's path or "components"
    Progress progress() const { return job_.progress(); }

    struct Result {
        std::uint64_t sceneGeneration = 0;
        std::string what;
        std::shared_ptr<const SceneBones> bones;  // null on error
        std::string error;
    };
    // The finished job's result, once.
    std::optional<Result> poll() { return job_.poll(); }
    // Blocks until the job ends, then returns its result (headless runs, tests).
    std::optional<Result> wait() {
        job_.join();
        return job_.poll();
    }

  private:
    BackgroundJob<Result> job_;
};

}  // namespace fm::app

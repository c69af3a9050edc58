#pragma once
// Loads and meshes a CT on a background thread so the UI never freezes. One load at a time;
// a request made while busy replaces any queued one and starts when the current one ends.
// The two most recent scenes are kept process-wide (volume, DRR volume, mesh): re-opening one
// whose file has not changed (same size and modification time) is instant.
#include <memory>
#include <optional>
#include <string>

#include "scene/BackgroundJob.h"
#include "scene/LoadedScene.h"

namespace fm::app {

class SceneLoader {
  public:
    SceneLoader() = default;
    SceneLoader(const SceneLoader&) = delete;
    SceneLoader& operator=(const SceneLoader&) = delete;

    void start(const std::string& spec);

    struct Progress {
        bool busy = false;
        std::string spec, stage;
        float fraction = 0.0f;
        double elapsedSeconds = 0.0;
    };
    Progress progress() const;

    // A finished load: the scene, or the reader's error message (scene null).
    struct Result {
        std::string spec;
        std::shared_ptr<LoadedScene> scene;
        std::string error;
    };
    // The result of the last finished load, once; starts a queued request.
    std::optional<Result> poll();
    // Blocks until nothing is loading or queued, then returns the last result (headless runs).
    std::optional<Result> wait();

  private:
    void launch(const std::string& spec);

    // Touched by the owner's thread only (the job guards what the worker writes).
    std::optional<std::string> queued_;
    BackgroundJob<Result> job_;  // last: joined before the queue goes
};

// What identifies a loaded file's content cheaply: the spec plus, for paths, size and time.
std::string sceneCacheKey(const std::string& spec);

}  // namespace fm::app

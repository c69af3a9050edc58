#pragma once
// The workspace's Solve: one object registered in one frame from the user's pose, on a worker
// thread, with progress as plain data and a Stop. One camera: the path of `register --reference`
// (registerObject, realXraySettings: edge distance for meshes, gradient NCC for volumes); several:
// the biplane path of `register --trial` (Tracker::trackFrame, the sum of the views' costs).
// Find: the same with no start (docs/find.md): one camera as `register` with no --start (the
// answer and the finder's other answers as candidates); several as `track` with no keyframe
// (found in each camera, the cameras must agree), then registered in all of them.
#include <atomic>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "scene/RigidTransform.h"
#include "xray/AnswerCheck.h"
#include "workspace/WorkspaceModel.h"

namespace fm::app {

struct WorkspaceSolveSnapshot {
    bool running = false, finished = false, stopped = false;
    std::string error;
    int object = -1, frame = -1;
    std::string stage;
    int evaluations = 0, budget = 0;
    double seconds = 0.0;
    RigidTransform start;
    std::optional<RigidTransform> result;  // when finished (also when stopped)
    double similarity = 0.0;
    std::vector<double> viewCosts;  // biplane: per camera
    std::string note;               // "single view", "biplane", the tracker's note
    AnswerEvidence evidence;        // searches from independent starts, uncertainty (xray/AnswerCheck.h)
    bool find = false;              // found with no start
    // Find: the answer first, then the finder's other distinct answers, best first, with their
    // similarity (the user may step through them).
    std::vector<RigidTransform> candidates;
    std::vector<double> candidateSimilarity;
    std::uint64_t version = 0;
};

class WorkspaceSolver {
  public:
    WorkspaceSolver() = default;
    ~WorkspaceSolver();
    WorkspaceSolver(const WorkspaceSolver&) = delete;
    WorkspaceSolver& operator=(const WorkspaceSolver&) = delete;

    // Stops a running solve, then registers `object` of `model` in `frame` from `start` (with
    // `find`: finds it with no start; `start` is then only what "moved" is measured from).
    // Deterministic (seed 1) for a given start.
    void start(std::shared_ptr<const WorkspaceModel> model, int object, int frame, const RigidTransform& start,
               bool find = false);
    // Ends the search after its current batch and waits; the best pose so far is the result
    // (single camera; the biplane path ends its frame as stopped).
    void stop();
    bool running() const;
    WorkspaceSolveSnapshot snapshot() const;

  private:
    void join();
    mutable std::mutex mutex_;
    WorkspaceSolveSnapshot snapshot_;
    std::atomic<bool> stop_{false};
    std::thread worker_;
};

}  // namespace fm::app

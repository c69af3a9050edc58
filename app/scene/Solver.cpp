#include "scene/Solver.h"

#include <exception>

#include "bones/BoneRegistration.h"
#include "core/Error.h"
#include "scene/VolumeScene.h"

namespace fm::app {
namespace {

double msSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

}  // namespace

RegistrationSettings appSolveSettings(SearchMethod method, int threads) {
    RegistrationSettings settings;
    settings.method = method;
    settings.seed = 1;
    settings.threads = threads;
    return settings;
}

Solver::~Solver() {
    stop();
}

void Solver::join() {
    if (worker_.joinable()) worker_.join();
}

void Solver::stop() {
    stopFlag_ = true;
    join();
}

bool Solver::running() const {
    std::lock_guard lock(mutex_);
    return snapshot_.running;
}

SolveSnapshot Solver::snapshot() const {
    std::lock_guard lock(mutex_);
    return snapshot_;
}

void Solver::start(std::shared_ptr<const LoadedScene> scene, Image reference, const Pose& start,
                   RegistrationSettings settings) {
    launch(settings.method, start,
           [scene = std::move(scene), reference = std::move(reference), start, settings](
               const auto& prepared, const RegistrationCallback& progress,
               const std::atomic<bool>* stop) {
               const Registration registration(
                   volumeScene(scene->drrVolume),
                   std::make_shared<Pose2011Parameterization>(scene->setup, scene->center),
                   {{0, reference, {}}}, settings);
               prepared(registration.totalBudget(), registration.levelCount());
               return registration.run(start.toArray(), progress, stop);
           });
}

void Solver::startFind(std::shared_ptr<const LoadedScene> scene, Image reference, RegistrationSettings settings,
                       ViewFindSettings find) {
    launch(settings.method, Pose{},
           [this, scene = std::move(scene), reference = std::move(reference), settings, find](
               const auto& prepared, const RegistrationCallback&, const std::atomic<bool>* stop) {
               prepared(0, 0);
               const FoundView found =
                   findScenePose(scene->drrVolume, scene->setup, scene->center, reference, settings, find, stop,
                                 [this](const char* stage) { publishStage(std::string("find: ") + stage); });
               if (found.candidates.empty()) throw Error("find: stopped before any pose was found");
               RegistrationResult result;
               result.params = found.candidates.front().pose.toArray();
               result.similarity = found.candidates.front().similarity;
               for (const FindStage& stage : found.stages)
                   if (stage.name == "refine" || stage.name == "finish")
                       result.evaluations += static_cast<int>(stage.evaluations);
               result.stopped = found.stopped;
               return result;
           });
}

void Solver::publishStage(std::string stage) {
    std::lock_guard lock(mutex_);
    snapshot_.stage = std::move(stage);
    ++snapshot_.version;
}

void Solver::startBone(Scene scene, std::string bone, std::vector<Image> references,
                       RegistrationSettings settings) {
    const SceneParams start = boneParameterization(scene, bone)->referenceParams();
    launch(settings.method, Pose::fromArray(start),
           [scene = std::move(scene), bone = std::move(bone), references = std::move(references),
            settings](const auto& prepared, const RegistrationCallback& progress,
                      const std::atomic<bool>* stop) {
               // The budget arrives with the first progress report.
               prepared(0, int(settings.levelFactors.size()));
               return registerBone(scene, bone, references, settings, 20.0, progress, stop)
                   .search;
           });
}

void Solver::startSlice(std::shared_ptr<const LoadedScene> scene, Image reference, Mask mask,
                        const Pose& start, SliceRegistrationSettings settings) {
    launch(settings.method, start,
           [scene = std::move(scene), reference = std::move(reference), mask = std::move(mask),
            start, settings](const auto& prepared, const RegistrationCallback& progress,
                             const std::atomic<bool>* stop) {
               const bool cubic = settings.interpolation == SliceInterpolation::CubicBSpline;
               const SliceRegistration registration(
                   prepareSliceVolume(scene->volume, cubic, settings.threads), reference, &mask,
                   scene->sliceSetup, scene->center, settings);
               prepared(registration.totalBudget(), registration.levelCount());
               return registration.run(start, progress, stop);
           });
}

void Solver::launch(SearchMethod method, const Pose& start, Search search) {
    stop();
    stopFlag_ = false;
    {
        std::lock_guard lock(mutex_);
        const std::uint64_t version = snapshot_.version + 1;
        snapshot_ = {};
        snapshot_.running = true;
        snapshot_.method = method;
        snapshot_.stage = "preparing";
        snapshot_.start = snapshot_.bestPose = snapshot_.candidate = start;
        snapshot_.version = version;
    }
    worker_ = std::thread([this, search = std::move(search)]() {
        const auto began = std::chrono::steady_clock::now();
        try {
            const RegistrationResult result = search(
                [&](int budget, int levels) {
                    std::lock_guard lock(mutex_);
                    snapshot_.budget = budget;
                    snapshot_.levelCount = levels;
                    ++snapshot_.version;
                },
                [&](const RegistrationProgress& p) {
                    std::lock_guard lock(mutex_);
                    if (p.level != snapshot_.level) snapshot_.costHistory.clear();
                    snapshot_.level = p.level;
                    snapshot_.levelCount = p.levelCount;
                    snapshot_.factor = p.factor;
                    snapshot_.stage = p.stage;
                    snapshot_.evaluations = p.evaluations;
                    snapshot_.budget = p.evaluationBudget;
                    snapshot_.bestCost = p.bestCost;
                    snapshot_.costHistory.push_back(static_cast<float>(p.bestCost));
                    snapshot_.bestPose = p.bestPose();
                    snapshot_.candidate = p.candidatePose();
                    snapshot_.elapsedMs = msSince(began);
                    ++snapshot_.version;
                },
                &stopFlag_);
            std::lock_guard lock(mutex_);
            snapshot_.bestPose = result.pose();
            snapshot_.evaluations = result.evaluations;
            snapshot_.stopped = result.stopped;
            snapshot_.stage = result.stopped ? "stopped" : "done";
        } catch (const std::exception& e) {
            std::lock_guard lock(mutex_);
            snapshot_.error = e.what();
            snapshot_.stage = "failed";
        }
        std::lock_guard lock(mutex_);
        snapshot_.running = false;
        snapshot_.finished = snapshot_.error.empty();
        snapshot_.elapsedMs = msSince(began);
        ++snapshot_.version;
    });
}

}  // namespace fm::app

#include "scene/BonesLoader.h"

#include <exception>

namespace fm::app {

BonesLoader::~BonesLoader() {
    join();
}

void BonesLoader::join() {
    if (worker_.joinable()) worker_.join();
}

void BonesLoader::start(std::uint64_t sceneGeneration, std::string what, Job job) {
    join();  // one job at a time; the previous result is dropped
    std::lock_guard lock(mutex_);
    finished_.reset();
    busy_ = true;
    what_ = what;
    stage_ = "starting";
    fraction_ = 0.0f;
    started_ = std::chrono::steady_clock::now();
    worker_ = std::thread([this, sceneGeneration, what = std::move(what), job = std::move(job)] {
        Result result{sceneGeneration, what, nullptr, {}};
        try {
            result.bones = job([this](const std::string& stage, float fraction) {
                std::lock_guard lock(mutex_);
                stage_ = stage;
                fraction_ = fraction;
            });
        } catch (const std::exception& e) {
            result.error = e.what();
        } catch (...) {
            result.error = "unknown error while building the bones of " + what;
        }
        std::lock_guard lock(mutex_);
        finished_ = std::move(result);
        busy_ = false;
    });
}

BonesLoader::Progress BonesLoader::progress() const {
    std::lock_guard lock(mutex_);
    Progress p;
    p.busy = busy_;
    p.what = what_;
    p.stage = stage_;
    p.fraction = fraction_;
    p.elapsedSeconds =
        busy_ ? std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count()
              : 0.0;
    return p;
}

std::optional<BonesLoader::Result> BonesLoader::poll() {
    std::lock_guard lock(mutex_);
    if (busy_ || !finished_) return std::nullopt;
    std::optional<Result> out = std::move(finished_);
    finished_.reset();
    return out;
}

std::optional<BonesLoader::Result> BonesLoader::wait() {
    join();
    return poll();
}

}  // namespace fm::app

#pragma once
// One job at a time on a worker thread, so the UI keeps drawing while it runs: the job reports
// its stage and fraction as it goes, and its result is taken once with poll(). SceneLoader (a CT)
// and BonesLoader (the bones of a CT) are this plus their own rules: a queue and a cache of
// recent scenes; the scene a result belongs to.
#include <chrono>
#include <exception>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

namespace fm::app {

// What a job calls as it goes: the stage's name and the fraction done, 0..1.
using JobReport = std::function<void(const std::string& stage, float fraction)>;

struct JobProgress {
    bool busy = false;
    std::string what, stage;  // `what`: the last job's, kept after it ends
    float fraction = 0.0f;
    double elapsedSeconds = 0.0;
};

template <class Result>
class BackgroundJob {
  public:
    using Work = std::function<Result(const JobReport& report)>;
    // Makes the result of a job that threw; `error` is empty when it threw no std::exception.
    using Failed = std::function<Result(const std::string& error)>;

    BackgroundJob() = default;
    ~BackgroundJob() { join(); }
    BackgroundJob(const BackgroundJob&) = delete;
    BackgroundJob& operator=(const BackgroundJob&) = delete;

    // Runs `work` on a new worker once the previous one has ended (its result, if not polled,
    // is dropped).
    void start(std::string what, Work work, Failed failed) {
        join();
        std::lock_guard lock(mutex_);
        finished_.reset();
        busy_ = true;
        what_ = what;
        stage_ = "starting";
        fraction_ = 0.0f;
        started_ = std::chrono::steady_clock::now();
        worker_ = std::thread([this, work = std::move(work), failed = std::move(failed)] {
            std::optional<Result> result;
            try {
                result = work([this](const std::string& stage, float fraction) {
                    std::lock_guard lock(mutex_);
                    stage_ = stage;
                    fraction_ = fraction;
                });
            } catch (const std::exception& e) {
                result = failed(e.what());
            } catch (...) {
                result = failed("");
            }
            std::lock_guard lock(mutex_);
            finished_ = std::move(result);
            busy_ = false;
        });
    }
    // A result that needs no worker (a cache hit): poll() returns it next.
    void finish(Result result) {
        join();
        std::lock_guard lock(mutex_);
        finished_ = std::move(result);
    }

    JobProgress progress() const {
        std::lock_guard lock(mutex_);
        JobProgress p;
        p.busy = busy_;
        p.what = what_;
        p.stage = stage_;
        p.fraction = fraction_;
        p.elapsedSeconds =
            busy_ ? std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count() : 0.0;
        return p;
    }
    // Nothing running and no result waiting.
    bool idle() const {
        std::lock_guard lock(mutex_);
        return !busy_ && !finished_;
    }
    // The finished job's result, once.
    std::optional<Result> poll() {
        std::lock_guard lock(mutex_);
        if (busy_ || !finished_) return std::nullopt;
        std::optional<Result> out = std::move(finished_);
        finished_.reset();
        return out;
    }
    // Blocks until the running job (if any) has ended.
    void join() {
        if (worker_.joinable()) worker_.join();
    }

  private:
    mutable std::mutex mutex_;
    std::thread worker_;  // started and joined by the owner's thread only
    bool busy_ = false;
    std::string what_, stage_;
    float fraction_ = 0.0f;
    std::chrono::steady_clock::time_point started_;
    std::optional<Result> finished_;
};

}  // namespace fm::app

#pragma once
// One worker thread that computes the newest request only: a request made while another runs
// replaces any request still waiting, so a slider dragged faster than the work keeps up costs one
// render at a time and the result shown is never older than needed. The UI thread never waits
// unless it asks to (wait(): headless runs, whose frames must not depend on timing).
#include <condition_variable>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>

namespace fm::app {

template <class Request, class Result>
class NewestWins {
  public:
    using Work = std::function<Result(const Request&)>;
    // `finished` (optional) is called on the worker after each result, e.g. to wake a window
    // waiting for events.
    explicit NewestWins(Work work, std::function<void()> finished = {})
        : work_(std::move(work)), finished_(std::move(finished)), worker_([this] { run(); }) {}
    ~NewestWins() {
        {
            std::lock_guard lock(mutex_);
            stopping_ = true;
        }
        wake_.notify_all();
        worker_.join();
    }
    NewestWins(const NewestWins&) = delete;
    NewestWins& operator=(const NewestWins&) = delete;

    void request(Request r) {
        {
            std::lock_guard lock(mutex_);
            pending_ = std::move(r);
        }
        wake_.notify_all();
    }
    // The newest result not taken yet (results of older requests finished meanwhile are
    // dropped).
    std::optional<Result> take() {
        std::lock_guard lock(mutex_);
        std::optional<Result> out = std::move(result_);
        result_.reset();
        return out;
    }
    // Blocks until no request waits or runs, then takes.
    std::optional<Result> wait() {
        std::unique_lock lock(mutex_);
        done_.wait(lock, [this] { return !pending_ && !running_; });
        std::optional<Result> out = std::move(result_);
        result_.reset();
        return out;
    }
    // A request waits or runs, or its result waits to be taken.
    bool busy() const {
        std::lock_guard lock(mutex_);
        return pending_ || running_ || result_;
    }

  private:
    void run() {
        std::unique_lock lock(mutex_);
        for (;;) {
            wake_.wait(lock, [this] { return stopping_ || pending_; });
            if (stopping_) return;
            Request r = std::move(*pending_);
            pending_.reset();
            running_ = true;
            lock.unlock();
            Result out = work_(r);
            lock.lock();
            result_ = std::move(out);
            running_ = false;
            done_.notify_all();
            if (finished_) {
                lock.unlock();
                finished_();
                lock.lock();
            }
        }
    }

    Work work_;
    std::function<void()> finished_;
    mutable std::mutex mutex_;
    std::condition_variable wake_, done_;
    std::optional<Request> pending_;
    std::optional<Result> result_;
    bool running_ = false, stopping_ = false;
    std::thread worker_;  // last: started once the rest is built
};

}  // namespace fm::app

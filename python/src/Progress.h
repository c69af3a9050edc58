#pragma once
// Progress from the engine's worker threads to a Python callback. The engine runs with the GIL
// released; each report takes the GIL, checks for Ctrl-C and calls the callback with a dict.
// A callback that returns False, raises, or a Ctrl-C sets the stop flag the engine polls; the
// exception is raised again once the engine has returned (rethrowIfFailed).
#include <atomic>
#include <mutex>
#include <optional>

#include <pybind11/pybind11.h>

namespace fm::py {

class ProgressRelay {
  public:
    explicit ProgressRelay(pybind11::object callback) : callback_(std::move(callback)) {}

    // Call with the GIL released (from any thread): returns false once the run should stop.
    template <class MakeDict>
    void report(MakeDict&& makeDict) {
        pybind11::gil_scoped_acquire lock;
        if (stop_) return;
        if (PyErr_CheckSignals() != 0) {
            fail();
            return;
        }
        if (callback_.is_none()) return;
        try {
            const pybind11::object answer = callback_(makeDict());
            if (!answer.is_none() && !answer.cast<bool>()) stop_ = true;
        } catch (pybind11::error_already_set& e) {
            error_.emplace(std::move(e));
            stop_ = true;
        }
    }
    const std::atomic<bool>* stopFlag() const { return &stop_; }
    bool stopped() const { return stop_; }
    // With the GIL held, after the engine returned.
    void rethrowIfFailed() {
        if (error_) throw pybind11::error_already_set(std::move(*error_));
    }

  private:
    void fail() {
        error_.emplace();  // takes the pending Python error (KeyboardInterrupt)
        stop_ = true;
    }
    pybind11::object callback_;
    std::atomic<bool> stop_{false};
    std::optional<pybind11::error_already_set> error_;
};

}  // namespace fm::py

#pragma once
// How long a window's frame loop may wait for input before drawing the next frame, from what
// the app is doing. An idle app must use no CPU: with nothing moving and no worker running it
// sleeps until the next input event instead of redrawing (issue 15). No GL, no GLFW: the policy
// is tested on its own (tests/app/EventWaitTest.cpp).
namespace fm::app {

enum class Activity {
    Busy,        // the user is dragging, typing or holding a button: draw as fast as shown
    Background,  // a worker runs (load, Solve, Track, play): show its progress at kBackgroundHz
    Idle,        // nothing moves: sleep until an input event
};

enum class EventWait { Poll, Timeout, Forever };

// ImGui reflects an input a frame or two after it (a click's result, a hover highlight), so a
// few frames are drawn without waiting after each event before sleeping again.
inline constexpr int kSettleFrames = 3;
inline constexpr double kBackgroundHz = 10.0;

class EventWaitPolicy {
  public:
    // The wait before the next frame. `woken`: the last wait ended on an event (not a timeout).
    // A change of activity (a worker's result just shown) settles like an event.
    EventWait next(Activity activity, bool woken) {
        if (activity == Activity::Busy || woken || activity != last_) settled_ = 0;
        last_ = activity;
        if (settled_ < kSettleFrames) {
            ++settled_;
            return EventWait::Poll;
        }
        return activity == Activity::Background ? EventWait::Timeout : EventWait::Forever;
    }

  private:
    int settled_ = 0;
    Activity last_ = Activity::Busy;
};

}  // namespace fm::app

// The window's wait policy (platform/EventWait.h): an idle app sleeps until an event after a few
// settling frames; a running worker gets timed frames; interaction is drawn without waiting.
#include <gtest/gtest.h>

#include <vector>

#include "platform/EventWait.h"

namespace fm::app {
namespace {

std::vector<EventWait> run(EventWaitPolicy& p, Activity a, int frames, bool woken = false) {
    std::vector<EventWait> out;
    for (int i = 0; i < frames; ++i) out.push_back(p.next(a, woken && i == 0));
    return out;
}

TEST(EventWait, IdleSleepsUntilAnEventAfterTheSettlingFrames) {
    EventWaitPolicy p;
    const auto waits = run(p, Activity::Idle, kSettleFrames + 3);
    for (int i = 0; i < kSettleFrames; ++i) EXPECT_EQ(waits[static_cast<std::size_t>(i)], EventWait::Poll) << i;
    for (std::size_t i = kSettleFrames; i < waits.size(); ++i) EXPECT_EQ(waits[i], EventWait::Forever) << i;
}

TEST(EventWait, AnEventGivesTheSettlingFramesAgain) {
    EventWaitPolicy p;
    run(p, Activity::Idle, 10);
    const auto waits = run(p, Activity::Idle, kSettleFrames + 1, /*woken=*/true);
    for (int i = 0; i < kSettleFrames; ++i) EXPECT_EQ(waits[static_cast<std::size_t>(i)], EventWait::Poll) << i;
    EXPECT_EQ(waits.back(), EventWait::Forever);
}

TEST(EventWait, BusyNeverWaits) {
    EventWaitPolicy p;
    for (EventWait w : run(p, Activity::Busy, 20)) EXPECT_EQ(w, EventWait::Poll);
    // Released: the settling frames, then sleep.
    const auto after = run(p, Activity::Idle, kSettleFrames + 1);
    EXPECT_EQ(after.front(), EventWait::Poll);
    EXPECT_EQ(after.back(), EventWait::Forever);
}

TEST(EventWait, AWorkerGetsTimedFramesNotSleep) {
    EventWaitPolicy p;
    const auto waits = run(p, Activity::Background, kSettleFrames + 5);
    for (std::size_t i = kSettleFrames; i < waits.size(); ++i) EXPECT_EQ(waits[i], EventWait::Timeout) << i;
    // The worker ends: its result is settled like an event, then the app sleeps.
    const auto after = run(p, Activity::Idle, kSettleFrames + 1);
    for (int i = 0; i < kSettleFrames; ++i) EXPECT_EQ(after[static_cast<std::size_t>(i)], EventWait::Poll) << i;
    EXPECT_EQ(after.back(), EventWait::Forever);
}

}  // namespace
}  // namespace fm::app

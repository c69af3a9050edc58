// The trial view's track runner on the real wrist frames (Autoscoper's sample): a run publishes
// every frame as it is done; Stop ends it and keeps the frames finished; a new request stops the
// running one; and the poses it finds are those of `fluoromatch track` for the same frames, seed
// and keyframes: the .tra saved from them is byte for byte the one the CLI writes.
#include <chrono>
#include <cstdlib>
#include <thread>

#include <gtest/gtest.h>

#include "common/TestData.h"
#include "core/Error.h"
#include "io/TextFile.h"
#include "scene/TrackRunner.h"
#include "scene/TrialPoseFiles.h"

namespace fm::app {
namespace {

TrackSnapshot waitUntil(const TrackRunner& runner, const std::function<bool(const TrackSnapshot&)>& done) {
    for (int i = 0; i < 6000; ++i) {  // 10 minutes at most
        const TrackSnapshot s = runner.snapshot();
        if (done(s)) return s;
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    ADD_FAILURE() << "the track runner did not get there";
    return runner.snapshot();
}

TEST(TrackRunner, PublishesStopsAndGivesTheTrackCommandsPoses) {
    if (!fm::test::sharedDataBesideRepo()) {
        if (fm::test::underCI()) FAIL() << "under CI the shared data must be ../shared/data";
        GTEST_SKIP() << "the shared data is not ../shared/data beside the repository";
    }
    const auto trialPath = fm::test::repoDir() / "data/trials/wrist.json";
    const auto trial = std::make_shared<const TrialScene>(
        loadTrialScene(readTrial(trialPath), {"radius", "ulna"}, 2));
    const BonePoses ulna(trial->frameCount, trialKeyframes(*trial, "ulna"));
    ASSERT_EQ(trial->frameCount, 3);
    ASSERT_TRUE(ulna.isKeyframe(0) && ulna.isKeyframe(1));
    TrackRunner runner;
    EXPECT_THROW(runner.start(trial, {"mc3", {0}, {}, {}}), Error);  // not loaded
    EXPECT_THROW(runner.start(trial, {"ulna", {3}, {}, {}}), Error);
    EXPECT_FALSE(runner.running());

    // 1. Stop after the first frame: it is kept, nothing after it counts as done.
    runner.start(trial, trackRequestFrom("ulna", ulna, 0, false, 2));
    TrackSnapshot s = waitUntil(runner, [](const TrackSnapshot& t) { return !t.records.empty(); });
    runner.stop();
    s = runner.snapshot();
    EXPECT_FALSE(s.running);
    EXPECT_TRUE(s.finished);
    ASSERT_GE(s.records.size(), 1u);
    EXPECT_EQ(s.records[0].frame, 0);
    EXPECT_EQ(s.records[0].status, FrameRecord::Status::Tracked);
    EXPECT_EQ(s.records[0].camerasUsed, 2);
    EXPECT_TRUE(s.stopped || s.records.size() == 3u);
    if (s.stopped && s.records.size() > 1) {
        EXPECT_EQ(s.records.back().status, FrameRecord::Status::Stopped);
    }
    EXPECT_GT(s.secondsPerFrame(), 0.0);
    EXPECT_LT(s.lastCost(), -1.0);  // biplane -gradient NCC of a bone in place (docs: -1.2)

    // 2. The newest request wins: the radius run is stopped by the ulna run from frame 1.
    runner.start(trial, trackRequestFrom("radius", BonePoses(3, trialKeyframes(*trial, "radius")),
                                         0, false, 2));
    const TrackRequest request = trackRequestFrom("ulna", ulna, 1, false, 2);
    runner.start(trial, request);
    s = waitUntil(runner, [](const TrackSnapshot& t) { return !t.running; });
    EXPECT_EQ(s.run, 3u);
    EXPECT_EQ(s.bone, "ulna");
    EXPECT_EQ(s.frames, (std::vector<int>{1, 2}));
    EXPECT_FALSE(s.stopped);
    EXPECT_TRUE(s.error.empty()) << s.error;
    ASSERT_EQ(s.records.size(), 2u);
    BonePoses found(trial->frameCount);
    for (const FrameRecord& r : s.records) {
        EXPECT_EQ(r.status, FrameRecord::Status::Tracked) << r.note;
        found.apply(r);
    }

    // 3. The CLI on the same frames (its keyframes are the trial's, as the request's).
#ifndef FM_FLUOROMATCH_EXE
    GTEST_SKIP() << "built without the fluoromatch executable";
#else
    const auto dir = fm::test::scratchDir("track_runner_cli");
    saveTra(dir / "app.tra", *trial, "ulna", found);
    const std::string command = std::string("\"") + FM_FLUOROMATCH_EXE + "\" track --trial \"" +
                                trialPath.string() + "\" --bone ulna --frames 1:2 --threads 2 --out \"" +
                                (dir / "cli.tra").string() + "\" > \"" + (dir / "cli.log").string() +
                                "\" 2>&1";
    ASSERT_EQ(std::system(command.c_str()), 0) << io::readTextFile(dir / "cli.log", 1 << 20, "log");
    const std::string cli = io::readTextFile(dir / "cli.tra", 1 << 20, "cli.tra");
    EXPECT_EQ(io::readTextFile(dir / "app.tra", 1 << 20, "app.tra"), cli);
    EXPECT_EQ(cli.substr(0, 4), "NaN,");  // frame 0 was not tracked by either
#endif
}

}  // namespace
}  // namespace fm::app

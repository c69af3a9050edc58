// The Solve section: the automatic search run from the UI on a worker thread, driven headless
// through the real buttons and checked against the known reference pose (the truth).
#include <chrono>
#include <set>
#include <string>
#include <thread>

#include "AppFixture.h"
#include "core/Error.h"
#include "drr/Drr.h"
#include "match/MatchVerdict.h"
#include "match/PoseError.h"
#include "scene/DrrCache.h"

namespace fm::test {
namespace {

// A start a few mm and degrees off the test reference (12,-8,6,30,15,-10): what a user near
// the answer would hand over. Its mTRE is about 6 mm.
constexpr std::array<double, 6> kStartOffset{3.0, 3.0, 2.0, 3.0, -3.0, 3.0};
// The judge's idea of a solved pose: well under the 2011 tolerances; the search reaches
// ~0.05 mm on this phantom (docs/search.md), so 1 mm leaves a wide margin.
constexpr double kSolvedMtreMm = 1.0;
// The start must be clearly off, or "solved" would prove nothing.
constexpr double kMinStartMtreMm = 3.0;
// Frames to wait for a solve (a few seconds of search; each frame also sleeps 2 ms). A hang
// fails the test instead of blocking the suite.
constexpr int kMaxSolveFrames = 20000;
// Recomputing the mTRE of the same two poses gives the same sum in the same order.
constexpr double kSameComputationMm = 1e-9;

class SolveUi : public HeadlessApp {
  protected:
    Pose startPose() const {
        std::array<double, 6> v = parsePose(kTestReferencePose).toArray();
        for (int k = 0; k < 6; ++k) v[k] += kStartOffset[k];
        return Pose::fromArray(v);
    }
    double mtre(const Pose& pose) const {
        const app::LoadedScene& s = *app->scene();
        return targetRegistrationError(app->state().referencePose, pose, s.setup, s.center,
                                       s.bonePoints)
            .meanMm;
    }
    Image engineDrr(const Pose& pose) const {
        DrrRenderOptions options;
        options.threads = kTestDrrThreads;
        return renderDrr(*app->scene()->drrVolume, app::appGeometry(*app->scene(), pose), options);
    }
    // One frame, with a short pause so the worker is not starved on 2 cores.
    void step() {
        script->idle(1);
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    // Opens the Solve tab and presses Solve.
    void solve() {
        script->clickWidget("tab:solve");
        script->idle(1);
        script->clickWidget("button:solve");
    }
    static bool samePose(const Pose& a, const Pose& b) { return a.toArray() == b.toArray(); }
};

TEST_F(SolveUi, SolveFromNearTheReferenceFindsItWithoutTouchingTheUsersPose) {
    const Pose start = startPose();
    app->state().userPose = start;
    script->idle(1);
    ASSERT_GT(mtre(start), kMinStartMtreMm);

    solve();
    ASSERT_TRUE(app->state().solve.running) << app->state().solve.error;
    bool sawBestPoseInUserPane = false;
    int frames = 0;
    while (app->state().solve.running && frames++ < kMaxSolveFrames) {
        step();
        ASSERT_TRUE(samePose(app->state().userPose, start)) << "the solve moved the sliders";
        if (app->state().solve.running && !samePose(app->shownUserPose(), start)) {
            // The user pane shows exactly the engine's DRR of the best pose so far.
            const Image expected = engineDrr(app->shownUserPose());
            if (app->userDrr().pixels == expected.pixels) sawBestPoseInUserPane = true;
        }
    }
    const app::SolveStatus& solve = app->state().solve;
    ASSERT_FALSE(solve.running) << "no end after " << kMaxSolveFrames << " frames";
    ASSERT_TRUE(solve.finished) << solve.error;
    EXPECT_FALSE(solve.stopped);
    EXPECT_TRUE(sawBestPoseInUserPane) << "while running, the user pane follows the search";
    EXPECT_FALSE(solve.costHistory.empty());
    EXPECT_GT(solve.evaluations, 0);
    EXPECT_LE(solve.evaluations, solve.budget);

    // The reported error is the true one, and small.
    EXPECT_NEAR(solve.poseErrorMm, mtre(solve.bestPose), kSameComputationMm);
    EXPECT_LT(solve.poseErrorMm, kSolvedMtreMm);
    const auto diff = poseDifference(app->state().referencePose, solve.bestPose);
    for (int k = 0; k < 6; ++k) EXPECT_DOUBLE_EQ(solve.error6[k], diff[k]) << "parameter " << k;
    // Judged like a user's attempt, in words: a match.
    EXPECT_TRUE(solve.matched);
    EXPECT_EQ(solve.closeness, Closeness::VeryClose);
    EXPECT_TRUE(script->widget("text:solve-verdict").max.y > 0.0f) << "the verdict is drawn";
    EXPECT_TRUE(samePose(app->state().userPose, start)) << "finished, but not applied";
    EXPECT_TRUE(samePose(app->shownUserPose(), start)) << "the user pane is the user's again";
    EXPECT_EQ(app->state().attempts, 0) << "the computer's answer is no attempt of the user's";
}

TEST_F(SolveUi, ApplyPutsTheSolutionOnTheSlidersAndItMatches) {
    app->state().userPose = startPose();
    script->clickWidget("button:match");  // one attempt of the user's, to compare with
    ASSERT_TRUE(app->state().bestUserPoseErrorMm.has_value());
    EXPECT_NEAR(*app->state().bestUserPoseErrorMm, mtre(startPose()), kSameComputationMm);

    solve();
    for (int frames = 0; app->state().solve.running && frames < kMaxSolveFrames; ++frames) step();
    ASSERT_TRUE(app->state().solve.finished) << app->state().solve.error;
    const Pose solution = app->state().solve.bestPose;

    script->clickWidget("button:apply-solution");
    EXPECT_TRUE(samePose(app->state().userPose, solution));
    EXPECT_TRUE(app->state().solve.applied);
    EXPECT_EQ(app->userDrr().pixels, engineDrr(solution).pixels) << "the DRR follows the sliders";

    script->clickWidget("tab:match");
    script->idle(1);
    script->clickWidget("button:match");
    ASSERT_TRUE(app->state().match.has_value());
    EXPECT_TRUE(app->state().match->matched) << app->state().match->verdict;
    EXPECT_EQ(app->state().attempts, 2);
    // The computer's match, not the student's: said so, drawn dim, not their best.
    EXPECT_TRUE(app->state().match->assisted);
    EXPECT_EQ(app->state().match->verdict.rfind("Assisted (Apply solution set the pose)", 0), 0u)
        << app->state().match->verdict;
    EXPECT_NEAR(*app->state().bestUserPoseErrorMm, mtre(startPose()), kSameComputationMm)
        << "an assisted match is not the user's best";
    // A new reference: the user's own again.
    script->clickWidget("button:new-reference");
    script->idle(1);
    EXPECT_FALSE(app->state().assisted);
}

// The computer's pose is the answer: hidden (while it searches and when it is done) until
// Reveal, then shown with its error.
TEST_F(SolveUi, TheComputersPoseIsHiddenUntilReveal) {
    app->state().userPose = startPose();
    solve();
    step();
    EXPECT_THROW(script->widget("text:solve-pose"), Error);
    for (int frames = 0; app->state().solve.running && frames < kMaxSolveFrames; ++frames) step();
    ASSERT_TRUE(app->state().solve.finished) << app->state().solve.error;
    step();
    EXPECT_NO_THROW(script->widget("text:solve-pose-hidden"));
    EXPECT_THROW(script->widget("text:solve-pose"), Error) << "the answer shown before Reveal";
    script->clickWidget("tab:match");
    script->idle(1);
    script->clickWidget("checkbox:reveal");
    script->clickWidget("tab:solve");
    script->idle(1);
    ASSERT_TRUE(app->state().referenceRevealed);
    EXPECT_NO_THROW(script->widget("text:solve-pose"));
    EXPECT_THROW(script->widget("text:solve-pose-hidden"), Error);
}

TEST_F(SolveUi, StopEndsTheRunPromptlyAndKeepsTheBestSoFar) {
    const Pose start = startPose();
    app->state().userPose = start;
    solve();
    // Wait until the global search is over (level 2 of 3 started): its best is already better.
    // At least one frame after the press: the Stop button is drawn by a frame that saw the run
    // (the frame of the press drew Solve, and the worker may have reported before it ended).
    int frames = 0;
    do step();
    while (app->state().solve.running && app->state().solve.level < 1 && frames++ < kMaxSolveFrames);
    ASSERT_TRUE(app->state().solve.running) << "finished before Stop could be pressed";
    script->clickWidget("button:stop-solve");
    // Stop waits for the current batch only: the run is over once the click's frames are.
    const app::SolveStatus& solve = app->state().solve;
    EXPECT_FALSE(solve.running);
    EXPECT_FALSE(app->solver().running());
    EXPECT_TRUE(solve.finished);
    EXPECT_TRUE(solve.stopped);
    EXPECT_LT(solve.evaluations, solve.budget) << "stopped before the end of its budget";
    EXPECT_FALSE(samePose(solve.bestPose, start)) << "the best so far is kept, not the start";
    EXPECT_LT(solve.poseErrorMm, mtre(start)) << "the best so far improved on the start";
    EXPECT_NEAR(solve.poseErrorMm, mtre(solve.bestPose), kSameComputationMm);
    // The stopped answer is judged like a user's: match or not, as the engine's judge says.
    const MatchVerdict judged =
        judgeMatch(app->state().referencePose, solve.bestPose, mtre(solve.bestPose));
    EXPECT_EQ(solve.matched, judged.match);
    EXPECT_EQ(solve.closeness, judged.closeness);
    EXPECT_TRUE(samePose(app->state().userPose, start)) << "Stop does not apply the solution";
}

// Find: the camera's pose from nothing (engine findScenePose). The user stays at the centre pose,
// far from the reference; the finder's stages are shown as it goes, the user pane stays the
// user's (there is no best pose to follow before the end), and the answer is judged like an
// attempt: a match, well under the tolerances.
TEST_F(SolveUi, FindReachesTheReferenceFromNothing) {
    const Pose centre{};
    app->state().userPose = centre;
    script->idle(1);
    // Twice the capture range of a search from a start (10 mm mTRE, docs/search.md).
    ASSERT_GT(mtre(centre), 20.0) << "the centre pose must be far from the reference";
    script->clickWidget("tab:solve");
    script->idle(1);
    script->clickWidget("button:find");
    ASSERT_TRUE(app->state().solve.running) << app->state().solve.error;
    EXPECT_TRUE(app->state().solve.find);
    std::set<std::string> stages;
    for (int frames = 0; app->state().solve.running && frames < kMaxSolveFrames; ++frames) {
        step();
        stages.insert(app->state().solve.stage);
        ASSERT_TRUE(samePose(app->state().userPose, centre)) << "Find moved the sliders";
        ASSERT_TRUE(samePose(app->shownUserPose(), centre)) << "the user pane left the user's pose";
    }
    const app::SolveStatus& solve = app->state().solve;
    ASSERT_TRUE(solve.finished) << solve.error;
    EXPECT_FALSE(solve.stopped);
    EXPECT_TRUE(stages.count("find: scan") || stages.count("find: refine") || stages.count("find: finish"))
        << "no stage of the finder shown";
    EXPECT_GT(solve.evaluations, 0);
    EXPECT_NEAR(solve.poseErrorMm, mtre(solve.bestPose), kSameComputationMm);
    EXPECT_LT(solve.poseErrorMm, kSolvedMtreMm);
    EXPECT_TRUE(solve.matched);
    EXPECT_TRUE(samePose(app->state().userPose, centre)) << "finished, but not applied";
}

// Stop during a Find ends it after the stage under way and keeps that stage's best: a pose, not
// the centre it started from, judged like any answer.
TEST_F(SolveUi, StopEndsAFindAndKeepsTheBestOfItsLastStage) {
    app->state().userPose = Pose{};
    script->clickWidget("tab:solve");
    script->idle(1);
    script->clickWidget("button:find");
    int frames = 0;  // at least one frame after the press, as above
    do step();
    while (app->state().solve.running && app->state().solve.stage.rfind("find: ", 0) != 0 &&
           frames++ < kMaxSolveFrames);
    ASSERT_TRUE(app->state().solve.running) << "finished before Stop could be pressed";
    script->clickWidget("button:stop-solve");
    const app::SolveStatus& solve = app->state().solve;
    EXPECT_FALSE(solve.running);
    ASSERT_TRUE(solve.finished) << solve.error;
    EXPECT_TRUE(solve.stopped);
    EXPECT_FALSE(samePose(solve.bestPose, Pose{})) << "a stage's best is kept, not the start";
    EXPECT_NEAR(solve.poseErrorMm, mtre(solve.bestPose), kSameComputationMm);
    EXPECT_TRUE(samePose(app->state().userPose, Pose{})) << "Stop does not apply the answer";
}

TEST_F(SolveUi, ReloadingTheSceneOrANewReferenceEndsTheSolve) {
    app->state().userPose = startPose();
    solve();
    ASSERT_TRUE(app->state().solve.running);
    script->clickWidget("tab:match");
    script->idle(1);
    script->clickWidget("button:new-reference");
    EXPECT_FALSE(app->solver().running()) << "a solution belongs to its reference";
    EXPECT_FALSE(app->state().solve.running);
    EXPECT_FALSE(app->state().solve.finished) << "the old result is not shown";

    solve();
    ASSERT_TRUE(app->state().solve.running);
    // Reload (the Parameters pane): the search of the old scene must end.
    script->clickWidget("button:knee");
    EXPECT_FALSE(app->solver().running());
    app->waitForLoad();
    script->idle(1);
    EXPECT_FALSE(app->state().solve.running);
    EXPECT_FALSE(app->state().solve.finished);
}

}  // namespace
}  // namespace fm::test

// The trial controls of the workspace on the real wrist trial (data/trials/wrist.json), driven
// through the UI (headless OSMesa, scripted mouse and keys): Track forward from a keyframe runs
// with live progress, the panes follow the frames tracked and the saved .tra holds the poses
// `fluoromatch track` writes for them; Stop keeps the finished frames; keyframes set and clear
// and are saved in the trial JSON; play steps through the frames and pause stops; the pose plot
// holds the .tra pose's numbers; a bone moved off its keyframe, put back roughly with the arrow
// keys and Solved ends at the keyframe; and a golden image of the trial view.
#include <gtest/gtest.h>

#include <imgui.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <thread>

#include "GoldenImage.h"
#include "WorkspaceFixture.h"
#include "common/TestData.h"
#include "core/Error.h"
#include "io/TextFile.h"
#include "pose/AutoscoperTra.h"
#include "render/Screenshot.h"
#include "scene/ObjectPoseParameterization.h"
#include "track/PoseErrors.h"
#include "trial/Trial.h"
#include "ui/UiScript.h"
#include "workspace/WorkspaceApp.h"

namespace fm::test {
namespace {

namespace fs = std::filesystem;

class TrackUi : public WorkspaceFixture {
  public:
    void SetUp() override { openTrial("data/trials/wrist.json"); }
    int object(const std::string& name) const {
        for (int k = 0; k < model->objectCount(); ++k)
            if (model->objectName(k) == name) return k;
        throw std::runtime_error("no object " + name);
    }
    RigidTransform keyframe(const std::string& bone, int frame) const {
        return trialKeyframes(model->trial(), bone).at(frame);
    }
    const std::optional<RigidTransform>& poseAt(int frame, int k) const {
        return app->state().poses.at(static_cast<std::size_t>(frame)).at(static_cast<std::size_t>(k));
    }
    glm::dvec3 pivot(int k) const { return defaultPivot(*model->scene().objects[static_cast<std::size_t>(k)].model); }
    // Draws frames (with pauses, the worker runs meanwhile) until `done`, 10 minutes at most.
    void idleUntil(const std::function<bool()>& done) {
        for (int i = 0; i < 12000 && !done(); ++i) {  // the UI draws 20 frames a second at most
            script->idle(1);
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
        }
        ASSERT_TRUE(done());
    }
};

std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string l; std::getline(in, l);) out.push_back(l);
    return out;
}

TEST_F(TrackUi, TrackForwardFollowsTheFramesAndSavesTheTraTheCliWrites) {
    const int ulna = object("ulna");
    script->clickWidget("select:object-ulna");
    script->clickWidget("button:frame-next");
    script->idle(1);
    ASSERT_EQ(app->state().frame, 1);
    ASSERT_EQ(app->state().selected, ulna);

    script->clickWidget("button:track-forward");
    bool sawRunning = false;
    idleUntil([&] {
        // A run may end before the UI first polls it (a loaded machine): finished counts too.
        sawRunning = sawRunning || app->state().track.run.running || app->state().track.run.finished;
        return sawRunning && !app->state().track.run.running;
    });
    script->idle(2);
    const app::TrackRunView& run = app->state().track.run;
    EXPECT_TRUE(run.error.empty()) << run.error;
    EXPECT_EQ(run.object, "ulna");
    EXPECT_EQ(run.done, 2);
    EXPECT_EQ(run.total, 2);
    EXPECT_FALSE(run.stopped);
    EXPECT_LT(run.lastCost, -1.0);  // both views, the bone in place (docs: -1.15)
    EXPECT_EQ(app->state().frame, 2);  // the panes followed the run to its last frame
    ASSERT_TRUE(poseAt(2, ulna));
    ASSERT_TRUE(poseAt(1, ulna));

    // Save .tra: rows 1 and 2 are the CLI's for the same frames (row 0 is the keyframe here,
    // NaN in the CLI's file, which tracked frames 1 and 2 only).
    const fs::path dir = scratchDir("track-ui-save");
    script->clickWidget("input:tra-path");
    script->type((dir / "ulna.tra").string());
    script->pressKey(ImGuiKey_Enter);
    script->clickWidget("button:save-tra");
    script->idle(1);
    ASSERT_FALSE(app->state().track.messageFailed) << app->state().track.message;
    const std::string command = std::string("\"") + FM_FLUOROMATCH_EXE + "\" track --trial \"" +
                                (repoDir() / "data/trials/wrist.json").string() +
                                "\" --bone ulna --frames 1:2 --threads 2 --out \"" + (dir / "cli.tra").string() +
                                "\" > \"" + (dir / "cli.log").string() + "\" 2>&1";
    ASSERT_EQ(std::system(command.c_str()), 0) << io::readTextFile(dir / "cli.log", 1 << 20, "log");
    const auto ours = lines(io::readTextFile(dir / "ulna.tra", 1 << 20, "ulna.tra"));
    const auto cli = lines(io::readTextFile(dir / "cli.tra", 1 << 20, "cli.tra"));
    ASSERT_EQ(ours.size(), 3u);
    ASSERT_EQ(cli.size(), 3u);
    EXPECT_EQ(ours[1], cli[1]);
    EXPECT_EQ(ours[2], cli[2]);
    EXPECT_NE(ours[0].substr(0, 3), "NaN");  // frame 0 has its keyframe in the workspace

    // The plot holds the .tra pose's x, y, z, yaw, pitch, roll of every frame.
    const TraFile tra = readTra(dir / "ulna.tra");
    const app::PoseCurves& curves = app->state().track.curves;
    for (std::size_t f = 0; f < 3; ++f) {
        double v[6];
        xyzyprFromTransform(*tra.frames[f][0], v);
        for (int i = 0; i < 3; ++i) EXPECT_NEAR(curves.values[static_cast<std::size_t>(i)][f], v[i], 1e-3);
        for (int i = 3; i < 6; ++i)
            EXPECT_NEAR(std::remainder(curves.values[static_cast<std::size_t>(i)][f] - v[i], 360.0), 0.0, 1e-3);
    }
}

TEST_F(TrackUi, StopKeepsTheFinishedFrames) {
    const int ulna = object("ulna");
    script->clickWidget("select:object-ulna");
    script->idle(1);
    const RigidTransform before = *poseAt(0, ulna);
    script->clickWidget("button:track-forward");
    idleUntil([&] { return app->state().track.run.done >= 1; });
    script->clickWidget("button:track-stop");
    idleUntil([&] { return !app->state().track.run.running; });
    script->idle(1);
    const app::TrackRunView& run = app->state().track.run;
    EXPECT_GE(run.done, 1);
    EXPECT_TRUE(run.stopped || run.done == 3);
    // Frame 0 was registered from its keyframe: near it, not equal to it.
    const RigidTransform after = *poseAt(0, ulna);
    EXPECT_GT(glm::length(after.translation - before.translation), 1e-6);
    EXPECT_LT(centreError(after, before, pivot(ulna)), 1.0);
}

TEST_F(TrackUi, KeyframesSetClearAndSaveAndPlayStepsTheFrames) {
    const int radius = object("radius");
    script->clickWidget("button:frame-next");
    script->clickWidget("button:frame-next");
    script->idle(1);
    ASSERT_EQ(app->state().frame, 2);
    EXPECT_EQ(app->state().track.keyframes.at(radius).count(2), 0u);
    script->clickWidget("button:keyframe-set");
    script->idle(1);
    ASSERT_EQ(app->state().track.keyframes.at(radius).count(2), 1u);
    EXPECT_EQ(app->state().track.keyframes.at(radius).at(2).translation, poseAt(2, radius)->translation);
    const fs::path path = scratchDir("track-ui-keyframes") / "wrist.json";
    app->state().track.keyframesPath = path.string();
    script->clickWidget("button:save-keyframes");
    script->idle(1);
    ASSERT_FALSE(app->state().track.messageFailed) << app->state().track.message;
    const Trial saved = readTrial(path);
    ASSERT_EQ(saved.keyframes.at("radius").size(), 3u);
    const RigidTransform tra2 = traPoseFromObject(model->trial(), "radius", *poseAt(2, radius));
    EXPECT_NEAR(glm::length(saved.keyframes.at("radius")[2].worldFromVolume.translation - tra2.translation), 0.0, 1e-6);
    script->clickWidget("button:keyframe-clear");
    script->idle(1);
    EXPECT_EQ(app->state().track.keyframes.at(radius).count(2), 0u);

    // Play goes round the three frames; Pause stays.
    script->clickWidget("button:play");
    std::vector<int> seen;
    idleUntil([&] {
        if (seen.empty() || seen.back() != app->state().frame) seen.push_back(app->state().frame);
        return seen.size() >= 3;
    });
    EXPECT_EQ(seen[0], 2);
    EXPECT_EQ(seen[1], 0);
    EXPECT_EQ(seen[2], 1);
    script->clickWidget("button:play");  // now Pause
    script->idle(1);
    const int paused = app->state().frame;
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    script->idle(3);
    EXPECT_EQ(app->state().frame, paused);
    EXPECT_FALSE(app->state().track.playing);
}

// Frames where a bone has no pose show it where the nearest set pose puts it, and store nothing:
// after playing through them, Save .tra writes NaN there and the plot has no point (before, the
// pose of the frame played from was copied in and saved as if tracked).
TEST_F(TrackUi, PlayingThroughUntrackedFramesStoresNoPose) {
    const int radius = object("radius"), mc3 = object("mc3");
    // The trial: radius keyframes at frames 0 and 1, none at 2; mc3 none at all.
    ASSERT_TRUE(poseAt(0, radius) && poseAt(1, radius));
    ASSERT_FALSE(poseAt(2, radius));
    for (int f = 0; f < 3; ++f) ASSERT_FALSE(poseAt(f, mc3)) << f;

    script->clickWidget("select:object-radius");
    script->clickWidget("button:play");
    std::vector<int> seen;
    idleUntil([&] {
        if (seen.empty() || seen.back() != app->state().frame) seen.push_back(app->state().frame);
        return seen.size() >= 5;  // 0 1 2 0 1: every frame left and reached again
    });
    script->clickWidget("button:play");  // Pause
    script->idle(1);
    EXPECT_FALSE(poseAt(2, radius));
    for (int f = 0; f < 3; ++f) EXPECT_FALSE(poseAt(f, mc3)) << f;
    EXPECT_EQ(poseAt(1, radius)->translation, keyframe("radius", 1).translation);

    // Shown at frame 2: the nearest earlier set pose, frame 1's keyframe.
    for (int f = app->state().frame; f < 2; ++f) {  // next stops at the last frame
        script->clickWidget("button:frame-next");
        script->idle(1);
    }
    ASSERT_EQ(app->state().frame, 2);
    ASSERT_TRUE(app->pose(radius));
    EXPECT_EQ(app->pose(radius)->translation, keyframe("radius", 1).translation);
    ASSERT_TRUE(app->pose(mc3));  // shown at its placement, where the cameras look
    EXPECT_FALSE(poseAt(2, radius));

    const fs::path dir = scratchDir("track-ui-untracked");
    app->state().track.traPath = (dir / "radius.tra").string();
    script->clickWidget("button:save-tra");
    script->idle(1);
    ASSERT_FALSE(app->state().track.messageFailed) << app->state().track.message;
    const auto rows = lines(io::readTextFile(dir / "radius.tra", 1 << 20, "radius.tra"));
    ASSERT_EQ(rows.size(), 3u);
    EXPECT_NE(rows[0].substr(0, 3), "NaN");
    EXPECT_NE(rows[1].substr(0, 3), "NaN");
    EXPECT_EQ(rows[2].substr(0, 3), "NaN") << rows[2];
    for (std::size_t i = 0; i < 6; ++i) EXPECT_TRUE(std::isnan(app->state().track.curves.values[i][2])) << i;

    script->clickWidget("select:object-mc3");
    script->idle(1);
    app->state().track.traPath = (dir / "mc3.tra").string();
    script->clickWidget("button:save-tra");
    script->idle(1);
    ASSERT_FALSE(app->state().track.messageFailed) << app->state().track.message;
    for (const std::string& row : lines(io::readTextFile(dir / "mc3.tra", 1 << 20, "mc3.tra")))
        EXPECT_EQ(row.substr(0, 3), "NaN") << row;
}

// The "first pose by hand in the app, then refined": the bone is moved off its keyframe
// (6, -4, 5 mm; 8, -6, 10 deg about the world axes), then put back roughly with the arrow keys
// as one would by eye (z and the last angle left 2 off), then Solve. Returns the distances from
// the keyframe (printed for docs/tracking.md).
struct HandResult {
    double offMm = 0, offDeg = 0, handMm = 0, handDeg = 0, endMm = 0, endDeg = 0, similarity = 0;
};

HandResult putBackByHandAndSolve(TrackUi& t, const std::string& bone, int frame) {
    static constexpr std::array<double, 6> kDisplacement{6, -4, 5, 8, -6, 10};
    static constexpr std::array<int, 6> kHandSteps{-6, 4, -3, -8, 6, -8};  // 1 mm / 1 deg per press
    app::WorkspaceApp& app = *t.app;
    app::UiScript& script = *t.script;
    const int k = t.object(bone);
    if (app.state().frame != frame) {
        app.state().requests.frame = frame;
        script.idle(1);
    }
    script.clickWidget("select:object-" + bone);
    script.idle(1);
    EXPECT_EQ(app.state().controls.object, k);
    const RigidTransform key = t.keyframe(bone, frame);
    EXPECT_LT(centreError(*t.poseAt(frame, k), key, t.pivot(k)), 1e-9);
    // Moved off: the controls written directly (the "wrong" start), then rebased there (another
    // object selected and back).
    for (std::size_t p = 0; p < 6; ++p) app.state().controls.values[p] += kDisplacement[p];
    script.idle(1);
    const RigidTransform off = *t.poseAt(frame, k);
    script.clickWidget(bone == "radius" ? "select:object-ulna" : "select:object-radius");
    script.clickWidget("select:object-" + bone);
    script.idle(1);
    // By hand: Down to the control, Left/Right one step at a time.
    for (int p = 0; p < 6; ++p) {
        while (app.state().controls.selected != p) script.pressKey(ImGuiKey_DownArrow);
        for (int i = 0; i < std::abs(kHandSteps[static_cast<std::size_t>(p)]); ++i)
            script.pressKey(kHandSteps[static_cast<std::size_t>(p)] > 0 ? ImGuiKey_RightArrow : ImGuiKey_LeftArrow);
    }
    script.idle(1);
    const RigidTransform hand = *t.poseAt(frame, k);
    script.clickWidget("button:solve");
    app.waitForSolve();
    const app::WorkspaceSolve& s = app.state().solve;
    EXPECT_TRUE(s.finished && s.result) << s.error;
    const RigidTransform solved = *t.poseAt(frame, k);
    HandResult r;
    r.offMm = centreError(off, key, t.pivot(k));
    r.offDeg = angleErrorDeg(off, key);
    r.handMm = centreError(hand, key, t.pivot(k));
    r.handDeg = angleErrorDeg(hand, key);
    r.endMm = centreError(solved, key, t.pivot(k));
    r.endDeg = angleErrorDeg(solved, key);
    r.similarity = s.similarity;
    std::printf("%s frame %d: moved off %.2f mm %.2f deg; by hand %.2f mm %.2f deg; after Solve %.3f mm %.2f deg "
                "from the keyframe, similarity %.4f (%s)\n",
                bone.c_str(), frame, r.offMm, r.offDeg, r.handMm, r.handDeg, r.endMm, r.endDeg, r.similarity,
                s.summary.c_str());
    return r;
}

// Exactly the same poses (every frame, every object, set or not).
bool samePoses(const std::vector<std::vector<std::optional<RigidTransform>>>& a,
               const std::vector<std::vector<std::optional<RigidTransform>>>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t f = 0; f < a.size(); ++f) {
        if (a[f].size() != b[f].size()) return false;
        for (std::size_t k = 0; k < a[f].size(); ++k) {
            if (a[f][k].has_value() != b[f][k].has_value()) return false;
            if (a[f][k] && (a[f][k]->rotation != b[f][k]->rotation || a[f][k]->translation != b[f][k]->translation))
                return false;
        }
    }
    return true;
}

// Undo: a nudge, a Track run and a Solve are one step each, back to the poses exactly as they
// were; the Solve of a bone without masks is judged by searches from independent starts; the Track
// line belongs to the object it tracked.
TEST_F(TrackUi, UndoTakesBackASolveATrackRunAndANudgeOneStepEach) {
    script->clickWidget("select:object-ulna");
    script->idle(1);
    const auto atStart = app->state().poses;
    const std::size_t steps = app->state().undo.steps.size();
    script->pressKey(ImGuiKey_RightArrow);
    script->pressKey(ImGuiKey_RightArrow);
    script->idle(1);
    ASSERT_FALSE(samePoses(app->state().poses, atStart)) << "the nudges moved nothing";
    EXPECT_EQ(app->state().undo.steps.size(), steps + 2) << "one step per nudge";
    const auto nudged = app->state().poses;

    script->clickWidget("button:track-forward");
    idleUntil([&] { return app->state().track.run.running; });
    idleUntil([&] { return !app->state().track.run.running; });
    script->idle(2);
    ASSERT_TRUE(app->state().track.run.error.empty()) << app->state().track.run.error;
    // Every frame of the run judged, the counts shown (coloured by the worst).
    const app::TrackRunView& run = app->state().track.run;
    EXPECT_EQ(run.ok + run.doubtful + run.lost, run.done);
    EXPECT_EQ(static_cast<int>(run.notOk.size()), run.doubtful + run.lost);
    EXPECT_NO_THROW(script->widget("text:track-verdicts"));
    const auto tracked = app->state().poses;
    ASSERT_FALSE(samePoses(tracked, nudged));
    // Another object selected: the ulna's run is not shown as its.
    script->clickWidget("select:object-radius");
    script->idle(1);
    EXPECT_THROW(script->widget("text:track-status"), Error);
    script->clickWidget("select:object-ulna");
    script->idle(1);
    EXPECT_NO_THROW(script->widget("text:track-status"));

    app->state().requests.frame = 0;
    script->idle(1);
    ASSERT_NO_FATAL_FAILURE(solveAndWait());
    const app::WorkspaceSolve& s = app->state().solve;
    // No mask: the verdict rests on searches from independent starts, and says so.
    EXPECT_EQ(s.checkText.rfind(toString(s.check), 0), 0u) << s.checkText;
    EXPECT_NE(s.checkText.find("searches from different starts"), std::string::npos) << s.checkText;
    EXPECT_NE(s.check, app::WorkspaceSolve::Check::Lost) << s.checkText;
    ASSERT_FALSE(samePoses(app->state().poses, tracked)) << "the Solve changed nothing";

    script->clickWidget("button:undo");
    script->idle(1);
    EXPECT_TRUE(samePoses(app->state().poses, tracked)) << app->state().undoMessage;
    EXPECT_NE(app->state().undoMessage.find("Solve of ulna in frame 0"), std::string::npos)
        << app->state().undoMessage;
    script->clickWidget("button:undo");
    script->idle(1);
    EXPECT_TRUE(samePoses(app->state().poses, nudged)) << app->state().undoMessage;
    EXPECT_NE(app->state().undoMessage.find("Track of ulna forward from frame 0"), std::string::npos);
    script->pressKey(ImGuiKey_Z, true);  // Ctrl+Z
    script->pressKey(ImGuiKey_Z, true);
    script->idle(1);
    EXPECT_TRUE(samePoses(app->state().poses, atStart)) << app->state().undoMessage;
    EXPECT_EQ(app->state().undo.steps.size(), steps);
}

TEST_F(TrackUi, ABonePutBackByHandAndSolvedEndsAtItsKeyframe) {
    const HandResult r = putBackByHandAndSolve(*this, "radius", 0);
    EXPECT_GT(r.offMm, 5.0);
    EXPECT_GT(r.offDeg, 10.0);
    EXPECT_LT(r.handMm, r.offMm);
    // Restarts +-3 mm / +-3 deg around the keyframes came back within 0.27 mm (docs/tracking.md).
    EXPECT_LT(r.endMm, 0.5);
    EXPECT_LT(r.endDeg, r.handDeg);
}

// Run by hand (--gtest_also_run_disabled_tests) for docs/tracking.md: both bones put back by hand
// and solved at both keyframes, frame 2 tracked from frame 1 in the app, and the trial view at
// each frame written to the scratch folder (tracking-app-wrist-frameK.png).
TEST_F(TrackUi, DISABLED_DocImagesOfTheWristFrames) {
    for (int frame : {0, 1})
        for (const char* bone : {"radius", "ulna"}) {
            const HandResult r = putBackByHandAndSolve(*this, bone, frame);
            EXPECT_LT(r.endMm, 0.5) << bone << " frame " << frame;
        }
    for (const char* bone : {"radius", "ulna"}) {
        script->clickWidget(std::string("select:object-") + bone);
        app->state().requests.frame = 1;
        script->idle(1);
        script->clickWidget("button:track-forward");
        idleUntil([&] { return app->state().track.run.running; });
        idleUntil([&] { return !app->state().track.run.running; });
        script->idle(2);
        const app::TrackRunView& run = app->state().track.run;
        std::printf("%s tracked from frame 1: %d of %d frames, %.2f s/frame, last cost %.4f, %s\n", bone, run.done,
                    run.total, run.secondsPerFrame, run.lastCost, run.lastNote.c_str());
    }
    script->clickWidget("select:object-radius");
    script->clickWidget("checkbox:object-mc3");  // no keyframe: it sits where the cameras look
    app->state().source = "data/trials/wrist.json";
    script->moveTo({1060.0f, 200.0f});  // over the 3D view: no tooltip
    const fs::path dir = scratchDir("track-ui-doc-images");
    for (int frame : {0, 1, 2}) {
        app->state().requests.frame = frame;
        script->idle(3);
        const fs::path out = dir / ("tracking-app-wrist-frame" + std::to_string(frame) + ".png");
        render::writePng(out, app->capture());
        std::printf("wrote %s\n", out.string().c_str());
    }
}

TEST_F(TrackUi, GoldenTrialView) {
    app->state().source = "data/trials/wrist.json";  // as opened from the repository (not this checkout's path)
    script->idle(1);
    EXPECT_TRUE(matchesGolden(app->capture(), "workspace_wrist_track"));
}

}  // namespace
}  // namespace fm::test

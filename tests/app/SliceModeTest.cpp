// The MRI slice mode of the app (docs/mri.md), driven through the real UI: the mode switch,
// the panes showing slices, Match and its hints, Solve, the plane missing the volume, and an
// MRI file opening in the slice mode by itself.
#include <algorithm>
#include <chrono>
#include <thread>

#include "AppFixture.h"
#include "common/TestData.h"
#include "scene/SliceImages.h"
#include "slice/SlicePoseError.h"

namespace fm::test {
namespace {

class SliceModeUi : public HeadlessApp {
  protected:
    void switchToSlices() {
        script->clickWidget("radio:mode-slice");
        script->idle(2);
        ASSERT_EQ(app->state().mode, app::ImagingMode::Slice);
    }
    SampledSlice slice(const Pose& pose) const {
        return app::renderAppSlice(*app->scene(), pose, 1, kTestDrrThreads);
    }
    double mtre(const Pose& pose) const {
        const app::LoadedScene& s = *app->scene();
        return sliceTargetError(app->state().referencePose, pose, s.sliceSetup, s.center,
                                s.foregroundPoints)
            .meanMm;
    }
};

TEST_F(SliceModeUi, TheSwitchTurnsBothPanesIntoSlices) {
    ASSERT_EQ(app->state().mode, app::ImagingMode::Xray);  // the knee phantom is a CT
    const Image drr = app->userDrr();
    switchToSlices();
    // A new hidden reference of the new kind; both panes hold the engine's slices exactly.
    EXPECT_EQ(app->referenceDrr().pixels, slice(app->state().referencePose).image.pixels);
    EXPECT_EQ(app->userDrr().pixels, slice(app->state().userPose).image.pixels);
    EXPECT_NE(app->userDrr().pixels, drr.pixels);
    EXPECT_FALSE(app->state().userSliceEmpty);
    script->clickWidget("radio:mode-xray");
    script->idle(2);
    EXPECT_EQ(app->state().mode, app::ImagingMode::Xray);
    EXPECT_EQ(app->userDrr().pixels, drr.pixels);
}

TEST_F(SliceModeUi, MatchJudgesSlicesWithTheSameHints) {
    switchToSlices();
    const Pose reference = app->state().referencePose;
    app->state().userPose = reference;
    script->clickWidget("button:match");
    script->idle(1);
    ASSERT_TRUE(app->state().match.has_value());
    EXPECT_TRUE(app->state().match->matched);
    EXPECT_NEAR(app->state().match->poseErrorMm, 0.0, 1e-9);
    EXPECT_NEAR(app->state().match->ncc, 1.0, 1e-6);  // the same slice
    // 8 mm too far along x: the hint names x, too high, and the slice mTRE is 8 mm.
    Pose off = reference;
    off.offset.x += 8.0;
    app->state().userPose = off;
    script->clickWidget("button:match");
    script->idle(1);
    const app::MatchOutcome& m = *app->state().match;
    EXPECT_FALSE(m.matched);
    EXPECT_EQ(m.furthestParameter, app::kOffsetX);
    EXPECT_EQ(m.direction[app::kOffsetX], +1);
    EXPECT_NEAR(m.poseErrorMm, 8.0, 1e-9);
    EXPECT_EQ(app->state().attempts, 2);
}

TEST_F(SliceModeUi, SolveFindsTheHiddenSlice) {
    switchToSlices();
    std::array<double, 6> start = app->state().referencePose.toArray();
    for (int k = 0; k < 6; ++k) start[k] += k % 2 ? -3.0 : 3.0;
    app->state().userPose = Pose::fromArray(start);
    ASSERT_GT(mtre(app->state().userPose), 3.0);
    script->clickWidget("tab:solve");
    script->idle(1);
    script->clickWidget("button:solve");
    for (int f = 0; f < 20000 && !app->state().solve.finished; ++f) {
        script->idle(1);
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
        ASSERT_TRUE(app->state().solve.error.empty()) << app->state().solve.error;
    }
    ASSERT_TRUE(app->state().solve.finished);
    EXPECT_LT(app->state().solve.poseErrorMm, 1.0)
        << "reference " << formatPose(app->state().referencePose) << " found "
        << formatPose(app->state().solve.bestPose);
    EXPECT_NEAR(app->state().solve.poseErrorMm, mtre(app->state().solve.bestPose), 1e-9);
    // Solve never moves the user's pose by itself.
    EXPECT_EQ(app->state().userPose.toArray(), start);
}

TEST_F(SliceModeUi, APlaneMissingTheVolumeShowsNoDataAndSaysSo) {
    switchToSlices();
    // The knee box is 220 mm wide: a plane at the slider's end of the x range, turned to
    // sagittal, lies beyond it.
    Pose p;
    p.azimuthDeg = 90.0;
    p.offset.x = app->state().translationRangeMm;
    app->state().userPose = p;
    script->idle(2);
    ASSERT_TRUE(slice(p).empty());
    EXPECT_TRUE(app->state().userSliceEmpty);
    for (float v : app->userDrr().pixels) ASSERT_EQ(v, 0.0f);
    script->clickWidget("button:match");  // judged by the parameters, not NaN
    script->idle(1);
    ASSERT_TRUE(app->state().match.has_value());
    EXPECT_FALSE(app->state().match->matched);
    EXPECT_EQ(app->state().match->ncc, 0.0);
    EXPECT_TRUE(std::isfinite(app->state().match->poseErrorMm));
}

TEST_F(SliceModeUi, OrientationLettersFollowTheSlicePlane) {
    switchToSlices();
    // The zero pose is a coronal slice seen from the front (docs/mri.md): columns towards the
    // patient's left, rows towards the feet.
    app->state().userPose = Pose{};
    script->idle(2);
    EXPECT_EQ(app->state().userEdges.left, "R");
    EXPECT_EQ(app->state().userEdges.right, "L");
    EXPECT_EQ(app->state().userEdges.top, "S");
    EXPECT_EQ(app->state().userEdges.bottom, "I");
    // Sagittal (azimuth 90): anterior and posterior at the sides, superior still at the top.
    app->state().userPose.azimuthDeg = 90.0;
    script->idle(2);
    const std::string sides = app->state().userEdges.left + app->state().userEdges.right;
    EXPECT_TRUE(sides == "AP" || sides == "PA") << sides;
    EXPECT_EQ(app->state().userEdges.top, "S");
    // Axial (elevation 90): the image's rows run front to back, its columns right to left.
    app->state().userPose = Pose::fromArray({0, 0, 0, 0, 90, 0});
    script->idle(2);
    const std::string rows = app->state().userEdges.top + app->state().userEdges.bottom;
    const std::string columns = app->state().userEdges.left + app->state().userEdges.right;
    EXPECT_TRUE(rows == "AP" || rows == "PA") << rows;
    EXPECT_TRUE(columns == "RL" || columns == "LR") << columns;
}

TEST_F(SliceModeUi, ReadoutSaysNoDataOutsideTheVolume) {
    switchToSlices();
    // A plane 40 mm off the centre, turned 30 deg: part of its grid lies outside the box.
    const Pose pose = Pose::fromArray({40, 0, 0, 30, 0, 0});
    app->state().userPose = pose;
    script->idle(2);
    const SampledSlice s = slice(pose);
    ASSERT_GT(s.dataPixels(), 0u);
    ASSERT_LT(s.dataPixels(), s.mask.inside.size());
    const app::WidgetRect r = script->widget("image:user");
    const auto centreOf = [&](int col, int row) {
        return glm::vec2(r.min.x + (col + 0.5f) / s.image.width * (r.max.x - r.min.x),
                         r.min.y + (row + 0.5f) / s.image.height * (r.max.y - r.min.y));
    };
    // The first pixel with data and the first without, along the middle row.
    const int row = s.image.height / 2;
    int with = -1, without = -1;
    for (int c = 0; c < s.image.width; ++c) {
        if (s.mask.at(c, row) && with < 0) with = c;
        if (!s.mask.at(c, row) && without < 0) without = c;
    }
    ASSERT_GE(with, 0);
    ASSERT_GE(without, 0);
    script->moveTo(centreOf(with, row));
    ASSERT_TRUE(app->state().readout.valid);
    EXPECT_EQ(app->state().readout.col, with);
    EXPECT_TRUE(app->state().readout.hasData);
    EXPECT_EQ(app->state().readout.value, s.image.at(with, row));
    script->moveTo(centreOf(without, row));
    ASSERT_TRUE(app->state().readout.valid);
    EXPECT_EQ(app->state().readout.col, without);
    EXPECT_FALSE(app->state().readout.hasData) << "outside the box: no data, not a 0";
}

// One App per test: the fixture opens the MRI instead of the knee.
class MriFileUi : public SliceModeUi {
  protected:
    void SetUp() override {
        FM_REQUIRE_SHARED_DATA("mricron-ch2/ch2bet.nii.gz");
        app::AppOptions options = testAppOptions();
        options.volumeSpec = (sharedDataDir() / "mricron-ch2/ch2bet.nii.gz").string();
        options.referencePose.reset();
        start(options);
    }
};

TEST_F(MriFileUi, AnMriFileOpensInTheSliceMode) {
    EXPECT_TRUE(app->scene()->looksLikeMri);
    EXPECT_EQ(app->state().mode, app::ImagingMode::Slice);
    EXPECT_EQ(app->referenceDrr().pixels, slice(app->state().referencePose).image.pixels);
    EXPECT_GT(app->scene()->foregroundPoints.size(), 1000u);
    EXPECT_GT(app->state().bone.triangles, 10000u);  // the brain's surface
}

// Real MRIs get real references: on ch2 (a head filling a fifth of the slice grid) every draw
// fell back to the plain coronal or sagittal plane through the centre. Each reference is a
// random plane, never a standard one, at least kMinSliceReferenceMtreMm from the start, and
// cuts at least half the foreground its standard plane does.
TEST(SliceReferences, RealMrisGetRandomPlanesAwayFromTheStart) {
    for (const char* file : {"mricron-ch2/ch2bet.nii.gz", "totalseg-example-mr/example_mr_sm.nii.gz"}) {
        FM_REQUIRE_SHARED_DATA(file);
        const auto scene = app::buildScene((sharedDataDir() / file).string(), [](const std::string&, float) {});
        ASSERT_FALSE(scene->foregroundPoints.empty()) << file;
        const Pose start;  // where the game starts: the coronal plane through the centre
        std::vector<std::array<double, 6>> seen;
        for (std::uint64_t seed = 1; seed <= 11; ++seed)
            for (Difficulty d : {Difficulty::Easy, Difficulty::Hard}) {
                const app::ReferenceChoice c = app::chooseSliceReference(*scene, seed, start, d);
                const std::string where = std::string(file) + " seed " + std::to_string(seed) +
                                          " " + difficultyName(d) + ": " + formatPose(c.pose) +
                                          " (" + c.source + ")";
                EXPECT_EQ(c.source.rfind("random ", 0), 0u) << where;
                EXPECT_EQ(c.source.find("fullest"), std::string::npos) << where;
                for (const auto& [az, el] : {std::pair{0.0, 0.0}, std::pair{90.0, 0.0}, std::pair{0.0, -90.0}}) {
                    Pose plane;
                    plane.azimuthDeg = az;
                    plane.elevationDeg = el;
                    EXPECT_NE(c.pose.toArray(), plane.toArray()) << where;
                }
                EXPECT_GE(app::sliceMtre(*scene, c.pose, start), app::kMinSliceReferenceMtreMm) << where;
                EXPECT_FALSE(judgeMatch(c.pose, start, 0.0).match) << where;
                seen.push_back(c.pose.toArray());
            }
        std::sort(seen.begin(), seen.end());
        EXPECT_EQ(std::unique(seen.begin(), seen.end()), seen.end()) << file << ": every draw differs";
    }
}

}  // namespace
}  // namespace fm::test

// The game's realistic reference (AppState::realistic): the checkbox turns the reference into a
// realistic radiograph of the same pose (engine/spectral), still the same anatomy (correlated with
// the DRR, not equal to it), Solve (and Find, from nothing) still finds the hidden pose against it,
// and it is offered only while the reference is the whole CT.
#include <chrono>
#include <cmath>
#include <thread>

#include "AppFixture.h"
#include "drr/Drr.h"
#include "match/PoseError.h"
#include "scene/DrrCache.h"
#include "similarity/Similarity.h"

namespace fm::test {
namespace {

constexpr std::array<double, 6> kStartOffset{3.0, 3.0, 2.0, 3.0, -3.0, 3.0};  // as SolveUiTest
constexpr double kSolvedMtreMm = 1.0;
constexpr int kMaxSolveFrames = 20000;

class RealisticReference : public HeadlessApp {
  protected:
    Image plainReference() const {
        DrrRenderOptions options;
        options.threads = kTestDrrThreads;
        return renderDrr(*app->scene()->drrVolume, app::appGeometry(*app->scene(), app->state().referencePose), options);
    }
    // From `start`, against the realistic reference: presses `button` (Solve or Find) on the Solve
    // tab, waits for the answer and returns its mTRE against the hidden pose.
    double answerMtre(const Pose& start, const char* button) {
        app->state().realistic.enabled = true;
        app->state().userPose = start;
        script->idle(1);
        script->clickWidget("tab:solve");
        script->idle(1);
        script->clickWidget(button);
        for (int frames = 0; app->state().solve.running && frames < kMaxSolveFrames; ++frames) {
            script->idle(1);
            std::this_thread::sleep_for(std::chrono::milliseconds(2));
        }
        const app::SolveStatus& solve = app->state().solve;
        EXPECT_TRUE(solve.finished) << solve.error;
        const app::LoadedScene& s = *app->scene();
        return targetRegistrationError(app->state().referencePose, solve.bestPose, s.setup, s.center, s.bonePoints)
            .meanMm;
    }
};

TEST_F(RealisticReference, TheCheckboxMakesTheReferenceARadiographOfTheSamePose) {
    ASSERT_TRUE(app->state().realistic.available) << "the knee phantom is in HU";
    const Image before = app->referenceDrr();
    EXPECT_EQ(before.pixels, plainReference().pixels);
    script->clickWidget("checkbox:realistic-reference");
    script->idle(1);
    ASSERT_TRUE(app->state().realistic.enabled);
    const Image realistic = app->referenceDrr();
    const Image expected = app::realisticAppImage(*app->scene()->spectral,
                                                  app::appGeometry(*app->scene(), app->state().referencePose),
                                                  app->state().realistic.spectrum, kTestDrrThreads);
    EXPECT_EQ(realistic.pixels, expected.pixels);
    EXPECT_NE(realistic.pixels, before.pixels);
    const double ncc = similarity(SimilarityMeasure::Ncc, prepareReference(before, SimilarityMeasure::Ncc), realistic, nullptr);
    EXPECT_GT(ncc, 0.9) << "the same anatomy";
    EXPECT_LT(ncc, 0.9999) << "not the DRR";
    script->clickWidget("checkbox:realistic-reference");
    script->idle(1);
    EXPECT_EQ(app->referenceDrr().pixels, before.pixels);
}

TEST_F(RealisticReference, SolveFindsTheHiddenPoseAgainstIt) {
    std::array<double, 6> v = parsePose(kTestReferencePose).toArray();
    for (int k = 0; k < 6; ++k) v[k] += kStartOffset[k];
    EXPECT_LT(answerMtre(Pose::fromArray(v), "button:solve"), kSolvedMtreMm);
}

// Find (no start: from the centre pose, 25 mm mTRE away) against the realistic radiograph: its
// DRR templates correlate with the radiograph as the DRR does.
TEST_F(RealisticReference, FindFindsTheHiddenPoseFromNothingAgainstIt) {
    EXPECT_LT(answerMtre(Pose{}, "button:find"), kSolvedMtreMm);
    EXPECT_TRUE(app->state().solve.find);
}

TEST_F(RealisticReference, OfferedOnlyWhileTheReferenceIsTheWholeCt) {
    app->state().realistic.enabled = true;
    script->idle(1);
    ASSERT_FALSE(app->state().bones.list.empty());
    app->state().bones.list[0].visible = false;  // a bone hidden: the reference is no longer the CT
    script->idle(1);
    EXPECT_FALSE(app->state().realistic.available);
    EXPECT_EQ(app->referenceDrr().pixels.size(), plainReference().pixels.size());
    EXPECT_NE(app->referenceDrr().pixels,
              app::realisticAppImage(*app->scene()->spectral, app::appGeometry(*app->scene(), app->state().referencePose),
                                     app->state().realistic.spectrum, kTestDrrThreads)
                  .pixels);
}

}  // namespace
}  // namespace fm::test

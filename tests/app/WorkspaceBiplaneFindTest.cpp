// Find in the workspace on a biplane trial (issue 29): a bone with no keyframe, put back by the
// Find button with no start, looked for in both cameras at once (as `track` and `register --trial`
// find it), then registered; the answer is ok and at the truth of a trial simulated by
// `fluoromatch simulate` (example_ct's right femur, two cameras 80 deg apart turned -40 deg, the
// case docs/find.md's "Biplane" section and python_test_track find ok).
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "WorkspaceFixture.h"
#include "common/TestData.h"
#include "io/TextFile.h"
#include "pose/AutoscoperTra.h"
#include "scene/ObjectPoseParameterization.h"
#include "track/PoseErrors.h"
#include "track/TrialScene.h"
#include "ui/UiScript.h"
#include "workspace/WorkspaceApp.h"

namespace fm::test {
namespace {

namespace fs = std::filesystem;

// The trial simulated by the CLI into a scratch folder and opened in the workspace (ASSERTs that
// the simulation ran).
class WorkspaceBiplaneFind : public WorkspaceFixture {
  public:
    void SetUp() override {
        FM_REQUIRE_SHARED_DATA("totalseg-example-ct/example_seg_fast_force_split.nii.gz");
        dir = scratchDir("workspace-biplane-find");
        const fs::path ct = sharedDataDir() / "totalseg-example-ct";
        const std::string command =
            std::string("\"") + FM_FLUOROMATCH_EXE + "\" simulate --volume \"" + (ct / "example_ct.nii.gz").string() +
            "\" --labels \"" + (ct / "example_seg_fast_force_split.nii.gz").string() + "\" --label-table \"" +
            (repoDir() / "data/totalseg_bones.json").string() +
            "\" --bone femur_right --motion rotate:axis=x,angle=0:3 --frames 2 --azimuth -40 --out \"" +
            (dir / "s").string() + "\" > \"" + (dir / "simulate.log").string() + "\" 2>&1";
        ASSERT_EQ(std::system(command.c_str()), 0) << io::readTextFile(dir / "simulate.log", 1 << 20, "log");
        openTrial(dir / "s" / "trial.json");
    }
    fs::path dir;
};

TEST_F(WorkspaceBiplaneFind, FindPutsABoneWithNoKeyframeAtItsTruthInBothCamerasAtOnce) {
    if (IsSkipped() || HasFatalFailure()) return;
    ASSERT_EQ(model->objectCount(), 1);
    ASSERT_EQ(model->scene().cameras.size(), 2u);
    ASSERT_TRUE(trialKeyframes(model->trial(), "femur_right").empty()) << "the premise: no keyframe";
    const TraFile truthTra = readTra(dir / "s" / "femur_right_truth.tra");
    ASSERT_TRUE(truthTra.frames.at(0).at(0));
    const RigidTransform truth = objectPoseFromTra(model->trial(), "femur_right", *truthTra.frames[0][0]);
    const glm::dvec3 pivot = defaultPivot(*model->scene().objects[0].model);
    // Moved well off first (the workspace shows a bone with no keyframe where the cameras' views
    // cross, a few mm from this simulation's truth): 40 mm along the film, 30 mm in depth, 25 deg.
    app->state().controls.values[0] += 40.0;
    app->state().controls.values[2] += 30.0;
    app->state().controls.values[5] += 25.0;
    script->idle(1);
    ASSERT_TRUE(app->pose(0));
    const RigidTransform before = *app->pose(0);
    ASSERT_GT(centreError(before, truth, pivot), 30.0) << "the pose shown before Find must be far from the truth";
    ASSERT_GT(angleErrorDeg(before, truth), 20.0);

    ASSERT_NO_FATAL_FAILURE(findAndWait());
    const app::WorkspaceSolve& s = app->state().solve;
    EXPECT_NE(s.summary.find("found with no start in all cameras at once (ok: "), std::string::npos) << s.summary;
    EXPECT_EQ(s.check, app::WorkspaceSolve::Check::Ok) << s.checkText;
    // At the truth: the rotation within 0.5 deg, the bone's centre within 1 mm (the femur stub,
    // 3 mm voxels, found ok and registered in both cameras).
    EXPECT_LT(angleErrorDeg(*app->pose(0), truth), 0.5);
    EXPECT_LT(centreError(*app->pose(0), truth, pivot), 1.0);
    // The answer shown is the first candidate; Undo goes back to the pose before Find.
    ASSERT_GE(s.candidates.size(), 1u);
    EXPECT_EQ(app->pose(0)->translation, s.candidates[0].translation);
    script->clickWidget("button:undo");
    script->idle(1);
    EXPECT_EQ(app->pose(0)->translation, before.translation) << app->state().undoMessage;
}

}  // namespace
}  // namespace fm::test

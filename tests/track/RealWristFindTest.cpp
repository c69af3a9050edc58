// Issue 29's proof on real frames: the wrist's radius and ulna found in frame 0 with no start
// (data/trials/wrist.json with its keyframes set aside: findTrialBone is what `track` runs for a
// bone with no keyframe), in both cameras at once, over every orientation. The keyframes were
// made by hand (picked landmarks, a scan, a biplane refinement; docs/tracking.md), not by the
// finder, so they are the independent answer here: each bone's centre within 1 mm of its
// keyframe's, and the verdict ok. The rotation about a long bone's axis is weakly fixed (the
// keyframes themselves differ from the found poses by 1-6 deg there, docs/find.md): reported,
// not asserted. ~1.5 minutes a bone on 2 cores: Release only (tests/track/extra.cmake).
#include <gtest/gtest.h>

#include "common/TestData.h"
#include "scene/ObjectPoseParameterization.h"
#include "track/FoundKeyframe.h"
#include "track/PoseErrors.h"
#include "track/TrialScene.h"

namespace {

using fm::RigidTransform;

struct RealWristFind : ::testing::Test {
    void SetUp() override {
        if (!fm::test::sharedDataBesideRepo()) {
            if (fm::test::underCI())
                FAIL() << "under CI the shared data must be ../shared/data beside the repository";
            GTEST_SKIP() << "the shared data is not ../shared/data beside the repository";
        }
    }
};

TEST_F(RealWristFind, RadiusAndUlnaAreFoundInFrameZeroWithNoStartAtTheirKeyframes) {
    FM_REQUIRE_SHARED_DATA("autoscoper-bvr/XMA_UND/xr_data_wrist_cam01");
    for (const std::string bone : {"radius", "ulna"}) {
        SCOPED_TRACE(bone);
        const fm::TrialScene scene =
            fm::loadTrialScene(fm::readTrial(fm::test::repoDir() / "data/trials/wrist.json"), {bone}, 2);
        RigidTransform keyframe;
        bool hasKeyframe = false;
        for (const fm::TrialPose& p : scene.trial.keyframes.at(bone))
            if (p.frame == 0) {
                keyframe = fm::objectPoseFromTra(scene, bone, p.worldFromVolume);
                hasKeyframe = true;
            }
        ASSERT_TRUE(hasKeyframe) << "the trial has no keyframe at frame 0";

        // The find reads only the frames: the keyframe is not passed to it.
        const fm::FoundKeyframe found = fm::findTrialBone(scene, bone, {}, 0, "", "--find-space", 1, 2);
        ASSERT_TRUE(found.biplane.has_value()) << "two cameras: found in both at once";
        EXPECT_EQ(found.verdict, fm::AnswerVerdict::Ok) << found.verdictText;
        const glm::dvec3 centre = fm::defaultPivot(*scene.scene.object(bone).model);
        const double centreMm = fm::test::centreError(found.pose, keyframe, centre);
        EXPECT_LT(centreMm, 1.0) << "the found centre is away from the keyframe's";
        std::printf("%s: found %s; centre %.3f mm, rotation %.2f deg from the keyframe\n", bone.c_str(),
                    found.verdictText.c_str(), centreMm, fm::rotationBetweenDeg(found.pose.rotation, keyframe.rotation));
    }
}

}  // namespace

// Real frames (Autoscoper's sample wrist: no published poses). Two checks that do not need a
// known answer, at the resolution tracking uses (512 x 512, the trial's RenderResolution):
//  * one camera alone fixes a bone's position across its view well but its depth poorly, so
//    each camera's own single-view answer, started away from the biplane answer, gives a ray
//    (source -> the bone's centre); the two rays come from independent registrations and must
//    meet where the biplane registration put the bone. The radius only: in camera 1's lateral
//    view the ulna lies over the radius, and its camera-1 answer is 1.3 mm off (docs/tracking.md);
//  * restarts 2 mm / 2 deg around the biplane answer (two; one under the sanitizers) bring the
//    bone's centre back to it (the rotation about a bone's long axis is weakly fixed, 0.5-6 deg
//    apart: reported, not asserted).
// The start is the trial's keyframe at frame 0 (data/trials/wrist.json, how it was found is in
// docs/tracking.md); the answers are computed here, none is written in this file. And the other
// way round: both bones found with no start, at their keyframes (issue 29).
#include <gtest/gtest.h>

#include "common/TestData.h"
#include "core/Random.h"
#include "scene/ObjectPoseParameterization.h"
#include "track/FoundKeyframe.h"
#include "track/PoseErrors.h"
#include "track/TrialScene.h"

namespace {

using fm::RigidTransform;

// The closest point between the rays a + s da and b + t db, and their distance there.
std::pair<glm::dvec3, double> closestPoint(glm::dvec3 a, glm::dvec3 da, glm::dvec3 b,
                                           glm::dvec3 db) {
    da = glm::normalize(da);
    db = glm::normalize(db);
    const glm::dvec3 w = a - b;
    const double p = glm::dot(da, db), d = glm::dot(da, w), e = glm::dot(db, w);
    const double den = 1.0 - p * p;
    const double s = (p * e - d) / den, t = (e - p * d) / den;
    const glm::dvec3 x = a + s * da, y = b + t * db;
    return {(x + y) / 2.0, glm::length(x - y)};
}

struct RealWrist : ::testing::Test {
    void SetUp() override {
        if (!fm::test::sharedDataBesideRepo()) {
            if (fm::test::underCI())
                FAIL() << "under CI the shared data must be ../shared/data beside the repository";
            GTEST_SKIP() << "the shared data is not ../shared/data beside the repository";
        }
    }

    static fm::TrialScene load(const std::string& bone) {
        return fm::loadTrialScene(fm::readTrial(fm::test::repoDir() / "data/trials/wrist.json"),
                                  {bone}, 2);
    }

    static RigidTransform keyframe(const fm::TrialScene& scene, const std::string& bone) {
        for (const fm::TrialPose& p : scene.trial.keyframes.at(bone))
            if (p.frame == 0) return fm::objectPoseFromTra(scene, bone, p.worldFromVolume);
        throw std::runtime_error("no keyframe at frame 0");
    }

    static fm::FrameRecord registerFrame(const fm::TrialScene& scene, const std::string& bone,
                                         const std::vector<std::size_t>& cameras,
                                         const RigidTransform& start) {
        fm::TrackSettings settings;
        settings.registration.threads = 2;
        const fm::Tracker tracker(
            scene.scene, bone, fm::trialFrameViews(scene, cameras),
            settings);
        return tracker.trackFrame(0, start);
    }
};

TEST_F(RealWrist, BiplaneAnswerIsWhereBothSingleViewAnswersPointAndRestartsReturnToIt) {
    FM_REQUIRE_SHARED_DATA("autoscoper-bvr/XMA_UND/xr_data_wrist_cam01");
    for (const std::string bone : {"radius", "ulna"}) {
        SCOPED_TRACE(bone);
        const fm::TrialScene scene = load(bone);
        const glm::dvec3 centre = fm::defaultPivot(*scene.scene.object(bone).model);
        const fm::FrameRecord biplane = registerFrame(scene, bone, {}, keyframe(scene, bone));
        ASSERT_EQ(biplane.status, fm::FrameRecord::Status::Tracked) << biplane.note;
        ASSERT_EQ(biplane.camerasUsed, 2);
        const RigidTransform answer = *biplane.worldFromBone;
        const glm::dvec3 where = answer.applyToPoint(centre);

        if (bone == "radius") {
            // Each camera alone, from the answer moved 2 mm across that camera's view (along its
            // detector's u axis) and turned 2 deg: if a single-view registration did not find the
            // bone on its own, its ray would miss the answer by about 2 mm.
            glm::dvec3 source[2], through[2];
            for (std::size_t c = 0; c < 2; ++c) {
                const fm::ProjectionGeometry& g = scene.scene.cameras[c];
                const double side = c == 0 ? 1.0 : -1.0;
                const RigidTransform start = RigidTransform::translate(2.0 * side * g.detector.u) *
                                             fm::rotationAbout(g.detector.v, 2.0 * side, where) *
                                             answer;
                const fm::FrameRecord one = registerFrame(scene, bone, {c}, start);
                ASSERT_EQ(one.status, fm::FrameRecord::Status::Tracked) << one.note;
                ASSERT_EQ(one.camerasUsed, 1);
                source[c] = g.source;
                through[c] = one.worldFromBone->applyToPoint(centre) - g.source;
            }
            const auto [met, gap] = closestPoint(source[0], through[0], source[1], through[1]);
            EXPECT_LT(gap, 1.0) << "the single-view rays miss each other";
            EXPECT_LT(glm::length(met - where), 1.0)
                << "the single-view rays meet away from the biplane answer";
        }

        // Two restarts 2 mm / 2 deg away in random directions (fixed seed) come back.
        fm::Rng rng(7);
        for (int k = 0; k < 2; ++k) {
            const glm::dvec3 shift =
                glm::normalize(glm::dvec3(rng.normal(), rng.normal(), rng.normal()));
            const glm::dvec3 axis =
                glm::normalize(glm::dvec3(rng.normal(), rng.normal(), rng.normal()));
            const RigidTransform start = RigidTransform::translate(2.0 * shift) *
                                         fm::rotationAbout(axis, 2.0, where) * answer;
            const fm::FrameRecord again = registerFrame(scene, bone, {}, start);
            ASSERT_EQ(again.status, fm::FrameRecord::Status::Tracked);
            EXPECT_LT(fm::test::centreError(*again.worldFromBone, answer, centre), 0.5)
                << "restart " << k;
        }
    }
}

// Issue 29's proof on these frames: the radius and the ulna found in frame 0 with no start (the
// keyframes set aside: findTrialBone is what `track` runs for a bone with no keyframe), in both
// cameras at once, over every orientation. The keyframes were made by hand, not by the finder, so
// they are the independent answer: each bone's centre within 1 mm of its keyframe's, and the
// verdict ok. The turn about a long bone's axis is the keyframes' least sure part (docs/find.md):
// reported, not asserted. ~1.5 minutes a bone on 2 cores.
TEST_F(RealWrist, RadiusAndUlnaAreFoundInFrameZeroWithNoStartAtTheirKeyframes) {
    FM_REQUIRE_SHARED_DATA("autoscoper-bvr/XMA_UND/xr_data_wrist_cam01");
    for (const std::string bone : {"radius", "ulna"}) {
        SCOPED_TRACE(bone);
        const fm::TrialScene scene = load(bone);
        const RigidTransform key = keyframe(scene, bone);
        // The find reads only the frames: the keyframe is not passed to it.
        const fm::FoundKeyframe found = fm::findTrialBone(scene, bone, {}, 0, "", "--find-space", 1, 2);
        ASSERT_TRUE(found.biplane.has_value()) << "two cameras: found in both at once";
        EXPECT_EQ(found.verdict, fm::AnswerVerdict::Ok) << found.verdictText;
        const glm::dvec3 centre = fm::defaultPivot(*scene.scene.object(bone).model);
        const double centreMm = fm::test::centreError(found.pose, key, centre);
        EXPECT_LT(centreMm, 1.0) << "the found centre is away from the keyframe's";
        std::printf("%s: found %s; centre %.3f mm, rotation %.2f deg from the keyframe\n", bone.c_str(),
                    found.verdictText.c_str(), centreMm, fm::rotationBetweenDeg(found.pose.rotation, key.rotation));
    }
}

}  // namespace

// Bone motions (the app's bone sliders, register --bone-motion) and the flex game's draw and
// judge, against the phantom's own flexion and hand-made joint angles.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "bones/BoneMotion.h"
#include "bones/KneeMotionGame.h"
#include "core/Error.h"
#include "phantom/ArticulatedKnee.h"

namespace {

void expectSame(const fm::RigidTransform& a, const fm::RigidTransform& b, double tol) {
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) EXPECT_NEAR(a.rotation[c][r], b.rotation[c][r], tol);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(a.translation[k], b.translation[k], tol);
}

TEST(BoneMotion, ATurnAboutXOnTheFlexionAxisIsThePhantomsFlexion) {
    const fm::KneePhantomParams p;
    const glm::dvec3 axis = fm::kneeModelToWorld(p, fm::KneeSegment::Femur, fm::kFlexionAxisPoint);
    for (double a : {-5.0, 12.0, 47.5, 90.0})
        expectSame(fm::boneMotionTransform({0, 0, 0, a, 0, 0}, axis),
                   fm::kneeBonePoses(p, a).tibia, 1e-12);
    // Shifts come after the turns; turns keep the pivot in place.
    const fm::RigidTransform m = fm::boneMotionTransform({1, 2, 3, 10, 20, 30}, axis);
    const glm::dvec3 moved = m.applyToPoint(axis) - axis;
    EXPECT_NEAR(moved.x, 1.0, 1e-12);
    EXPECT_NEAR(moved.y, 2.0, 1e-12);
    EXPECT_NEAR(moved.z, 3.0, 1e-12);
    EXPECT_THROW(fm::boneMotionTransform({0, 0, std::numeric_limits<double>::quiet_NaN(), 0, 0, 0},
                                         axis),
                 fm::Error);
}

TEST(BoneMotion, TheMotionOfAPoseGivesThatPoseBack) {
    const glm::dvec3 pivot{12.0, -30.0, 45.0};
    for (const fm::BoneMotion& m : {fm::BoneMotion{1, -2, 3, 10, -20, 30},
                                    fm::BoneMotion{0, 0, 0, 0, 0, 0},
                                    fm::BoneMotion{-40, 5, 0.5, -120, 85, -170}}) {
        const fm::BoneMotion back = fm::boneMotionOf(fm::boneMotionTransform(m, pivot), pivot);
        for (int k = 0; k < 6; ++k) EXPECT_NEAR(back[k], m[k], 1e-9) << k;
    }
    fm::RigidTransform scaled;
    scaled.rotation *= 2.0;
    EXPECT_THROW(fm::boneMotionOf(scaled, pivot), fm::Error);
}

TEST(KneeMotionGame, TheFlexionOfTheTibiaTurnedAboutTheFlexionAxisIsThatAngle) {
    const fm::KneePhantomParams p;
    const fm::KneeJoint joint{fm::kneeAnatomicalFrame(p, fm::KneeSegment::Femur),
                              fm::kneeAnatomicalFrame(p, fm::KneeSegment::Tibia),
                              fm::BodySide::Right};
    const fm::KneeAngles k =
        fm::kneeAnglesOf(joint, fm::RigidTransform::identity(), fm::kneeBonePoses(p, 33.0).tibia);
    EXPECT_NEAR(k.flexionDeg, 33.0, 1e-9);
    EXPECT_NEAR(k.varusDeg, 0.0, 1e-9);
    EXPECT_NEAR(k.internalRotationDeg, 0.0, 1e-9);
    const auto a = fm::kneeAngleArray(k);
    EXPECT_EQ(a[3], k.flexionDeg);
    EXPECT_EQ(a[0], k.medialShiftMm);
    const fm::KneeAngles back = fm::kneeAnglesFromArray(a);
    EXPECT_EQ(fm::kneeAngleArray(back), a);
    EXPECT_STREQ(fm::kneeComponentName(3), "flexion");
    EXPECT_THROW(fm::kneeComponentName(6), fm::Error);
}

TEST(KneeMotionGame, DrawsStayInTheirDifficultysRangesAndRepeatForASeed) {
    for (std::uint64_t seed = 1; seed <= 40; ++seed) {
        const fm::BoneMotion easy = fm::drawKneeMotion(seed, fm::Difficulty::Easy);
        EXPECT_GE(easy[3], 10.0);
        EXPECT_LE(easy[3], 60.0);
        for (int k : {0, 1, 2, 4, 5}) EXPECT_EQ(easy[k], 0.0);
        const fm::BoneMotion medium = fm::drawKneeMotion(seed, fm::Difficulty::Medium);
        EXPECT_LE(std::abs(medium[4]), 5.0);
        EXPECT_LE(std::abs(medium[5]), 10.0);
        for (int k : {0, 1, 2}) EXPECT_EQ(medium[k], 0.0);
        const fm::BoneMotion hard = fm::drawKneeMotion(seed, fm::Difficulty::Hard);
        EXPECT_GE(hard[3], 5.0);
        EXPECT_LE(hard[3], 90.0);
        for (int k : {0, 1, 2}) EXPECT_LE(std::abs(hard[k]), 4.0);
        for (double v : hard) EXPECT_EQ(v, std::round(v * 10.0) / 10.0) << "on the 0.1 grid";
        EXPECT_EQ(fm::drawKneeMotion(seed, fm::Difficulty::Hard), hard);
    }
    EXPECT_NE(fm::drawKneeMotion(1, fm::Difficulty::Easy), fm::drawKneeMotion(2, fm::Difficulty::Easy));
}

TEST(KneeMotionGame, TheJudgeNamesTheJointAnglesWithTheGamesTolerances) {
    fm::KneeAngles reference;
    reference.flexionDeg = 30.0;
    fm::KneeAngles user = reference;
    user.flexionDeg = 27.0;       // 3 deg low: beyond the 2 deg tolerance
    user.anteriorDrawerMm = 1.5;  // within 2 mm
    const fm::MatchVerdict v = fm::judgeKneeMotion(reference, user, 4.0);
    EXPECT_FALSE(v.match);
    EXPECT_EQ(v.worstParameter, 3);
    EXPECT_EQ(v.hints[3].text, "flexion too low");
    EXPECT_EQ(v.hints[1].text, "anterior drawer OK");
    EXPECT_NEAR(v.hints[3].error, -3.0, 1e-12);
    EXPECT_NEAR(v.hints[1].error, 1.5, 1e-12);
    EXPECT_EQ(v.mtreMm, 4.0);
    user.flexionDeg = 31.0;
    EXPECT_TRUE(fm::judgeKneeMotion(reference, user, 0.5).match);
}

}  // namespace

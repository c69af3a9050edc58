// Pose differences and the mean target registration error against hand-computed geometry:
// a pure offset moves every point by the offset's length; a change of azimuth, elevation or
// film rotation turns points about an axis through the isocenter, moving a point at distance
// r from that axis by the chord 2 r sin(delta / 2).
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "core/Error.h"
#include "match/PoseError.h"

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
// Scene distances of ~500 mm and rotations in double precision: far below a micrometre.
constexpr double kMm = 1e-9;

fm::Pose poseOf(double x, double y, double z, double az, double el, double rot) {
    return fm::Pose::fromArray({x, y, z, az, el, rot});
}

TEST(PoseError, WrapDegrees) {
    constexpr double kTol = 1e-12;
    EXPECT_NEAR(fm::wrapDegrees(0.0), 0.0, kTol);
    EXPECT_NEAR(fm::wrapDegrees(180.0), -180.0, kTol);  // [-180, 180)
    EXPECT_NEAR(fm::wrapDegrees(-180.0), -180.0, kTol);
    EXPECT_NEAR(fm::wrapDegrees(190.0), -170.0, kTol);
    EXPECT_NEAR(fm::wrapDegrees(-190.0), 170.0, kTol);
    EXPECT_NEAR(fm::wrapDegrees(359.5), -0.5, kTol);
    EXPECT_NEAR(fm::wrapDegrees(540.0), -180.0, kTol);
    EXPECT_NEAR(fm::wrapDegrees(-725.0), -5.0, kTol);
}

TEST(PoseError, DifferenceWrapsAnglesButNotOffsets) {
    const auto d =
        fm::poseDifference(poseOf(1, 2, 3, 179, 10, -80), poseOf(-199, 2.5, 3, -179, 20, 85));
    constexpr double kTol = 1e-12;
    EXPECT_NEAR(d[0], -200.0, kTol);  // offsets are plain differences
    EXPECT_NEAR(d[1], 0.5, kTol);
    EXPECT_NEAR(d[2], 0.0, kTol);
    EXPECT_NEAR(d[3], 2.0, kTol);  // -179 is 2 deg past 179, not 358 deg before it
    EXPECT_NEAR(d[4], 10.0, kTol);
    EXPECT_NEAR(d[5], 165.0, kTol);
    EXPECT_NEAR(fm::poseDifference(poseOf(0, 0, 0, -179, 0, 0), poseOf(0, 0, 0, 179, 0, 0))[3], -2.0,
                kTol);
    EXPECT_STREQ(fm::poseParameterName(0), "x offset");
    EXPECT_STREQ(fm::poseParameterName(3), "azimuth");
    EXPECT_STREQ(fm::poseParameterUnit(5), "deg");
    EXPECT_THROW(fm::poseParameterName(6), fm::Error);
}

TEST(PoseError, CameraFrameOfAHandMadeGeometry) {
    fm::ProjectionGeometry g;
    g.source = {10, 20, 30};
    g.detector.origin = {0, 0, 130};
    g.detector.u = {0, 1, 0};
    g.detector.v = {-1, 0, 0};  // u x v = +z: the beam runs along +z
    const glm::dvec3 c = fm::toCameraFrame(g, {11, 22, 33});
    EXPECT_NEAR(c.x, 2.0, kMm);
    EXPECT_NEAR(c.y, -1.0, kMm);
    EXPECT_NEAR(c.z, 3.0, kMm);
}

class PoseErrorScene : public ::testing::Test {
  protected:
    fm::SceneSetup setup = fm::defaultSceneSetup();
    glm::dvec3 volumeCenter{10.0, -20.0, 30.0};
};

TEST_F(PoseErrorScene, IdenticalPosesHaveNoError) {
    const std::vector<glm::dvec3> points{{0, 0, 0}, {50, -30, 80}, {-40, 20, -100}};
    const fm::Pose p = poseOf(3, -4, 5, 123, -33, 17);
    const auto e = fm::targetRegistrationError(p, p, setup, volumeCenter, points);
    EXPECT_EQ(e.meanMm, 0.0);
    EXPECT_EQ(e.maxMm, 0.0);
}

TEST_F(PoseErrorScene, PureOffsetGivesTheOffsetLength) {
    const std::vector<glm::dvec3> points{{0, 0, 0}, {50, -30, 80}, {-40, 20, -100}, {7, 7, 7}};
    for (const auto& angles :
         {glm::dvec3(0, 0, 0), glm::dvec3(37, -20, 15), glm::dvec3(-170, 80, -60)}) {
        const fm::Pose a = poseOf(1, 2, 3, angles.x, angles.y, angles.z);
        const fm::Pose b = poseOf(1 + 3, 2 + 4, 3 + 12, angles.x, angles.y, angles.z);
        const auto e = fm::targetRegistrationError(a, b, setup, volumeCenter, points);
        EXPECT_NEAR(e.meanMm, 13.0, kMm);
        EXPECT_NEAR(e.maxMm, 13.0, kMm);
    }
}

TEST_F(PoseErrorScene, OffsetSplitsIntoInPlaneAndDepth) {
    const std::vector<glm::dvec3> points{{0, 0, 0}, {30, 40, -50}};
    // AP view (az 0, el 0): the beam runs anterior -> posterior, along +y. A y offset is pure
    // depth, x and z are in the film plane.
    auto e = fm::targetRegistrationError(poseOf(0, 0, 0, 0, 0, 0), poseOf(3, 4, 12, 0, 0, 0), setup,
                                         volumeCenter, points);
    EXPECT_NEAR(e.meanDepthMm, 4.0, kMm);
    EXPECT_NEAR(e.meanInPlaneMm, std::hypot(3.0, 12.0), kMm);
    // Lateral view from the patient's left (az 90): the beam runs along -x: x is depth.
    e = fm::targetRegistrationError(poseOf(0, 0, 0, 90, 0, 0), poseOf(3, 4, 12, 90, 0, 0), setup,
                                    volumeCenter, points);
    EXPECT_NEAR(e.meanDepthMm, 3.0, kMm);
    EXPECT_NEAR(e.meanInPlaneMm, std::hypot(4.0, 12.0), kMm);
}

TEST_F(PoseErrorScene, AzimuthTurnsAboutTheSuperiorAxisThroughTheIsocenter) {
    const glm::dvec3 offset{1, 2, 3};
    const glm::dvec3 isocenter = volumeCenter - offset;
    const double delta = 10.0, r = 40.0;
    const fm::Pose a = poseOf(offset.x, offset.y, offset.z, 20, 0, 0);
    const fm::Pose b = poseOf(offset.x, offset.y, offset.z, 20 + delta, 0, 0);
    auto single = [&](const glm::dvec3& p, const fm::Pose& pa, const fm::Pose& pb) {
        return fm::targetRegistrationError(pa, pb, setup, volumeCenter, {p}).meanMm;
    };
    // On the rotation axis: no motion. At r from it: the chord 2 r sin(delta / 2).
    EXPECT_NEAR(single(isocenter, a, b), 0.0, kMm);
    EXPECT_NEAR(single(isocenter + glm::dvec3(0, 0, 50), a, b), 0.0, kMm);
    EXPECT_NEAR(single(isocenter + glm::dvec3(r, 0, 0), a, b), 2 * r * std::sin(delta / 2 * kDeg),
                kMm);
    EXPECT_NEAR(single(isocenter + glm::dvec3(0, r, 70), a, b), 2 * r * std::sin(delta / 2 * kDeg),
                kMm);
    // Across +-180: 179 -> -179 is a 2 degree turn.
    const fm::Pose c = poseOf(offset.x, offset.y, offset.z, 179, 0, 0);
    const fm::Pose d = poseOf(offset.x, offset.y, offset.z, -179, 0, 0);
    EXPECT_NEAR(single(isocenter + glm::dvec3(r, 0, 0), c, d), 2 * r * std::sin(1.0 * kDeg), kMm);
}

TEST_F(PoseErrorScene, ElevationTurnsAboutTheLeftRightAxisInAnApView) {
    const glm::dvec3 isocenter = volumeCenter;  // offset 0
    const double delta = 6.0, r = 40.0;
    const fm::Pose a = poseOf(0, 0, 0, 0, -3, 0), b = poseOf(0, 0, 0, 0, 3, 0);
    auto single = [&](const glm::dvec3& p) {
        return fm::targetRegistrationError(a, b, setup, volumeCenter, {p}).meanMm;
    };
    EXPECT_NEAR(single(isocenter + glm::dvec3(60, 0, 0)), 0.0, kMm);  // on the axis
    EXPECT_NEAR(single(isocenter + glm::dvec3(0, 0, r)), 2 * r * std::sin(delta / 2 * kDeg), kMm);
}

TEST_F(PoseErrorScene, FilmRotationTurnsAboutTheCentralRayInPlane) {
    const double delta = 20.0, rho = 30.0;
    const fm::Pose a = poseOf(0, 0, 0, 0, 0, -5), b = poseOf(0, 0, 0, 0, 0, 15);
    // AP view: the central ray runs along y through the isocenter (= volumeCenter here).
    const auto onRay = fm::targetRegistrationError(a, b, setup, volumeCenter,
                                                   {volumeCenter + glm::dvec3(0, 77, 0)});
    EXPECT_NEAR(onRay.meanMm, 0.0, kMm);
    const auto off = fm::targetRegistrationError(a, b, setup, volumeCenter,
                                                 {volumeCenter + glm::dvec3(rho, 10, 0)});
    EXPECT_NEAR(off.meanMm, 2 * rho * std::sin(delta / 2 * kDeg), kMm);
    EXPECT_NEAR(off.meanInPlaneMm, off.meanMm, kMm);
    EXPECT_NEAR(off.meanDepthMm, 0.0, kMm);
}

TEST(PoseError, EmptyTargetsAreAnError) {
    EXPECT_THROW(fm::targetRegistrationError({}, {}, fm::defaultSceneSetup(), {0, 0, 0}, {}),
                 fm::Error);
}

TEST(BoneTargetPoints, CentresOfVoxelsAboveThresholdEvenlySubsampled) {
    fm::Volume v = fm::Volume::allocate({10, 10, 10}, -1000.0f);
    v.spacing = {2.0, 2.0, 2.0};
    v.origin = {100.0, 0.0, 0.0};
    for (int k = 4; k < 6; ++k)
        for (int j = 4; j < 6; ++j)
            for (int i = 4; i < 6; ++i) v.at(i, j, k) = 500.0f;
    v.at(0, 0, 0) = 299.0f;  // just below the threshold
    const auto all = fm::boneTargetPoints(v, 300.0, 100);
    ASSERT_EQ(all.size(), 8u);
    for (const glm::dvec3& p : all) {
        const glm::dvec3 ijk = v.worldToIndex(p);
        EXPECT_GE(v.at(int(std::lround(ijk.x)), int(std::lround(ijk.y)), int(std::lround(ijk.z))),
                  300.0f);
    }
    EXPECT_NEAR(all.front().x, 108.0, kMm);  // voxel (4,4,4)
    // Subsampled to at most 3: every third voxel (stride ceil(8/3) = 3), the middle of each run.
    const auto three = fm::boneTargetPoints(v, 300.0, 3);
    ASSERT_EQ(three.size(), 3u);
    EXPECT_EQ(three[0], all[1]);
    EXPECT_EQ(three[1], all[4]);
    EXPECT_EQ(three[2], all[7]);
    EXPECT_THROW(fm::boneTargetPoints(v, 600.0), fm::Error);
    EXPECT_THROW(fm::boneTargetPoints(v, 300.0, 0), fm::Error);
}

}  // namespace

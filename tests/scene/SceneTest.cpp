// The scene model: rigid transforms compose and invert exactly, a camera moved into an
// object's frame sees the same thing, objects add, and the 2011 scene rendered through the
// scene model is the DRR the renderer gives directly (same pixels, bit for bit).
#include <cmath>

#include <gtest/gtest.h>

#include "core/Error.h"
#include "drr/Drr.h"
#include "geometry/Pose.h"
#include "phantom/AnalyticObjects.h"
#include "phantom/Phantoms.h"
#include "scene/Scene.h"
#include "scene/SceneParameterization.h"
#include "search/Registration.h"

namespace {

using fm::RigidTransform;

// Rotations built from a few sines and cosines: products stay within a few ulps of exact.
constexpr double kSceneExactTol = 1e-12;
// Line integrals traced in two frames differ only by rounding of the ray set-up (double) and the
// float image: relative 1e-5 of the largest value is far below one voxel's contribution.
constexpr double kFrameChangeRelTol = 1e-5;

RigidTransform someTransform() {
    return fm::rotationAbout({1.0, 2.0, -0.5}, 37.0, {10.0, -4.0, 3.0}) *
           RigidTransform::translate({5.0, -7.0, 11.0});
}

void expectNearPoint(const glm::dvec3& a, const glm::dvec3& b, double tol) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

TEST(RigidTransform, RotationAboutAxisThroughPivot) {
    // 90 deg about +z through (1, 0, 0): (2, 0, 0) -> (1, 1, 0), the pivot stays.
    const RigidTransform r = fm::rotationAbout({0.0, 0.0, 2.0}, 90.0, {1.0, 0.0, 0.0});
    expectNearPoint(r.applyToPoint({2.0, 0.0, 0.0}), {1.0, 1.0, 0.0}, kSceneExactTol);
    expectNearPoint(r.applyToPoint({1.0, 0.0, 0.0}), {1.0, 0.0, 0.0}, kSceneExactTol);
    expectNearPoint(r.applyToVector({0.0, 1.0, 0.0}), {-1.0, 0.0, 0.0}, kSceneExactTol);
    EXPECT_NO_THROW(r.validate("r"));
}

TEST(RigidTransform, InverseAndCompositionFollowTheFrameNames) {
    const RigidTransform aFromB = someTransform();
    const RigidTransform bFromC = fm::rotationAbout({0.0, 1.0, 0.0}, -63.0, {0.0, 0.0, 9.0});
    const RigidTransform aFromC = aFromB * bFromC;
    const glm::dvec3 pC{3.0, -2.0, 8.0};
    expectNearPoint(aFromC.applyToPoint(pC), aFromB.applyToPoint(bFromC.applyToPoint(pC)), kSceneExactTol);
    expectNearPoint(aFromB.inverse().applyToPoint(aFromB.applyToPoint(pC)), pC, kSceneExactTol);
    const RigidTransform id = aFromC.inverse() * aFromC;
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) EXPECT_NEAR(id.rotation[c][r], c == r ? 1.0 : 0.0, kSceneExactTol);
    expectNearPoint(id.translation, glm::dvec3(0.0), kSceneExactTol);
}

TEST(RigidTransform, RowMajorMatrixRoundTripAndLayout) {
    const RigidTransform t = someTransform();
    const auto m = t.toRowMajor4x4();
    // Row-major: element (row, col) at 4 row + col; translation in the last column.
    EXPECT_EQ(m[3], t.translation.x);
    EXPECT_EQ(m[7], t.translation.y);
    EXPECT_EQ(m[11], t.translation.z);
    EXPECT_EQ(m[1], t.rotation[1][0]);  // row 0, column 1
    EXPECT_EQ(m[15], 1.0);
    const RigidTransform back = RigidTransform::fromRowMajor4x4(m, "m");
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) EXPECT_EQ(back.rotation[c][r], t.rotation[c][r]);
}

TEST(RigidTransform, RefusesWhatIsNotAPose) {
    std::array<double, 16> reflection{-1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    EXPECT_THROW(RigidTransform::fromRowMajor4x4(reflection, "pose"), fm::Error);
    std::array<double, 16> scaled{2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 1};
    EXPECT_THROW(RigidTransform::fromRowMajor4x4(scaled, "pose"), fm::Error);
    std::array<double, 16> lastRow{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 1, 1};
    EXPECT_THROW(RigidTransform::fromRowMajor4x4(lastRow, "pose"), fm::Error);
    std::array<double, 16> nan{1, 0, 0, NAN, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    try {
        RigidTransform::fromRowMajor4x4(nan, "frame 3 of poses.tra");
        FAIL() << "NaN accepted";
    } catch (const fm::Error& e) {
        EXPECT_NE(std::string(e.what()).find("frame 3 of poses.tra"), std::string::npos);
    }
    EXPECT_THROW(fm::rotationAbout({0, 0, 0}, 10.0, {0, 0, 0}), fm::Error);
}

TEST(RigidTransform, MovedCameraProjectsMovedPointsToTheSamePixel) {
    const fm::ProjectionGeometry g =
        fm::sceneGeometry(fm::parsePose("3,-2,5,30,-20,10"), fm::defaultSceneSetup(), {0, 0, 0});
    const RigidTransform aFromB = someTransform();
    const fm::ProjectionGeometry moved = fm::transformGeometry(aFromB, g);
    EXPECT_NO_THROW(moved.validate("moved"));
    for (const glm::dvec3 p : {glm::dvec3{0, 0, 0}, glm::dvec3{40, -30, 20}, glm::dvec3{-60, 5, 70}}) {
        const auto a = g.projectToPixel(p);
        const auto b = moved.projectToPixel(aFromB.applyToPoint(p));
        ASSERT_TRUE(a && b);
        EXPECT_NEAR(a->x, b->x, 1e-9);
        EXPECT_NEAR(a->y, b->y, 1e-9);
    }
}

struct SmallScene {
    fm::Volume volume = fm::makePhantom("knee,size=48x48x52");
    fm::DrrVolumePtr prepared = fm::prepareDrrVolume(volume, {});
    fm::SceneSetup setup = [] {
        fm::SceneSetup s = fm::defaultSceneSetup();
        s.filmPixels = {64, 64};
        return s;
    }();
};

TEST(Scene, The2011SceneIsTheDirectDrrBitForBit) {
    SmallScene s;
    fm::Scene scene;
    scene.objects.push_back({"ct", std::make_shared<fm::VolumeXrayModel>(s.prepared), {}, true});
    const fm::Pose2011Parameterization param(s.setup, s.volume.center());
    const fm::Pose pose = fm::parsePose("4,-3,6,25,-15,8");
    param.apply(pose.toArray(), scene);
    ASSERT_EQ(scene.cameras.size(), 1u);

    fm::DrrRenderOptions direct;
    direct.threads = 1;
    const fm::Image expected =
        fm::renderDrr(*s.prepared, fm::sceneGeometry(pose, s.setup, s.volume.center()), direct);
    fm::XrayRenderSettings settings;
    settings.threads = 1;
    const fm::Image viaScene = fm::renderView(scene, 0, settings);
    ASSERT_EQ(viaScene.pixels.size(), expected.pixels.size());
    double maxValue = 0.0;
    for (std::size_t i = 0; i < expected.pixels.size(); ++i) {
        EXPECT_EQ(viaScene.pixels[i], expected.pixels[i]) << "pixel " << i;
        maxValue = std::max(maxValue, double(expected.pixels[i]));
    }
    EXPECT_GT(maxValue, 0.5);  // the knee is in view: the comparison means something
}

TEST(Scene, MovingTheObjectOrTheCameraGivesTheSameImage) {
    SmallScene s;
    const fm::ProjectionGeometry camera =
        fm::sceneGeometry(fm::parsePose("0,0,0,40,10,0"), s.setup, s.volume.center());
    const RigidTransform worldFromCt =
        fm::rotationAbout({0.3, 1.0, 0.2}, 12.0, s.volume.center()) *
        RigidTransform::translate({6.0, -4.0, 9.0});
    fm::Scene moved;
    moved.objects.push_back(
        {"ct", std::make_shared<fm::VolumeXrayModel>(s.prepared), worldFromCt, true});
    fm::XrayRenderSettings settings;
    const fm::Image a = fm::renderView(moved, camera, settings);
    // The same relative geometry: CT fixed, camera moved by the inverse.
    fm::DrrRenderOptions direct;
    const fm::Image b =
        fm::renderDrr(*s.prepared, fm::transformGeometry(worldFromCt.inverse(), camera), direct);
    double maxValue = 0.0, maxDiff = 0.0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        maxValue = std::max(maxValue, double(b.pixels[i]));
        maxDiff = std::max(maxDiff, std::abs(double(a.pixels[i]) - b.pixels[i]));
    }
    EXPECT_GT(maxValue, 0.5);
    EXPECT_LE(maxDiff, kFrameChangeRelTol * maxValue);
    // And moving it changed the image (the pose is not ignored).
    fm::Scene still;
    still.objects.push_back({"ct", std::make_shared<fm::VolumeXrayModel>(s.prepared), {}, true});
    const fm::Image c = fm::renderView(still, camera, settings);
    double change = 0.0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i)
        change = std::max(change, std::abs(double(a.pixels[i]) - c.pixels[i]));
    EXPECT_GT(change, 0.1 * maxValue);
}

// A unit-density box 40 x 20 x 10 mm turned 90 deg about the beam: the central ray's chord is the
// box's other side. Checks the pose's direction, not just consistency.
TEST(Scene, RotatedBoxGivesTheAnalyticChord) {
    const fm::BoxShape box{{-20.0, -10.0, -5.0}, {20.0, 10.0, 5.0}};
    const fm::Volume v = fm::voxelize(box, fm::centeredGrid({48, 48, 48}, {1.0, 1.0, 1.0}));
    fm::DrrValueOptions raw;
    raw.values = fm::DrrValues::Raw;
    auto model = std::make_shared<fm::VolumeXrayModel>(fm::prepareDrrVolume(v, raw));
    // A camera looking along world +x: source at x = -500, detector plane at x = +500.
    fm::ProjectionGeometry camera;
    camera.source = {-500.0, 0.0, 0.0};
    camera.detector.size = {3, 3};
    camera.detector.spacing = {1.0, 1.0};
    camera.detector.u = {0.0, 1.0, 0.0};
    camera.detector.v = {0.0, 0.0, 1.0};
    camera.detector.origin = {500.0, -1.0, -1.0};  // pixel (1, 1) on the axis
    fm::Scene scene;
    scene.objects.push_back({"box", model, {}, true});
    fm::XrayRenderSettings settings;
    EXPECT_NEAR(fm::renderView(scene, camera, settings).at(1, 1), 40.0, 1e-4);
    scene.objects[0].worldFromObject = fm::rotationAbout({0, 0, 1}, 90.0, {0, 0, 0});
    EXPECT_NEAR(fm::renderView(scene, camera, settings).at(1, 1), 20.0, 1e-4);
    scene.objects[0].worldFromObject = fm::rotationAbout({0, 1, 0}, 90.0, {0, 0, 0});
    EXPECT_NEAR(fm::renderView(scene, camera, settings).at(1, 1), 10.0, 1e-4);
    // Box bounds in the object's frame hold the box.
    const fm::Box3 b = model->bounds();
    EXPECT_LE(b.lower.x, -20.0);
    EXPECT_GE(b.upper.x, 20.0);
    EXPECT_LE(b.upper.y, 11.0);
}

TEST(Scene, ObjectsAddAndHiddenOnesDoNot) {
    SmallScene s;
    const fm::ProjectionGeometry camera =
        fm::sceneGeometry(fm::parsePose("0,0,0,-30,5,0"), s.setup, s.volume.center());
    auto model = std::make_shared<fm::VolumeXrayModel>(s.prepared);
    const RigidTransform shifted = RigidTransform::translate({25.0, 0.0, 0.0});
    fm::Scene one, two, both;
    one.objects.push_back({"a", model, {}, true});
    two.objects.push_back({"b", model, shifted, true});
    both.objects = {one.objects[0], two.objects[0]};
    fm::XrayRenderSettings settings;
    const fm::Image a = fm::renderView(one, camera, settings);
    const fm::Image b = fm::renderView(two, camera, settings);
    const fm::Image ab = fm::renderView(both, camera, settings);
    for (std::size_t i = 0; i < ab.pixels.size(); ++i)
        EXPECT_EQ(ab.pixels[i], a.pixels[i] + b.pixels[i]);
    both.object("b").visible = false;
    const fm::Image aOnly = fm::renderView(both, camera, settings);
    EXPECT_EQ(aOnly.pixels, a.pixels);
    EXPECT_THROW(both.object("c"), fm::Error);
    EXPECT_THROW(fm::renderView(both, 0, settings), fm::Error);  // no camera 0
}

TEST(Pose2011Parameterization, SearchPointsMoveAsRegistrationDoes) {
    const fm::SceneSetup setup = fm::defaultSceneSetup();
    const glm::dvec3 center{1.0, 2.0, 3.0};
    const fm::Pose2011Parameterization param(setup, center);
    const fm::Pose start = fm::parsePose("2,-1,4,175,30,-10");
    const std::array<double, 6> point{3.0, -2.0, 5.0, 10.0, -4.0, 2.5};
    const fm::SceneParams p = param.fromSearchPoint(start.toArray(), point);
    const fm::Pose expected =
        fm::poseFromSearchPoint(start, fm::sceneGeometry(start, setup, center), point);
    for (int i = 0; i < 6; ++i) EXPECT_NEAR(p[i], expected.toArray()[i], kSceneExactTol);
    EXPECT_NEAR(p[3], -175.0, kSceneExactTol);  // azimuth wraps
    const fm::SceneParams zero = param.fromSearchPoint(start.toArray(), {});
    for (int i = 0; i < 6; ++i) EXPECT_NEAR(zero[i], start.toArray()[i], kSceneExactTol);
    EXPECT_STREQ(param.describe()[3].name, "azimuth");
}

}  // namespace

// A bone with no keyframe found in two cameras (track/FoundKeyframe.h) on synthetic radiographs
// whose truth is known: each camera's depths are searched where the other's view crosses it
// (find/SharedView.h: checked against the projections it is made of), the two cameras' answers,
// found independently, agree, and the pose they give is the truth's within 1 mm and 2 deg in 3D.
#include <gtest/gtest.h>

#include "FindTestScenes.h"
#include "find/SeenPose.h"
#include "find/SharedView.h"
#include "scene/ObjectPoseParameterization.h"
#include "track/FoundKeyframe.h"
#include "xray/ObjectRegistration.h"

namespace fm {
namespace {

// A 512 x 512 film of 0.5 mm pixels 1200 mm from `source`, looking along `view` (unit), its
// columns along `u`.
ProjectionGeometry camera(const glm::dvec3& source, const glm::dvec3& view, const glm::dvec3& u) {
    ProjectionGeometry g;
    g.source = source;
    g.detector.size = {512, 512};
    g.detector.spacing = {0.5, 0.5};
    g.detector.u = u;
    g.detector.v = glm::cross(view, u);  // u x v = view
    g.detector.origin = source + 1200.0 * view - 127.75 * u - 127.75 * g.detector.v;
    return g;
}

// Two cameras 90 deg apart, both 800 mm from the origin, where the object is.
std::vector<ProjectionGeometry> biplane() {
    return {camera({0, 0, 800}, {0, 0, -1}, {1, 0, 0}), camera({800, 0, 0}, {-1, 0, 0}, {0, 0, -1})};
}

TEST(SharedView, TheDepthsOneCameraSharesWithAnotherHoldWhatBothSee) {
    const std::vector<ProjectionGeometry> cams = biplane();
    const auto band = sharedViewDepths(cams[0], {cams[1]});
    ASSERT_TRUE(band.has_value());
    // Both views open by tan a = 127.75 / 1200 about their axes. Camera 1's ray at depth d reaches
    // x = -d tan a (its film edge, furthest from camera 2's source), where camera 2 sees |z| up to
    // (800 + d tan a) tan a; with z = 800 - d that bounds d to [(800 - 800 t) / (1 + t^2),
    // (800 + 800 t) / (1 - t^2)], t = tan a. Sampled (9 x 9 rays, depths 1.2 % apart): within 10 mm.
    const double t = 127.75 / 1200.0;
    EXPECT_NEAR(band->first, (800.0 - 800.0 * t) / (1.0 + t * t), 10.0);
    EXPECT_NEAR(band->second, (800.0 + 800.0 * t) / (1.0 - t * t), 10.0);
    // A camera looking the other way shares nothing with camera 1.
    EXPECT_FALSE(sharedViewDepths(cams[0], {camera({0, 0, 800}, {0, 0, 1}, {1, 0, 0})}).has_value());
}

TEST(FoundKeyframe, TwoCamerasAgreeOnAnObjectNeitherHadAStartFor) {
    Scene truth;
    truth.cameras = biplane();
    const XrayModelPtr corner = test::metalCorner();
    const glm::dvec3 pivot = defaultPivot(*corner);
    // Turned so that each camera sees it tilted well within +-50 deg of its own base orientation.
    RigidTransform pose = rotationAbout({0, 1, 0}, 45.0, glm::dvec3(0.0)) * rotationAbout({1, 0, 0}, 12.0, glm::dvec3(0.0)) *
                          rotationAbout({0, 0, 1}, 30.0, glm::dvec3(0.0));
    pose.translation = glm::dvec3(6.0, -4.0, 3.0) - pose.rotation * pivot;
    truth.objects.push_back({"corner", corner, pose, true});
    const std::vector<RegistrationView> views{test::preparedView(truth, 0), test::preparedView(truth, 1)};
    Scene scene = truth;
    scene.objects[0].worldFromObject = RigidTransform{};  // no start
    FindSettings find;
    find.space.tiltDeg = 50.0;
    const FoundKeyframe k = findKeyframe(scene, "corner", [&](int) { return views; }, 0, realXraySettings(), find);
    ASSERT_EQ(k.cameras.size(), 2u);
    // Each camera searched the depths the other's view crosses, not a fraction of its film distance.
    for (const CameraFind& c : k.cameras) {
        EXPECT_GT(c.space.nearMm, 0.0);
        EXPECT_LT(c.space.nearMm, 800.0);
        EXPECT_GT(c.space.farMm, 800.0);
    }
    ASSERT_TRUE(k.rayMissMm.has_value()) << "the cameras' answers disagree";
    EXPECT_LT(*k.rayMissMm, kCamerasAgreeMm);
    EXPECT_LT(k.camerasAgreeDeg, kCamerasAgreeDeg);
    EXPECT_EQ(k.verdict, AnswerVerdict::Ok);
    EXPECT_LT(glm::length(k.pose.applyToPoint(pivot) - pose.applyToPoint(pivot)), 1.0);
    EXPECT_LT(rotationBetweenDeg(pose.rotation, k.pose.rotation), 2.0);
}

}  // namespace
}  // namespace fm

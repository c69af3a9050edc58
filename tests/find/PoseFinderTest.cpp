// Finding a pose with no start on synthetic radiographs whose truth is known (find/PoseFinder.h,
// find/FoundRegistration.h): an asymmetric metal object placed off the optical axis, between the
// grids' depths, rolls and tilts, beside a distracting box, is found within 1 mm in-plane and
// 2 deg, confirmed ok; a
// symmetric one (a box: a half turn about the ray casts the same outline) is found, and the
// verdict says the image cannot tell the half-turned pose apart.
#include <memory>

#include <gtest/gtest.h>

#include "common/ErrorText.h"
#include "FindTestScenes.h"
#include "common/TestMeshes.h"
#include "find/FoundRegistration.h"
#include "find/SeenPose.h"
#include "meshdrr/MeshDrr.h"
#include "scene/MeshXrayModel.h"
#include "scene/ObjectPoseParameterization.h"
#include "xray/AnswerCheck.h"
#include "xray/CameraPoseDifference.h"
#include "xray/ObjectRegistration.h"

namespace fm {
namespace {

ProjectionGeometry film() {
    ProjectionGeometry g;
    g.source = {0.0, 0.0, 0.0};
    g.detector.size = {512, 512};
    g.detector.spacing = {0.5, 0.5};
    g.detector.u = {1, 0, 0};
    g.detector.v = {0, -1, 0};
    g.detector.origin = {-127.75, 127.75, -1000.0};
    return g;
}

using test::metalCorner;
using test::metalModel;

// The radiograph of camera 1.
RegistrationView viewOf(const Scene& truth) { return test::preparedView(truth, 0); }

TEST(PoseFinder, FindsAnAsymmetricObjectAnywhereInTheImage) {
    Scene truth;
    truth.cameras = {film()};
    const XrayModelPtr ell = metalCorner();
    const CameraAxes axes = cameraAxes(truth.cameras[0]);
    const glm::dvec3 pivot = defaultPivot(*ell);
    SeenPose seen;  // off the optical axis, between the depth, roll and tilt steps of the grids
    seen.pixel = {330.0, 170.0};
    seen.depth = 640.0;
    seen.rollDeg = 127.0;
    seen.tiltUDeg = 17.0;
    seen.tiltVDeg = -11.0;
    truth.objects.push_back({"corner", ell, worldFromSeen(axes, seen, pivot), true});
    // A distracting box elsewhere in the image.
    truth.objects.push_back({"box", metalModel(test::boxMesh({-15, -15, -15}, {15, 15, 15}), "box"),
                             RigidTransform::translate({-60.0, -50.0, -600.0}), true});
    const RegistrationView view = viewOf(truth);
    Scene scene = truth;
    scene.objects.resize(1);
    scene.objects[0].worldFromObject = RigidTransform{};  // no start
    const FoundRegistration r = registerObjectsFinding(scene, {true}, view, realXraySettings(), FindSettings{});
    ASSERT_TRUE(r.found[0].has_value());
    EXPECT_EQ(r.found[0]->stages.size(), 4u);
    const ConfirmedObject& c = r.registration.objects[0];
    const CameraPoseDifference d =
        cameraPoseDifference(truth.cameras[0], truth.objects[0].worldFromObject, c.answer.worldFromObject, pivot);
    EXPECT_LT(d.inPlaneMm, 1.0);
    EXPECT_LT(d.rotationDeg, 2.0);
    const AnswerCheck check = checkAnswer(scene.objects[0], c.answer.worldFromObject, {view}, scene.cameras, c.evidence, 0);
    EXPECT_EQ(check.verdict, AnswerVerdict::Ok) << check.text;
    for (const std::string& line : describeFindStages(r.found[0]->stages)) std::printf("%s\n", line.c_str());
    for (const FoundCandidate& f : r.found[0]->candidates) {
        const SeenPose s = seenFrom(axes, f.worldFromObject, pivot);
        std::printf("candidate %.4f: pixel %.1f %.1f depth %.1f roll %.1f tilts %.1f %.1f\n", f.similarity, s.pixel.x, s.pixel.y,
                    s.depth, s.rollDeg, s.tiltUDeg, s.tiltVDeg);
    }
}

TEST(PoseFinder, SaysWhenAHalfTurnCastsTheSameOutline) {
    Scene truth;
    truth.cameras = {film()};
    const XrayModelPtr box = metalModel(test::boxMesh({-25, -10, -6}, {25, 10, 6}), "bar");
    const CameraAxes axes = cameraAxes(truth.cameras[0]);
    SeenPose seen;
    seen.pixel = {200.0, 290.0};
    seen.depth = 700.0;
    seen.rollDeg = 40.0;
    seen.tiltUDeg = 5.0;
    seen.tiltVDeg = 5.0;
    truth.objects.push_back({"bar", box, worldFromSeen(axes, seen, glm::dvec3(0.0)), true});
    const RegistrationView view = viewOf(truth);
    Scene scene = truth;
    const FoundRegistration r = registerObjectsFinding(scene, {true}, view, realXraySettings(), FindSettings{});
    const ConfirmedObject& c = r.registration.objects[0];
    // The outline is matched (the pose is one of the bar's symmetric poses) ...
    EXPECT_GT(c.answer.similarity, kConfirmedOutlineRatio);
    // ... and a pose half a turn away scores as well: doubtful, and it says why.
    ASSERT_TRUE(c.evidence.rival.has_value());
    EXPECT_LE(c.evidence.rival->shortfallRatio, kRivalShortfallRatio);
    EXPECT_GT(c.evidence.rival->rotationDeg, 5.0);  // beyond the registration's start radius
    const AnswerCheck check = checkAnswer(scene.objects[0], c.answer.worldFromObject, {view}, scene.cameras, c.evidence, 0);
    EXPECT_EQ(check.verdict, AnswerVerdict::Doubtful) << check.text;
    EXPECT_NE(check.text.find("cannot tell them apart"), std::string::npos) << check.text;
}

TEST(PoseFinder, RefusesWhatItCannotSearch) {
    Scene scene;
    scene.cameras = {film()};
    scene.objects.push_back({"bar", metalModel(test::boxMesh({-5, -5, -5}, {5, 5, 5}), "bar"), RigidTransform{}, true});
    const RegistrationView view{0, Image(512, 512, 0.0f), std::nullopt};
    FindSettings bad;
    bad.finalists = 30;
    EXPECT_NE(test::errorOf([&] { findObjectPose(scene, 0, view, realXraySettings(), bad); }).find("finalists"),
              std::string::npos);
    EXPECT_NE(test::errorOf([&] { findObjectPose(scene, 3, view, realXraySettings(), FindSettings{}); }).find("object 4"),
              std::string::npos);
    const RegistrationView wrongSize{0, Image(100, 100, 0.0f), std::nullopt};
    EXPECT_NE(test::errorOf([&] { findObjectPose(scene, 0, wrongSize, realXraySettings(), FindSettings{}); })
                  .find("size differs"),
              std::string::npos);
    EXPECT_NE(test::errorOf([&] { registerObjectsFinding(scene, {true, false}, view, realXraySettings(), FindSettings{}); })
                  .find("one flag per object"),
              std::string::npos);
}

}  // namespace
}  // namespace fm

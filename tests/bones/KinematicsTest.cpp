// Relative kinematics: Grood-Suntay knee angles against poses built from known rotations,
// anatomical frames from landmarks, and the articulated knee phantom flexed as its generator
// flexes it.
#include <cmath>
#include <cstdio>
#include <fstream>

#include <gtest/gtest.h>

#include "bones/AnatomicalFrame.h"
#include "bones/BoneRegistration.h"
#include "bones/BoneScene.h"
#include "bones/GroodSuntay.h"
#include "common/TestData.h"
#include "core/Error.h"
#include "core/Random.h"
#include "drr/Drr.h"
#include "geometry/Pose.h"
#include "phantom/ArticulatedKnee.h"

namespace {

const glm::dvec3 kO(0.0);
constexpr double kTol = 1e-9;

TEST(GroodSuntay, PureFlexionAboutTheFemurAxis) {
    // Tibia swung posteriorly by 35 deg about the femur's X axis through the origin.
    const fm::RigidTransform pose = fm::rotationAbout({1, 0, 0}, 35.0, kO);
    for (fm::BodySide side : {fm::BodySide::Right, fm::BodySide::Left}) {
        const fm::KneeAngles k = fm::groodSuntayAngles(pose, side);
        EXPECT_NEAR(k.flexionDeg, 35.0, kTol);
        EXPECT_NEAR(k.varusDeg, 0.0, kTol);
        EXPECT_NEAR(k.internalRotationDeg, 0.0, kTol);
        EXPECT_NEAR(k.medialShiftMm, 0.0, kTol);
        EXPECT_NEAR(k.anteriorDrawerMm, 0.0, kTol);
        EXPECT_NEAR(k.distractionMm, 0.0, kTol);
    }
    // Flexion moves the shank's distal end posteriorly (+Y in the femur frame).
    EXPECT_GT(pose.applyToPoint({0, 0, -100}).y, 0.0);
}

TEST(GroodSuntay, ClinicalSignsFollowTheSide) {
    // Right knee: +X (patient left) is medial. Turning the tibia's front (-Y) towards +X about
    // its own long axis is internal rotation; for a left knee the same motion is external.
    const fm::RigidTransform turn = fm::rotationAbout({0, 0, 1}, 12.0, kO);
    EXPECT_NEAR(fm::groodSuntayAngles(turn, fm::BodySide::Right).internalRotationDeg, 12.0, kTol);
    EXPECT_NEAR(fm::groodSuntayAngles(turn, fm::BodySide::Left).internalRotationDeg, -12.0, kTol);
    EXPECT_GT(turn.applyToVector({0, -1, 0}).x, 0.0);
    // The ankle (distal tibia) moving medially is varus: for a right knee towards +X.
    const fm::RigidTransform tilt = fm::rotationAbout({0, 1, 0}, -8.0, kO);
    EXPECT_GT(tilt.applyToPoint({0, 0, -100}).x, 0.0);
    EXPECT_NEAR(fm::groodSuntayAngles(tilt, fm::BodySide::Right).varusDeg, 8.0, kTol);
    EXPECT_NEAR(fm::groodSuntayAngles(tilt, fm::BodySide::Left).varusDeg, -8.0, kTol);
    // A tibia 4 mm anterior (-Y), 3 mm towards +X, 2 mm lower (away from the femur).
    const fm::RigidTransform shift = fm::RigidTransform::translate({3.0, -4.0, -2.0});
    const fm::KneeAngles k = fm::groodSuntayAngles(shift, fm::BodySide::Right);
    EXPECT_NEAR(k.anteriorDrawerMm, 4.0, kTol);
    EXPECT_NEAR(k.medialShiftMm, 3.0, kTol);
    EXPECT_NEAR(k.distractionMm, 2.0, kTol);
}

TEST(GroodSuntay, EqualsTheXyzCardanSequenceAndInvertsExactly) {
    fm::Rng rng(12);
    for (int n = 0; n < 50; ++n) {
        const double a = rng.uniform(-20.0, 120.0), b = rng.uniform(-15.0, 15.0),
                     c = rng.uniform(-30.0, 30.0);
        // Independent construction: femurFromTibia = Rx(a) Ry(b) Rz(c) (right-handed, raw).
        const fm::RigidTransform r = fm::rotationAbout({1, 0, 0}, a, kO) *
                                     fm::rotationAbout({0, 1, 0}, b, kO) *
                                     fm::rotationAbout({0, 0, 1}, c, kO);
        const fm::KneeAngles k = fm::groodSuntayAngles(r, fm::BodySide::Right);
        EXPECT_NEAR(k.flexionDeg, a, 1e-8);
        EXPECT_NEAR(k.varusDeg, -b, 1e-8);
        EXPECT_NEAR(k.internalRotationDeg, c, 1e-8);
        fm::KneeAngles want{rng.uniform(-10, 120), rng.uniform(-10, 10),
                            rng.uniform(-20, 20),  rng.uniform(-5, 5),
                            rng.uniform(-8, 8),    rng.uniform(-3, 3)};
        for (fm::BodySide side : {fm::BodySide::Right, fm::BodySide::Left}) {
            const fm::KneeAngles got =
                fm::groodSuntayAngles(fm::poseFromGroodSuntay(want, side), side);
            EXPECT_NEAR(got.flexionDeg, want.flexionDeg, 1e-8);
            EXPECT_NEAR(got.varusDeg, want.varusDeg, 1e-8);
            EXPECT_NEAR(got.internalRotationDeg, want.internalRotationDeg, 1e-8);
            EXPECT_NEAR(got.medialShiftMm, want.medialShiftMm, 1e-8);
            EXPECT_NEAR(got.anteriorDrawerMm, want.anteriorDrawerMm, 1e-8);
            EXPECT_NEAR(got.distractionMm, want.distractionMm, 1e-8);
        }
    }
    EXPECT_THROW(fm::groodSuntayAngles(fm::rotationAbout({0, 1, 0}, 90.0, kO), fm::BodySide::Right),
                 fm::Error);
}

TEST(AnatomicalFrame, FromLandmarksAndFromAFile) {
    fm::BoneLandmarks l;
    l.origin = {10, 20, 30};
    l.proximal = glm::dvec3{10, 22, 430};           // long axis slightly tilted
    l.left = {50, 20, 35};
    l.right = {-30, 20, 25};
    const fm::RigidTransform f = fm::anatomicalFrameFromLandmarks(l, "femur");
    const glm::dvec3 z = f.rotation[2], x = f.rotation[0];
    EXPECT_NEAR(glm::dot(z, glm::normalize(glm::dvec3(0, 2, 400))), 1.0, 1e-12);
    EXPECT_NEAR(glm::dot(x, z), 0.0, 1e-12);
    EXPECT_GT(x.x, 0.99);
    EXPECT_GT(f.rotation[1].y, 0.99);  // Y posterior
    EXPECT_EQ(f.translation, l.origin);
    l.right = l.left;
    EXPECT_THROW(fm::anatomicalFrameFromLandmarks(l, "femur"), fm::Error);
    l.distal = glm::dvec3{0, 0, 0};
    EXPECT_THROW(fm::anatomicalFrameFromLandmarks(l, "femur"), fm::Error);  // both given

    const auto path = fm::test::scratchDir("anatomical") / "landmarks.json";
    std::ofstream(path) << R"({"tibia": {"origin": [0,0,0], "distal": [0,0,-300],
        "left": [30,0,0], "right": [-30,0,0]}, "femur": {"origin": [0,0,0]}})";
    const fm::RigidTransform t = fm::readAnatomicalFrame(path.string(), "tibia");
    EXPECT_NEAR(t.rotation[2].z, 1.0, 1e-12);
    EXPECT_THROW(fm::readAnatomicalFrame(path.string(), "femur"), fm::Error);    // incomplete
    EXPECT_THROW(fm::readAnatomicalFrame(path.string(), "patella"), fm::Error);  // absent
}

TEST(ArticulatedKnee, BonePosesMoveLandmarksWhereTheGeneratorPutsThem) {
    for (bool left : {false, true}) {
        fm::KneePhantomParams rest;
        rest.leftKnee = left;
        rest.flexionDeg = 10.0;
        fm::KneePhantomParams flexed = rest;
        flexed.flexionDeg = 55.0;
        const fm::KneeBonePoses poses = fm::kneeBonePoses(rest, 55.0);
        for (const glm::dvec3 p : {glm::dvec3(4, -2, -120), glm::dvec3(-36, 22, -40),
                                   glm::dvec3(0, 4, -3)}) {
            const glm::dvec3 moved =
                poses.tibia.applyToPoint(fm::kneeModelToWorld(rest, fm::KneeSegment::Tibia, p));
            EXPECT_LT(glm::length(moved - fm::kneeModelToWorld(flexed, fm::KneeSegment::Tibia, p)),
                      1e-9);
        }
        for (const glm::dvec3 p : {fm::kPatellaCenter, fm::kPatellaCenter + glm::dvec3(10, 5, -8)}) {
            const glm::dvec3 moved = poses.patella.applyToPoint(
                fm::kneeModelToWorld(rest, fm::KneeSegment::Patella, p));
            EXPECT_LT(
                glm::length(moved - fm::kneeModelToWorld(flexed, fm::KneeSegment::Patella, p)),
                1e-9);
        }
        // The femur does not move.
        EXPECT_EQ(poses.femur.translation, glm::dvec3(0.0));
    }
}

TEST(ArticulatedKnee, FlexedBonesCoverTheGeneratorsFlexedBones) {
    // Labels of the knee generated at 40 deg against those of the straight knee moved by the
    // tibia's pose: the same voxels up to nearest-neighbour rounding at the surface.
    fm::KneePhantomParams rest;
    rest.dims = {80, 80, 88};
    fm::KneePhantomParams flexed = rest;
    flexed.flexionDeg = 40.0;
    const fm::Volume restLabels = fm::makeKneeBoneLabels(rest);
    const fm::Volume flexedLabels = fm::makeKneeBoneLabels(flexed);
    const fm::RigidTransform restFromFlexed = fm::kneeBonePoses(rest, 40.0).tibia.inverse();
    std::size_t tibia = 0, agree = 0;
    for (int k = 0; k < flexedLabels.dims.z; ++k)
        for (int j = 0; j < flexedLabels.dims.y; ++j)
            for (int i = 0; i < flexedLabels.dims.x; ++i) {
                if (flexedLabels.at(i, j, k) != 2.0f) continue;
                ++tibia;
                const glm::dvec3 ijk = glm::floor(
                    restLabels.worldToIndex(restFromFlexed.applyToPoint(
                        flexedLabels.indexToWorld({i, j, k}))) + 0.5);
                if (glm::all(glm::greaterThanEqual(ijk, glm::dvec3(0))) &&
                    glm::all(glm::lessThan(ijk, glm::dvec3(restLabels.dims))) &&
                    restLabels.at(int(ijk.x), int(ijk.y), int(ijk.z)) == 2.0f)
                    ++agree;
            }
    ASSERT_GT(tibia, 1000u);
    EXPECT_GT(double(agree) / tibia, 0.95);
}

TEST(ArticulatedKnee, SceneIsTheWholeKneeAtRestAndFlexesByGroodSuntay) {
    fm::KneePhantomParams p;
    p.dims = {64, 64, 70};
    fm::Scene knee = fm::makeArticulatedKnee(p);
    ASSERT_EQ(knee.objects.size(), 4u);  // femur, tibia, patella, rest (soft tissue)
    // At rest the scene's DRR is the phantom's DRR (line integrals add over the bones).
    fm::SceneSetup setup = fm::defaultSceneSetup();
    setup.filmPixels = {64, 64};
    const fm::ProjectionGeometry g =
        fm::sceneGeometry(fm::Pose{{0, 0, 0}, 90.0, 0.0, 0.0}, setup, glm::dvec3(0.0));
    const fm::Image whole =
        fm::renderDrr(*fm::prepareDrrVolume(fm::makeKneePhantom(p), {}), g, {});
    const fm::Image scene = fm::renderView(knee, g, {});
    double worst = 0.0, peak = 0.0;
    for (std::size_t n = 0; n < whole.pixels.size(); ++n) {
        worst = std::max(worst, double(std::abs(scene.pixels[n] - whole.pixels[n])));
        peak = std::max(peak, double(whole.pixels[n]));
    }
    EXPECT_LT(worst, 1e-5 * peak);
    // Flexed to 30 deg: the tibia in the femur's frame has Grood-Suntay flexion 30, no varus or
    // rotation, and the translation of a rotation about the flexion axis through
    // kFlexionAxisPoint: h = c - R c in the femur frame (origin at the joint centre).
    fm::flexKnee(knee, p, 30.0);
    const fm::RigidTransform femurFromTibia =
        fm::kneeAnatomicalFrame(p, fm::KneeSegment::Femur).inverse() *
        fm::relativePose(knee, fm::kKneeFemur, fm::kKneeTibia) *
        fm::kneeAnatomicalFrame(p, fm::KneeSegment::Tibia);
    const fm::KneeAngles k = fm::groodSuntayAngles(femurFromTibia, fm::BodySide::Right);
    EXPECT_NEAR(k.flexionDeg, 30.0, 1e-9);
    EXPECT_NEAR(k.varusDeg, 0.0, 1e-9);
    EXPECT_NEAR(k.internalRotationDeg, 0.0, 1e-9);
    const double s = std::sin(30.0 * M_PI / 180.0), c = std::cos(30.0 * M_PI / 180.0);
    const glm::dvec3 axis = fm::kFlexionAxisPoint;
    const glm::dvec3 h = axis - glm::dvec3(axis.x, axis.y * c - axis.z * s, axis.y * s + axis.z * c);
    // e2 = (0, c, s), e3 = (0, -s, c): anterior drawer = -h.e2, distraction = -h.e3.
    EXPECT_NEAR(k.anteriorDrawerMm, -glm::dot(h, glm::dvec3(0, c, s)), 1e-9);
    EXPECT_NEAR(k.distractionMm, -glm::dot(h, glm::dvec3(0, -s, c)), 1e-9);
    EXPECT_NEAR(k.medialShiftMm, 0.0, 1e-9);
    // And the flexed image differs from the straight one (the tibia moved in the picture).
    const fm::Image bent = fm::renderView(knee, g, {});
    double change = 0.0;
    for (std::size_t n = 0; n < whole.pixels.size(); ++n)
        change = std::max(change, double(std::abs(bent.pixels[n] - whole.pixels[n])));
    EXPECT_GT(change, 0.1 * peak);
}

}  // namespace

namespace {

TEST(ArticulatedKnee, RegisteringTheTibiaAloneFindsTheFlexion) {
    // The hidden reference flexes the knee by 12 deg (tibia and patella move); the tibia alone
    // is registered from the straight pose with the femur, patella and soft tissue static; its
    // pose in the femur's frame gives the flexion by Grood-Suntay.
    fm::KneePhantomParams p;
    p.dims = {80, 80, 88};
    fm::Scene knee = fm::makeArticulatedKnee(p);
    fm::SceneSetup setup = fm::defaultSceneSetup();
    setup.filmPixels = {128, 128};
    // Biplane, lateral and AP: one view alone hardly sees the out-of-plane rotations (varus in
    // a lateral view).
    for (double azimuth : {90.0, 0.0})
        knee.cameras.push_back(fm::sceneGeometry(fm::Pose{{0, 0, 0}, azimuth, 0.0, 0.0}, setup, {}));
    fm::Scene truth = knee;
    fm::flexKnee(truth, p, 12.0);
    truth.object(fm::kKneePatella).worldFromObject = fm::RigidTransform::identity();  // tibia only
    fm::RegistrationSettings settings;
    settings.globalEvaluations = 200;
    settings.polishEvaluations = 60;
    const fm::BoneRegistrationResult r =
        fm::registerBone(knee, fm::kKneeTibia,
                         {fm::renderView(truth, 0, {}), fm::renderView(truth, 1, {})}, settings);
    knee.object(fm::kKneeTibia).worldFromObject = r.worldFromBone;
    const fm::KneeAngles k = fm::groodSuntayAngles(
        fm::kneeAnatomicalFrame(p, fm::KneeSegment::Femur).inverse() *
            fm::relativePose(knee, fm::kKneeFemur, fm::kKneeTibia) *
            fm::kneeAnatomicalFrame(p, fm::KneeSegment::Tibia),
        fm::BodySide::Right);
    std::printf("tibia registered alone: flexion %.3f deg (truth 12), varus %.3f, internal %.3f, "
                "%d evaluations\n",
                k.flexionDeg, k.varusDeg, k.internalRotationDeg, r.search.evaluations);
    EXPECT_NEAR(k.flexionDeg, 12.0, 0.5);
    EXPECT_NEAR(k.varusDeg, 0.0, 1.0);
    EXPECT_NEAR(k.internalRotationDeg, 0.0, 1.0);
}

}  // namespace

// Registration of one bone at a time on the real CT: femur_right moved 10 mm / 10 deg
// relative to the pelvis (hip_right, itself moved a little) in a biplane reference; femur_right
// registered alone from the unmoved pose, then hip_right the same way; the relative pose
// femur-to-hip against the truth.
#include <chrono>
#include <cstdio>

#include <gtest/gtest.h>

#include "bones/BoneRegistration.h"
#include "bones/BoneScene.h"
#include "bones/BoneVolume.h"
#include "bones/LabelMap.h"
#include "common/TestData.h"
#include "geometry/Pose.h"
#include "io/ReadVolume.h"

namespace {

std::vector<glm::dvec3> targetsOf(const fm::Volume& ct, const fm::Volume& labels,
                                  const fm::BoneSelection& bone) {
    return fm::boneTargetPoints(fm::boneVolume(ct, labels, bone), 200.0, 500);
}

TEST(BoneRegistration, FemurThenHipOnTheRealCtRecoverTheirPosesAndTheRelativePose) {
    FM_REQUIRE_SHARED_DATA("totalseg-example-ct/example_seg_fast_force_split.nii.gz");
    const auto dir = fm::test::sharedDataDir() / "totalseg-example-ct";
    const fm::Volume ct = fm::readVolume(dir / "example_ct.nii.gz");
    const fm::Volume labels =
        fm::loadLabelMap((dir / "example_seg_fast_force_split.nii.gz").string(), ct);
    const fm::BoneSelection femur{"femur_right", {76}}, hip{"hip_right", {78}};
    // The two bones only (the rest of the CT left out, as docs/bones.md allows): what moves is
    // what is compared, and each evaluation traces two small volumes instead of the whole CT.
    fm::Scene scene = fm::makeBoneScene(ct, labels, {femur, hip}, {.includeRest = false});
    // Biplane: the 2011 AP and lateral cameras around the CT's centre.
    fm::SceneSetup setup = fm::defaultSceneSetup();
    setup.filmPixels = {160, 160};
    for (double azimuth : {0.0, 90.0})
        scene.cameras.push_back(
            fm::sceneGeometry(fm::Pose{{0, 0, 0}, azimuth, 0.0, 0.0}, setup, ct.center()));

    // Truth: the pelvis moved 3 mm / 3 deg, the femur moved with it and then 10 mm / 10 deg
    // relative to it (about its own centre).
    const glm::dvec3 hipCentre = fm::boneCentroid(labels, hip);
    const glm::dvec3 femurCentre = fm::boneCentroid(labels, femur);
    const fm::RigidTransform worldFromHip = fm::RigidTransform::translate({1.0, -2.0, 2.0}) *
                                            fm::rotationAbout({0.3, 1.0, 0.2}, 3.0, hipCentre);
    const fm::RigidTransform hipFromFemur =
        fm::RigidTransform::translate(glm::normalize(glm::dvec3(0.6, -0.5, 0.62)) * 10.0) *
        fm::rotationAbout({1.0, 0.4, -0.3}, 10.0, femurCentre);
    const fm::RigidTransform worldFromFemur = worldFromHip * hipFromFemur;
    fm::Scene truth = scene;
    truth.object("hip_right").worldFromObject = worldFromHip;
    truth.object("femur_right").worldFromObject = worldFromFemur;
    std::vector<fm::Image> references;
    for (std::size_t c = 0; c < truth.cameras.size(); ++c)
        references.push_back(fm::renderView(truth, c, {}));

    fm::RegistrationSettings settings;
    settings.globalEvaluations = 300;
    settings.polishEvaluations = 80;
    settings.seed = 3;
    const auto femurTargets = targetsOf(ct, labels, femur);
    const auto hipTargets = targetsOf(ct, labels, hip);
    const auto t0 = std::chrono::steady_clock::now();
    const double startFemur =
        fm::bonePoseError(scene.cameras[0], worldFromFemur, {}, femurTargets).meanMm;
    const fm::BoneRegistrationResult f =
        fm::registerBone(scene, "femur_right", references, settings);
    scene.object("femur_right").worldFromObject = f.worldFromBone;
    const fm::BoneRegistrationResult h = fm::registerBone(scene, "hip_right", references, settings);
    scene.object("hip_right").worldFromObject = h.worldFromBone;
    // The femur was registered against a pelvis still at its old pose, where they overlap at
    // the hip joint: once more from where it is, now that the pelvis is in place (small radius).
    fm::RegistrationSettings refine = settings;
    refine.searchRadius = {2.0, 2.0, 4.0, 2.0, 2.0, 2.0};
    refine.globalEvaluations = 60;
    refine.levelFactors = {2, 1};
    // Confirmed (register --bone's default): two searches from independent starts, the curvature.
    const fm::BoneRegistrationResult f2 =
        fm::registerBone(scene, "femur_right", references, refine, 20.0, {}, nullptr, fm::ConfirmationSettings{});
    scene.object("femur_right").worldFromObject = f2.worldFromBone;
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

    const double firstFemurError =
        fm::bonePoseError(scene.cameras[0], worldFromFemur, f.worldFromBone, femurTargets).meanMm;
    const double femurError =
        fm::bonePoseError(scene.cameras[0], worldFromFemur, f2.worldFromBone, femurTargets).meanMm;
    const double hipError =
        fm::bonePoseError(scene.cameras[0], worldFromHip, h.worldFromBone, hipTargets).meanMm;
    // The relative pose femur-to-hip against the truth, as the mTRE of the femur's targets in
    // the hip's frame.
    const fm::RigidTransform foundHipFromFemur = fm::relativePose(scene, "hip_right", "femur_right");
    double relative = 0.0;
    for (const glm::dvec3& p : femurTargets)
        relative += glm::length(foundHipFromFemur.applyToPoint(p) - hipFromFemur.applyToPoint(p));
    relative /= double(femurTargets.size());
    std::printf("femur_right: start mTRE %.2f mm -> %.3f mm (first pass %.3f mm); hip_right -> "
                "%.3f mm; relative femur-in-hip error %.3f mm; %.1f s (%d + %d + %d "
                "evaluations)\n",
                startFemur, femurError, firstFemurError, hipError, relative, seconds,
                f.search.evaluations, h.search.evaluations, f2.search.evaluations);
    EXPECT_GT(startFemur, 8.0);
    EXPECT_LT(femurError, 1.0);
    EXPECT_LT(hipError, 1.0);
    EXPECT_LT(relative, 1.0);
    // How sure, without the truth: the searches agree, the similarity is a perfect match's.
    const fm::AnswerCheck verdict = fm::judgeEvidence(f2.evidence);
    EXPECT_EQ(verdict.verdict, fm::AnswerVerdict::Ok) << verdict.text;
    EXPECT_GE(f2.evidence.runs, 2);
    ASSERT_TRUE(f2.evidence.similarityRatio);
    EXPECT_GT(*f2.evidence.similarityRatio, fm::kConfirmedPerfectMatchRatio);
    ASSERT_TRUE(f2.evidence.uncertainty);
    EXPECT_TRUE(f2.evidence.uncertainty->bounded);
    // The first searches ran alone (the games' default): no confirmation, never ok on that.
    EXPECT_EQ(f.evidence.runs, 1);
    EXPECT_FALSE(f.evidence.uncertainty);
}

}  // namespace

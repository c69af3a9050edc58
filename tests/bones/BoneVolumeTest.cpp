// A bone's own volume: cropped to its box plus a margin, air outside the bone; and the DRR of
// a bone plus the DRR of the rest equals the DRR of the whole (synthetic and the real CT).
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "bones/BoneScene.h"
#include "bones/BoneVolume.h"
#include "bones/LabelMap.h"
#include "bones/LabelTable.h"
#include "common/TestData.h"
#include "core/Error.h"
#include "drr/Drr.h"
#include "geometry/Pose.h"
#include "io/ReadVolume.h"
#include "test_support_bones.h"

namespace {

fm::ProjectionGeometry cameraFor(const fm::Volume& v, double azimuth, int pixels) {
    fm::SceneSetup setup = fm::defaultSceneSetup();
    setup.filmPixels = {pixels, pixels};
    fm::Pose pose;
    pose.azimuthDeg = azimuth;
    pose.elevationDeg = 15.0;
    return fm::sceneGeometry(pose, setup, v.center());
}

// Largest |a + b - whole| relative to the largest pixel of `whole`.
double additivityError(const fm::Image& a, const fm::Image& b, const fm::Image& whole) {
    double worst = 0.0, peak = 0.0;
    for (std::size_t n = 0; n < whole.pixels.size(); ++n) {
        worst = std::max(worst, std::abs(double(a.pixels[n]) + b.pixels[n] - whole.pixels[n]));
        peak = std::max(peak, double(whole.pixels[n]));
    }
    EXPECT_GT(peak, 0.0);
    return worst / peak;
}

// Float images of sums over a few hundred voxels: relative 1e-5 is a few float ulps of the
// largest pixel, far below one voxel's contribution (about 1e-2 of it).
constexpr double kFloatRelTol = 1e-5;

TEST(BoneVolume, CropsToTheBoxWithMarginAndSetsTheRestToAir) {
    fm::Volume ct = fm::test::grid({20, 20, 20}, {1.0, 2.0, 1.5}, {-5.0, 3.0, 7.0}, 40.0f);
    fm::Volume labels = fm::test::grid({20, 20, 20}, {1.0, 2.0, 1.5}, {-5.0, 3.0, 7.0});
    fm::test::fillBox(labels, {5, 6, 7}, {9, 10, 12}, 4.0f);
    fm::test::fillBox(ct, {5, 6, 7}, {9, 10, 12}, 900.0f);
    labels.at(9, 10, 12) = 0.0f;  // one voxel of bone value not labelled: must become air
    const fm::BoneSelection bone{"b", {4}};
    const fm::VoxelBox box = fm::boneVoxelBox(labels, bone);
    EXPECT_EQ(box.lower, glm::ivec3(5, 6, 7));
    EXPECT_EQ(box.upper, glm::ivec3(9, 10, 12));
    const fm::Volume v = fm::boneVolume(ct, labels, bone, {.marginVoxels = 2});
    EXPECT_EQ(v.dims, glm::ivec3(9, 9, 10));
    // Its first voxel is CT voxel (3, 4, 5), at the same world position.
    const glm::dvec3 d = v.indexToWorld({0, 0, 0}) - ct.indexToWorld({3, 4, 5});
    EXPECT_LT(glm::length(d), 1e-12);
    EXPECT_EQ(v.at(2, 2, 2), 900.0f);
    EXPECT_EQ(v.at(0, 0, 0), fm::kAirHU);
    EXPECT_EQ(v.at(6, 6, 7), fm::kAirHU);  // CT (9,10,12): bone value, not labelled
    const fm::Volume rest = fm::volumeWithout(ct, labels, bone);
    EXPECT_EQ(rest.at(5, 6, 7), fm::kAirHU);
    EXPECT_EQ(rest.at(9, 10, 12), 900.0f);
    EXPECT_EQ(rest.at(0, 0, 0), 40.0f);
    // Margin clipped at the CT border.
    fm::test::fillBox(labels, {0, 0, 0}, {0, 0, 0}, 4.0f);
    EXPECT_EQ(fm::boneVolume(ct, labels, bone, {.marginVoxels = 3}).dims,
              glm::ivec3(13, 14, 16));
    const fm::Volume mask = fm::boneMask(labels, bone, 0);
    EXPECT_EQ(mask.at(0, 0, 0), 1.0f);
    EXPECT_EQ(mask.at(1, 0, 0), 0.0f);
}

TEST(BoneVolume, EmptyBoneAndForeignGridAreRefused) {
    const fm::Volume ct = fm::test::grid({8, 8, 8}, {1.0, 1.0, 1.0}, {0.0, 0.0, 0.0});
    fm::Volume labels = ct;
    labels.at(1, 1, 1) = 2.0f;
    EXPECT_THROW(fm::boneVolume(ct, labels, {"missing", {3}}), fm::Error);
    EXPECT_THROW(fm::volumeWithout(ct, labels, {"missing", {3}}), fm::Error);
    fm::Volume shifted = labels;
    shifted.origin.x += 1.0;
    EXPECT_THROW(fm::boneVolume(ct, shifted, {"two", {2}}), fm::Error);
    EXPECT_THROW(fm::boneVolume(ct, labels, {"two", {2}}, {.marginVoxels = -1}), fm::Error);
}

TEST(BoneVolume, CentroidIsTheMeanOfTheBoneVoxels) {
    fm::Volume labels = fm::test::grid({10, 10, 10}, {2.0, 1.0, 1.0}, {1.0, 0.0, 0.0});
    fm::test::fillBox(labels, {2, 3, 4}, {4, 3, 6}, 1.0f);
    const glm::dvec3 c = fm::boneCentroid(labels, {"b", {1}});
    EXPECT_NEAR(c.x, 1.0 + 2.0 * 3.0, 1e-12);
    EXPECT_NEAR(c.y, 3.0, 1e-12);
    EXPECT_NEAR(c.z, 5.0, 1e-12);
}

TEST(BoneVolume, BonePlusRestEqualsWholeOnTheRealCt) {
    FM_REQUIRE_SHARED_DATA("totalseg-example-ct/example_seg_fast_force_split.nii.gz");
    const auto dir = fm::test::sharedDataDir() / "totalseg-example-ct";
    const fm::Volume ct = fm::readVolume(dir / "example_ct.nii.gz");
    const fm::Volume labels =
        fm::loadLabelMap((dir / "example_seg_fast_force_split.nii.gz").string(), ct);
    // Voxel counts from the data README (section 6).
    const auto counts = fm::labelVoxelCounts(labels);
    EXPECT_EQ(counts.at(76), 4396u);
    EXPECT_EQ(counts.at(78), 13048u);
    const fm::BoneSelection femur{"femur_right", {76}};
    const fm::DrrValueOptions mu;
    const fm::DrrVolumePtr whole = fm::prepareDrrVolume(ct, mu);
    const fm::DrrVolumePtr bone = fm::prepareDrrVolume(fm::boneVolume(ct, labels, femur), mu);
    const fm::DrrVolumePtr rest = fm::prepareDrrVolume(fm::volumeWithout(ct, labels, femur), mu);
    for (double azimuth : {0.0, 70.0}) {
        const fm::ProjectionGeometry g = cameraFor(ct, azimuth, 96);
        const fm::Image a = fm::renderDrr(*bone, g, {});
        const fm::Image b = fm::renderDrr(*rest, g, {});
        const fm::Image w = fm::renderDrr(*whole, g, {});
        EXPECT_LT(additivityError(a, b, w), kFloatRelTol) << "azimuth " << azimuth;
        // The bone alone is not nothing: a small but real share of the pelvis image.
        double boneSum = 0.0, wholeSum = 0.0;
        for (std::size_t n = 0; n < w.pixels.size(); ++n) {
            boneSum += a.pixels[n];
            wholeSum += w.pixels[n];
        }
        EXPECT_GT(boneSum, 0.001 * wholeSum);  // measured: 0.4-0.7 %
    }
    // The same through a scene of two bones and the rest, each traced in its own frame.
    const fm::Scene scene = fm::makeBoneScene(ct, labels, {femur, {"hip_right", {78}}});
    ASSERT_EQ(scene.objects.size(), 3u);
    const fm::ProjectionGeometry g = cameraFor(ct, 30.0, 96);
    const fm::Image sceneImage = fm::renderView(scene, g, {});
    const fm::Image w = fm::renderDrr(*whole, g, {});
    const fm::Image zero(w.width, w.height, 0.0f);
    EXPECT_LT(additivityError(sceneImage, zero, w), kFloatRelTol);
}

TEST(BoneScene, RefusesOverlappingBonesAndReportsRelativePoses) {
    fm::Volume ct = fm::test::grid({12, 12, 12}, {1.0, 1.0, 1.0}, {0.0, 0.0, 0.0}, 0.0f);
    fm::Volume labels = ct;
    fm::test::fillBox(labels, {1, 1, 1}, {3, 3, 3}, 1.0f);
    fm::test::fillBox(labels, {7, 7, 7}, {9, 9, 9}, 2.0f);
    EXPECT_THROW(fm::makeBoneScene(ct, labels, {{"a", {1}}, {"b", {1, 2}}}), fm::Error);
    EXPECT_THROW(fm::makeBoneScene(ct, labels, {{"a", {1}}, {"a", {2}}}), fm::Error);
    EXPECT_THROW(fm::makeBoneScene(ct, labels, {{"a", {1}}, {"c", {3}}}), fm::Error);
    fm::Scene s = fm::makeBoneScene(ct, labels, {{"a", {1}}, {"b", {2}}}, {.includeRest = false});
    ASSERT_EQ(s.objects.size(), 2u);
    const fm::RigidTransform worldFromA = fm::rotationAbout({0, 0, 1}, 30.0, {1, 2, 3});
    const fm::RigidTransform worldFromB = fm::RigidTransform::translate({5, 0, 0});
    s.object("a").worldFromObject = worldFromA;
    s.object("b").worldFromObject = worldFromB;
    const fm::RigidTransform aFromB = fm::relativePose(s, "a", "b");
    const glm::dvec3 p{1.0, -2.0, 4.0};
    const glm::dvec3 viaWorld = worldFromA.inverse().applyToPoint(worldFromB.applyToPoint(p));
    EXPECT_LT(glm::length(aFromB.applyToPoint(p) - viaWorld), 1e-12);
}

}  // namespace

// How prepared voxels are stored: int16 exactly when every value per mm is a scale times an
// integer of int16's range, else float; and that the stored type never changes an image beyond
// the float rounding the float store itself makes.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "DrrTestUtil.h"
#include "drr/Drr.h"

namespace {

fm::DrrValueOptions options(fm::DrrValues values, bool compact = true) {
    fm::DrrValueOptions o;
    o.values = values;
    o.compactVoxels = compact;
    return o;
}

fm::DrrVoxelType typeOf(const fm::Volume& volume, const fm::DrrValueOptions& o) {
    return fm::drrVolumeInfo(*fm::prepareDrrVolume(volume, o)).voxelType;
}

// Whole-HU values from air to dense bone, a quarter exactly air (-1000 HU: mu 0) or raw 0, on an
// oblique anisotropic grid.
fm::Volume integerCt(unsigned seed) {
    fm::Volume volume = fm::test::makeVolume({21, 18, 15}, {1.1, 0.8, 1.7}, 0.0f, {-4.0, 2.0, 1.0},
                                             fm::test::rotation(31.0, {0.5, 1.0, -1.0}));
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> hu(-1000, 3000);
    for (float& x : volume.values) x = rng() % 4 == 0 ? -1000.0f : float(hu(rng));
    return volume;
}

TEST(DrrVoxelType, Int16OnlyWhereItHoldsEveryValueExactly) {
    using fm::DrrValues;
    using fm::DrrVoxelType;
    fm::Volume volume = fm::test::makeVolume({6, 5, 4}, {1.0, 1.0, 1.0}, -1000.0f);
    volume.at(2, 2, 2) = 1200.0f;
    EXPECT_EQ(typeOf(volume, options(DrrValues::Mu)), DrrVoxelType::Int16);
    EXPECT_EQ(typeOf(volume, options(DrrValues::Raw)), DrrVoxelType::Int16);
    EXPECT_EQ(typeOf(volume, options(DrrValues::Mu, false)), DrrVoxelType::Float32);
    fm::DrrValueOptions downsampled = options(DrrValues::Mu);
    downsampled.downsample = 2;  // block means are not integers
    EXPECT_EQ(typeOf(volume, downsampled), DrrVoxelType::Float32);

    // The ends of the range: mu stores HU + 1000, raw stores the value.
    volume.at(1, 1, 1) = 31767.0f;
    EXPECT_EQ(typeOf(volume, options(DrrValues::Mu)), DrrVoxelType::Int16);
    volume.at(1, 1, 1) = 31768.0f;
    EXPECT_EQ(typeOf(volume, options(DrrValues::Mu)), DrrVoxelType::Float32);
    volume.at(1, 1, 1) = -32768.0f;
    EXPECT_EQ(typeOf(volume, options(DrrValues::Raw)), DrrVoxelType::Int16);
    volume.at(1, 1, 1) = -32769.0f;
    EXPECT_EQ(typeOf(volume, options(DrrValues::Raw)), DrrVoxelType::Float32);
    // ... mu clamps everything below air to 0, which int16 holds.
    EXPECT_EQ(typeOf(volume, options(DrrValues::Mu)), DrrVoxelType::Int16);

    // A value the threshold removes does not count; one it keeps does.
    volume.at(1, 1, 1) = 0.5f;
    EXPECT_EQ(typeOf(volume, options(DrrValues::Raw)), DrrVoxelType::Float32);
    fm::DrrValueOptions bone = options(DrrValues::Raw);
    bone.thresholdHU = 200.0;
    EXPECT_EQ(typeOf(volume, bone), DrrVoxelType::Int16);
    volume.at(1, 1, 1) = 40000.0f;
    EXPECT_EQ(typeOf(volume, bone), DrrVoxelType::Float32);

    // NaN is "no data" (0 in both stores).
    volume.at(1, 1, 1) = std::numeric_limits<float>::quiet_NaN();
    EXPECT_EQ(typeOf(volume, options(DrrValues::Raw)), DrrVoxelType::Int16);

    const fm::DrrVolumeInfo info = fm::drrVolumeInfo(*fm::prepareDrrVolume(volume, options(DrrValues::Raw)));
    const glm::ivec3 padded = info.dims + 2;
    EXPECT_EQ(info.voxelBytes, std::size_t(padded.x) * padded.y * padded.z * sizeof(std::int16_t));
}

// Raw values: the int16 store holds the very numbers the float store holds, so every walk gives
// the same bits (scale 1).
TEST(DrrVoxelType, RawImagesAreTheFloatImagesBitForBit) {
    const fm::Volume volume = integerCt(3);
    const fm::DrrVolumePtr small = fm::prepareDrrVolume(volume, options(fm::DrrValues::Raw));
    const fm::DrrVolumePtr wide = fm::prepareDrrVolume(volume, options(fm::DrrValues::Raw, false));
    ASSERT_EQ(fm::drrVolumeInfo(*small).voxelType, fm::DrrVoxelType::Int16);
    ASSERT_EQ(fm::drrVolumeInfo(*wide).voxelType, fm::DrrVoxelType::Float32);
    for (double azimuth : {0.0, 47.0, 90.0, 200.0}) {
        fm::ProjectionGeometry g =
            fm::test::orbitGeometry(volume.center(), azimuth, 23.0, 180.0, 120.0, 35, 1.3);
        for (fm::DrrExactWalk walk :
             {fm::DrrExactWalk::Auto, fm::DrrExactWalk::Bricks, fm::DrrExactWalk::Dense}) {
            fm::DrrRenderOptions o;
            o.walk = walk;
            const fm::Image a = fm::renderDrr(*small, g, o), b = fm::renderDrr(*wide, g, o);
            int differing = 0, nonZero = 0;
            for (std::size_t p = 0; p < a.pixels.size(); ++p) {
                differing += a.pixels[p] != b.pixels[p];
                nonZero += b.pixels[p] != 0.0f;
            }
            EXPECT_EQ(differing, 0) << "azimuth " << azimuth << ", walk " << int(walk);
            EXPECT_GT(nonZero, int(a.pixels.size()) / 4);
        }
        const glm::dvec3 target = g.detector.pixelCenter(17, 17);
        for (bool skip : {true, false})
            EXPECT_EQ(fm::drrLineIntegral(*small, g.source, target, skip),
                      fm::drrLineIntegral(*wide, g.source, target, skip));
    }
}

// Mu: the int16 store integrates (mu_water / 1000)(HU + 1000) with one multiplication per ray,
// where the float store rounds every voxel's mu to float first. Against the long-double Siddon
// reference, int16 is as close as float or closer; the two differ by float rounding only.
TEST(DrrVoxelType, MuImagesAreAtLeastAsCloseToTheReferenceAsFloat) {
    const fm::Volume volume = integerCt(11);
    const fm::DrrValueOptions mu = options(fm::DrrValues::Mu);
    const fm::DrrVolumePtr small = fm::prepareDrrVolume(volume, mu);
    const fm::DrrVolumePtr wide = fm::prepareDrrVolume(volume, options(fm::DrrValues::Mu, false));
    ASSERT_EQ(fm::drrVolumeInfo(*small).voxelType, fm::DrrVoxelType::Int16);
    for (double azimuth : {15.0, 120.0}) {
        const fm::ProjectionGeometry g =
            fm::test::orbitGeometry(volume.center(), azimuth, -35.0, 180.0, 120.0, 31, 1.3);
        const fm::Image a = fm::renderDrr(*small, g, {}), b = fm::renderDrr(*wide, g, {});
        const fm::Image truth = fm::renderDrrReference(volume, mu, g, fm::DrrOutput::LineIntegral);
        double errSmall = 0.0, errWide = 0.0, apart = 0.0;
        for (std::size_t p = 0; p < a.pixels.size(); ++p) {
            const double t = truth.pixels[p];
            if (t <= 0.0) continue;
            errSmall = std::max(errSmall, std::abs(a.pixels[p] - t) / t);
            errWide = std::max(errWide, std::abs(b.pixels[p] - t) / t);
            apart = std::max(apart, std::abs(double(a.pixels[p]) - b.pixels[p]) / t);
        }
        EXPECT_LE(errSmall, errWide * 1.01 + 1e-9) << "azimuth " << azimuth;
        EXPECT_LT(errSmall, 3e-7);  // a float image's own rounding (6e-8) and a few more ulps
        EXPECT_LT(apart, 5e-7);
        EXPECT_GT(truth.pixels[31 * 15 + 15], 0.0f) << "the volume is in view";
    }
}

// Coarse copies (previews, coarse search levels) are float block means of the values per mm,
// whichever store they come from.
TEST(DrrVoxelType, CoarseningAnInt16VolumeGivesTheFloatVolumesCoarseCopy) {
    const fm::Volume volume = integerCt(5);
    const fm::DrrVolumePtr small = fm::prepareDrrVolume(volume, options(fm::DrrValues::Raw));
    const fm::DrrVolumePtr wide = fm::prepareDrrVolume(volume, options(fm::DrrValues::Raw, false));
    const fm::DrrVolumePtr a = fm::coarsenDrrVolume(*small, 2), b = fm::coarsenDrrVolume(*wide, 2);
    EXPECT_EQ(fm::drrVolumeInfo(*a).voxelType, fm::DrrVoxelType::Float32);
    const fm::ProjectionGeometry g =
        fm::test::orbitGeometry(volume.center(), 70.0, 10.0, 180.0, 120.0, 29, 1.3);
    const fm::Image ia = fm::renderDrr(*a, g, {}), ib = fm::renderDrr(*b, g, {});
    EXPECT_EQ(ia.pixels, ib.pixels);
    // Mu through the scale: the same within float rounding.
    const fm::DrrVolumePtr muSmall = fm::prepareDrrVolume(volume, options(fm::DrrValues::Mu));
    const fm::DrrVolumePtr muWide = fm::prepareDrrVolume(volume, options(fm::DrrValues::Mu, false));
    const fm::Image ma = fm::renderDrr(*fm::coarsenDrrVolume(*muSmall, 3), g, {});
    const fm::Image mb = fm::renderDrr(*fm::coarsenDrrVolume(*muWide, 3), g, {});
    double worst = 0.0;
    for (std::size_t p = 0; p < ma.pixels.size(); ++p)
        if (mb.pixels[p] > 0.0f)
            worst = std::max(worst, std::abs(double(ma.pixels[p]) - mb.pixels[p]) / mb.pixels[p]);
    EXPECT_LT(worst, 5e-7);
    EXPECT_GT(*std::max_element(mb.pixels.begin(), mb.pixels.end()), 0.0f);
}

// Bricks hold stored values: uniform and empty bricks are found in int16 as in float.
TEST(DrrVoxelType, BricksAreClassifiedAlike) {
    fm::Volume volume = fm::test::makeVolume({32, 24, 16}, {1.0, 1.0, 1.0}, -1000.0f);
    for (int k = 0; k < 8; ++k)
        for (int j = 8; j < 16; ++j)
            for (int i = 0; i < 16; ++i) volume.at(i, j, k) = i < 8 ? 400.0f : float(i * 37 % 50);
    for (fm::DrrValues values : {fm::DrrValues::Mu, fm::DrrValues::Raw}) {
        const fm::DrrVolumeInfo a = fm::drrVolumeInfo(*fm::prepareDrrVolume(volume, options(values)));
        const fm::DrrVolumeInfo b =
            fm::drrVolumeInfo(*fm::prepareDrrVolume(volume, options(values, false)));
        EXPECT_EQ(a.voxelType, fm::DrrVoxelType::Int16);
        EXPECT_EQ(a.dims, b.dims);
        EXPECT_EQ(a.bricksEmpty, b.bricksEmpty);
        EXPECT_EQ(a.bricksUniform, b.bricksUniform);
        EXPECT_GE(a.bricksUniform, 1);
    }
}

}  // namespace

#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "core/Error.h"
#include "core/Random.h"
#include "slice/SliceSampler.h"
#include "slice/SliceTestUtil.h"

using namespace fm;
using fm::test::analyticVolume;

namespace {

SliceSetup samplerSetup(int w, int h, double su, double sv, double t = 0.0) {
    SliceSetup s;
    s.pixels = {w, h};
    s.spacingMm = {su, sv};
    s.thicknessMm = t;
    return s;
}

// An oblique, non-isotropic grid: the sampler must work in index space correctly.
glm::dmat3 obliqueDirection() {
    const glm::dmat4 r = glm::rotate(glm::rotate(glm::dmat4(1.0), 0.4, glm::dvec3(0, 0, 1)), -0.3,
                                     glm::dvec3(1, 0, 0));
    return glm::dmat3(r);
}

std::shared_ptr<const Volume> randomVolume(glm::ivec3 dims, std::uint64_t seed) {
    Rng rng(seed);
    return analyticVolume(dims, {1, 1, 1}, {0, 0, 0}, glm::dmat3(1.0),
                          [&](const glm::dvec3&) { return rng.uniform(0, 100); });
}

}  // namespace

TEST(SliceSampler, TrilinearReproducesALinearFunctionToRounding) {
    auto f = [](const glm::dvec3& p) { return 50.0 + 0.7 * p.x - 1.3 * p.y + 0.4 * p.z; };
    auto volume = analyticVolume({20, 24, 18}, {1.5, 1.2, 2.0}, {-10, 5, 3}, obliqueDirection(), f);
    const auto prepared = prepareSliceVolume(volume, false);
    // A small slice around the centre at an oblique pose: inside the voxel-centre hull.
    const SliceGeometry g = sliceGeometry({{1, -2, 1.5}, 37, 21, 13}, samplerSetup(21, 17, 0.6, 0.7),
                                          volume->center());
    const SampledSlice s = sampleSlice(*prepared, g, SliceInterpolation::Trilinear);
    ASSERT_EQ(s.dataPixels(), 21u * 17u);
    for (int r = 0; r < 17; ++r)
        for (int c = 0; c < 21; ++c)
            ASSERT_NEAR(s.image.at(c, r), f(g.pixelCenter(c, r)), 1e-4) << c << "," << r;
}

TEST(SliceSampler, APlaneThroughVoxelCentresReproducesTheVoxels) {
    const glm::ivec3 dims{9, 11, 13};
    auto volume = randomVolume(dims, 3);
    const auto prepared = prepareSliceVolume(volume, true);
    // Zero pose: coronal plane through the centre voxel row j = 5; u = +i, v = -k.
    const SliceGeometry g = sliceGeometry(Pose{}, samplerSetup(15, 17, 1, 1), volume->center());
    for (SliceInterpolation interp : {SliceInterpolation::Trilinear, SliceInterpolation::CubicBSpline}) {
        const SampledSlice s = sampleSlice(*prepared, g, interp);
        EXPECT_EQ(s.dataPixels(), std::size_t(dims.x * dims.z));
        for (int r = 0; r < 17; ++r)
            for (int c = 0; c < 15; ++c) {
                const int i = c - 3, k = 6 + 8 - r;  // centre pixel (7, 8) is voxel (4, 5, 6)
                const bool inside = i >= 0 && i < dims.x && k >= 0 && k < dims.z;
                ASSERT_EQ(s.mask.at(c, r), inside) << c << "," << r;
                if (inside)
                    ASSERT_NEAR(s.image.at(c, r), volume->at(i, 5, k), 2e-4) << toString(interp);
                else
                    ASSERT_EQ(s.image.at(c, r), 0.0f);
            }
    }
}

TEST(SliceSampler, SeenFromBehindTheSliceIsMirrored) {
    auto volume = randomVolume({12, 10, 14}, 5);
    const auto prepared = prepareSliceVolume(volume, true);
    const SliceSetup st = samplerSetup(19, 23, 0.8, 0.9);
    const Pose a{{0.5, -0.3, 0.7}, 0, 12, 0};
    Pose b = a;
    b.azimuthDeg = 180;
    b.elevationDeg = -12;
    // Azimuth + 180 and elevation negated: the same plane seen from its other side (the same
    // points), u reversed and v unchanged, so the columns are mirrored.
    const SliceGeometry ga = sliceGeometry(a, st, volume->center());
    const SliceGeometry gb = sliceGeometry(b, st, volume->center());
    for (SliceInterpolation interp : {SliceInterpolation::Trilinear, SliceInterpolation::CubicBSpline}) {
        const SampledSlice sa = sampleSlice(*prepared, ga, interp);
        const SampledSlice sb = sampleSlice(*prepared, gb, interp);
        ASSERT_GT(sa.dataPixels(), 100u);
        for (int r = 0; r < 23; ++r)
            for (int c = 0; c < 19; ++c) {
                ASSERT_EQ(sa.mask.at(c, r), sb.mask.at(18 - c, r));
                ASSERT_NEAR(sa.image.at(c, r), sb.image.at(18 - c, r), 1e-4);
            }
    }
}

TEST(SliceSampler, APlaneOnAFaceSamplesTheFaceAndOneBeyondItNothing) {
    const glm::ivec3 dims{5, 6, 7};
    auto volume = randomVolume(dims, 9);
    const auto prepared = prepareSliceVolume(volume, false);
    // Coronal plane on the front face j = -0.5 (the box edge, half a voxel before row 0).
    Pose face;
    face.offset.y = volume->center().y - (volume->origin.y - 0.5);
    const SliceGeometry g = sliceGeometry(face, samplerSetup(9, 11, 1, 1), volume->center());
    const SampledSlice s = sampleSlice(*prepared, g, SliceInterpolation::Trilinear);
    EXPECT_EQ(s.dataPixels(), std::size_t(dims.x * dims.z));
    for (int r = 0; r < 11; ++r)
        for (int c = 0; c < 9; ++c) {
            const int i = c - 2, k = 3 + 5 - r;
            if (i >= 0 && i < dims.x && k >= 0 && k < dims.z) {
                ASSERT_TRUE(s.mask.at(c, r));
                ASSERT_NEAR(s.image.at(c, r), volume->at(i, 0, k), 1e-4);  // the edge voxels
            }
        }
    Pose beyond = face;
    beyond.offset.y += 1e-6;
    const SampledSlice none =
        sampleSlice(*prepared, sliceGeometry(beyond, samplerSetup(9, 11, 1, 1), volume->center()),
                    SliceInterpolation::Trilinear);
    EXPECT_TRUE(none.empty());
}

TEST(SliceSampler, APlaneGrazingAnEdgeSamplesOnlyThatEdge) {
    const glm::ivec3 dims{6, 6, 8};
    auto volume = randomVolume(dims, 11);
    const auto prepared = prepareSliceVolume(volume, false);
    // az = -45: normal (1, 1, 0)/sqrt2, u = (1, -1, 0)/sqrt2, v = -z. The plane through the
    // box edge x = -0.5, y = -0.5 touches the box along that edge only.
    const glm::dvec3 edge = volume->indexToWorld({-0.5, -0.5, 3.5});
    Pose p;
    p.azimuthDeg = -45;
    p.offset = volume->center() - edge;
    const SliceGeometry g = sliceGeometry(p, samplerSetup(7, 12, 1, 1), volume->center());
    const SampledSlice s = sampleSlice(*prepared, g, SliceInterpolation::Trilinear);
    // Column 3 lies on the edge; rows 2..9 fall within z = -0.5 .. 7.5 (8 voxels).
    EXPECT_EQ(s.dataPixels(), 8u);
    for (int r = 0; r < 12; ++r)
        for (int c = 0; c < 7; ++c) {
            const bool onEdge = c == 3 && r >= 2 && r <= 9;
            ASSERT_EQ(s.mask.at(c, r), onEdge) << c << "," << r;
            if (onEdge) {
                ASSERT_NEAR(s.image.at(c, r), volume->at(0, 0, 9 - r), 1e-4);
            }
        }
}

TEST(SliceSampler, APlaneMissingTheVolumeIsFullyMaskedNotNan) {
    auto volume = randomVolume({8, 8, 8}, 13);
    const auto prepared = prepareSliceVolume(volume, true);
    const SliceGeometry g = sliceGeometry({{0, 500, 0}, 10, 20, 30}, samplerSetup(32, 32, 1, 1, 3.0),
                                          volume->center());
    for (SliceInterpolation interp : {SliceInterpolation::Trilinear, SliceInterpolation::CubicBSpline}) {
        const SampledSlice s = sampleSlice(*prepared, g, interp);
        EXPECT_TRUE(s.empty());
        for (float v : s.image.pixels) ASSERT_EQ(v, 0.0f);
    }
}

TEST(SliceSampler, ThicknessAveragesABoxProfileAcrossThePlane) {
    // A slab along y: 100 for rows j = 8..12, 0 elsewhere. The trilinear profile across it is
    // 100 within 2 mm of j = 10, falls linearly to 0 at 3 mm: its mean over [-5, 5] mm is
    // (4 * 100 + 2 * 50) / 10 = 50; the 20 midpoint samples average exactly that.
    auto volume = analyticVolume({6, 21, 6}, {1, 1, 1}, {0, 0, 0}, glm::dmat3(1.0),
                                 [](const glm::dvec3& p) {
                                     return std::abs(p.y - 10.0) <= 2.0 ? 100.0 : 0.0;
                                 });
    const auto prepared = prepareSliceVolume(volume, false);
    const SliceGeometry thin = sliceGeometry(Pose{}, samplerSetup(4, 4, 1, 1, 0.0), volume->center());
    SliceGeometry thick = thin;
    thick.thicknessMm = 10.0;
    const SampledSlice a = sampleSlice(*prepared, thin, SliceInterpolation::Trilinear);
    const SampledSlice b = sampleSlice(*prepared, thick, SliceInterpolation::Trilinear);
    ASSERT_EQ(b.dataPixels(), 16u);
    for (std::size_t i = 0; i < 16; ++i) {
        EXPECT_NEAR(a.image.pixels[i], 100.0f, 1e-4);
        EXPECT_NEAR(b.image.pixels[i], 50.0f, 1e-4);
    }
    // A linear profile averages to its centre value, whatever the thickness.
    auto ramp = analyticVolume({6, 21, 6}, {1, 1, 1}, {0, 0, 0}, glm::dmat3(1.0),
                               [](const glm::dvec3& p) { return 3.0 * p.y; });
    const auto rp = prepareSliceVolume(ramp, false);
    SliceGeometry t6 = thin;
    t6.thicknessMm = 6.0;
    const SampledSlice c = sampleSlice(*rp, t6, SliceInterpolation::Trilinear);
    for (float v : c.image.pixels) EXPECT_NEAR(v, 30.0f, 1e-4);
}

TEST(SliceSampler, ColumnRunsAreExactlyTheColumnsInsideTheBox) {
    Rng rng(17);
    const glm::ivec3 dims{7, 5, 9};
    for (int n = 0; n < 500; ++n) {
        const glm::dvec3 o{rng.uniform(-5, 12), rng.uniform(-5, 10), rng.uniform(-5, 14)};
        const glm::dvec3 step{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
        const ColumnRun run = columnsInBox(o, step, dims, 30);
        for (int c = 0; c < 30; ++c) {
            const glm::dvec3 q = o + double(c) * step;
            bool inside = true;
            for (int a = 0; a < 3; ++a) inside = inside && q[a] >= -0.5 && q[a] <= dims[a] - 0.5;
            ASSERT_EQ(inside, c >= run.first && c <= run.last) << n << " col " << c;
        }
    }
}

TEST(SliceSampler, CubicNeedsPreparedCoefficients) {
    auto volume = randomVolume({4, 4, 4}, 1);
    const auto prepared = prepareSliceVolume(volume, false);
    const SliceGeometry g = sliceGeometry(Pose{}, samplerSetup(4, 4, 1, 1), volume->center());
    EXPECT_THROW(sampleSlice(*prepared, g, SliceInterpolation::CubicBSpline), Error);
    EXPECT_THROW(parseSliceInterpolation("quintic"), Error);
    EXPECT_EQ(parseSliceInterpolation("linear"), SliceInterpolation::Trilinear);
}

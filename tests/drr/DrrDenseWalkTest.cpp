// The dense walk (every voxel, 16 rays at once in AVX-512 or AVX2 lanes where the CPU has them)
// against the scalar plain walk, pixel for pixel and bit for bit, in every form this CPU runs,
// and against the brick-skipping walk.
#include <algorithm>
#include <cstdint>
#include <random>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include "DrrTestUtil.h"
#include "common/TestData.h"
#include "drr/DenseWalk.h"
#include "drr/Drr.h"
#include "geometry/Pose.h"
#include "io/ReadVolume.h"

namespace {

fm::DrrRenderOptions withWalk(fm::DrrExactWalk walk, int threads = 0) {
    fm::DrrRenderOptions o;
    o.walk = walk;
    o.threads = threads;
    return o;
}

// Every pixel of the dense image equals the scalar plain walk of its ray (drrLineIntegral
// without skipping), rounded to float: the vector lanes do the scalar arithmetic exactly, in
// the walk (DenseWalk.h) and in the rays' set-up (DenseRaySetup.h: clipping, first voxel and
// crossings, including rays parallel to an axis and rays on voxel faces).
void expectDenseEqualsScalar(const fm::DrrVolume& v, const fm::ProjectionGeometry& g) {
    fm::Image scalar(g.detector.size.x, g.detector.size.y, 0.0f);
    int nonZero = 0;
    for (int row = 0; row < g.detector.size.y; ++row)
        for (int col = 0; col < g.detector.size.x; ++col) {
            scalar.at(col, row) = static_cast<float>(
                fm::drrLineIntegral(v, g.source, g.detector.pixelCenter(col, row), false));
            if (scalar.at(col, row) != 0.0f) ++nonZero;
        }
    EXPECT_GT(nonZero, g.detector.size.x * g.detector.size.y / 10) << "the volume is in view";
    for (int form = 0; form <= int(fm::denseWalkSimdSupported()); ++form) {
        SCOPED_TRACE("dense walk form " + std::to_string(form) + " (0 scalar, 1 AVX2, 2 AVX-512)");
        const fm::ScopedDenseWalkSimd use(static_cast<fm::DenseWalkSimd>(form));
        const fm::Image dense = fm::renderDrr(v, g, withWalk(fm::DrrExactWalk::Dense));
        int mismatches = 0;
        for (std::size_t i = 0; i < dense.pixels.size(); ++i) mismatches += dense.pixels[i] != scalar.pixels[i];
        EXPECT_EQ(mismatches, 0);
    }
}

// Random values with exact zeros (air), on an oblique anisotropic grid, seen off-axis; the
// detector width (37) leaves partial groups of 16 at the end of every row.
TEST(DrrDenseWalk, EqualsTheScalarWalkBitForBit) {
    fm::Volume volume = fm::test::makeVolume({23, 17, 19}, {1.3, 0.7, 2.1}, 0.0f, {-5.0, 3.0, 2.0},
                                             fm::test::rotation(27.0, {1.0, 2.0, -0.5}));
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> value(-0.5f, 2.0f);
    for (float& x : volume.values) x = rng() % 4 == 0 ? 0.0f : value(rng);
    fm::DrrValueOptions raw;
    raw.values = fm::DrrValues::Raw;
    const fm::DrrVolumePtr v = fm::prepareDrrVolume(volume, raw);
    for (double azimuth : {0.0, 33.0, 90.0, 211.0}) {
        fm::ProjectionGeometry g =
            fm::test::orbitGeometry(volume.center(), azimuth, 17.0, 200.0, 150.0, 37, 1.1);
        g.detector.size.y = 29;
        expectDenseEqualsScalar(*v, g);
    }
}

// The same on int16 voxels (whole numbers, stored in half the bytes: the lanes widen int16, not
// float).
TEST(DrrDenseWalk, EqualsTheScalarWalkBitForBitOnInt16Voxels) {
    fm::Volume volume = fm::test::makeVolume({23, 17, 19}, {1.3, 0.7, 2.1}, 0.0f, {-5.0, 3.0, 2.0},
                                             fm::test::rotation(27.0, {1.0, 2.0, -0.5}));
    std::mt19937 rng(9);
    std::uniform_int_distribution<int> value(-300, 2000);
    for (float& x : volume.values) x = rng() % 4 == 0 ? 0.0f : float(value(rng));
    fm::DrrValueOptions raw;
    raw.values = fm::DrrValues::Raw;
    const fm::DrrVolumePtr v = fm::prepareDrrVolume(volume, raw);
    ASSERT_EQ(fm::drrVolumeInfo(*v).voxelType, fm::DrrVoxelType::Int16);
    for (double azimuth : {0.0, 33.0, 211.0}) {
        fm::ProjectionGeometry g =
            fm::test::orbitGeometry(volume.center(), azimuth, 17.0, 200.0, 150.0, 37, 1.1);
        g.detector.size.y = 29;
        expectDenseEqualsScalar(*v, g);
    }
}

// Volumes past kDenseWalkPrefetchFromBytes, float and int16: there the walk runs a shadow of
// every group ahead to prefetch its voxels (DenseWalkAvx512.cpp), which must not change a bit.
// Views near x (lanes in different rows), near z (lanes sharing cache lines) and oblique.
TEST(DrrDenseWalk, EqualsTheScalarWalkBitForBitOnVolumesLargeEnoughToPrefetch) {
    for (bool int16 : {false, true}) {
        SCOPED_TRACE(int16 ? "int16" : "float");
        const glm::ivec3 dims = int16 ? glm::ivec3{256, 240, 150} : glm::ivec3{200, 180, 130};
        fm::Volume volume = fm::test::makeVolume(dims, {0.9, 0.8, 1.3}, 0.0f, {2.0, -1.0, 3.0},
                                                 fm::test::rotation(11.0, {0.3, 1.0, 0.2}));
        std::mt19937 rng(int16 ? 13 : 12);
        std::uniform_int_distribution<int> value(-1000, 2000);
        for (float& x : volume.values)
            x = int16 ? float(value(rng)) : float(value(rng)) * 0.37f + 0.01f;
        fm::DrrValueOptions raw;
        raw.values = fm::DrrValues::Raw;
        const fm::DrrVolumePtr v = fm::prepareDrrVolume(volume, raw);
        const fm::DrrVolumeInfo info = fm::drrVolumeInfo(*v);
        ASSERT_EQ(info.voxelType, int16 ? fm::DrrVoxelType::Int16 : fm::DrrVoxelType::Float32);
        ASSERT_TRUE(fm::denseWalkPrefetches(info.voxelBytes)) << info.voxelBytes << " bytes";
        for (auto [azimuth, elevation] : {std::pair{0.0, 0.0}, {0.0, 90.0}, {33.0, 17.0}}) {
            fm::ProjectionGeometry g = fm::test::orbitGeometry(volume.center(), azimuth,
                                                               elevation, 400.0, 300.0, 37, 7.0);
            g.detector.size.y = 29;
            expectDenseEqualsScalar(*v, g);
        }
    }
}

// Axis-aligned grid and views along the axes: central rays parallel to two axes, rays on
// voxel faces and through edges (ties between axes), where the lanes' masks must choose as the
// scalar walk does.
TEST(DrrDenseWalk, EqualsTheScalarWalkOnAxisAlignedRays) {
    fm::Volume volume = fm::test::makeVolume({16, 12, 10}, {1.0, 1.0, 1.0}, 0.0f, {0.5, 0.5, 0.5});
    for (std::size_t n = 0; n < volume.values.size(); ++n)
        volume.values[n] = float((n * 7919) % 11) * 0.5f;
    fm::DrrValueOptions raw;
    raw.values = fm::DrrValues::Raw;
    const fm::DrrVolumePtr v = fm::prepareDrrVolume(volume, raw);
    for (auto [azimuth, elevation] : {std::pair{0.0, 0.0}, {90.0, 0.0}, {0.0, 90.0}, {45.0, 0.0}})
        expectDenseEqualsScalar(*v, fm::test::orbitGeometry({8.0, 6.0, 5.0}, azimuth, elevation,
                                                            100.0, 100.0, 33, 1.0));
}

TEST(DrrDenseWalk, EqualsTheScalarWalkOnARealCt) {
    FM_REQUIRE_SHARED_DATA("totalseg-example-ct/example_ct.nii.gz");
    const fm::Volume ct =
        fm::readVolume(fm::test::sharedDataDir() / "totalseg-example-ct/example_ct.nii.gz");
    const fm::DrrVolumePtr v = fm::prepareDrrVolume(ct, {});
    fm::SceneSetup setup = fm::defaultSceneSetup();
    setup.filmPixels = {61, 47};
    fm::Pose pose;
    pose.azimuthDeg = 20.0;
    pose.elevationDeg = 10.0;
    expectDenseEqualsScalar(*v, fm::sceneGeometry(pose, setup, ct.center()));
    // Air noise above -1000 HU: nearly every brick is mixed, so Auto walks densely (in vector lanes).
    EXPECT_GT(fm::drrVolumeInfo(*v).bricksTotal - fm::drrVolumeInfo(*v).bricksEmpty -
                  fm::drrVolumeInfo(*v).bricksUniform,
              fm::drrVolumeInfo(*v).bricksTotal * 9 / 10);
}

// The dense and the brick walk visit the same segments; uniform bricks are summed as one
// product, so the sums differ by rounding only.
TEST(DrrDenseWalk, AgreesWithTheBrickWalk) {
    FM_REQUIRE_SHARED_DATA("totalseg-example-ct/example_ct.nii.gz");
    const fm::Volume ct =
        fm::readVolume(fm::test::sharedDataDir() / "totalseg-example-ct/example_ct.nii.gz");
    fm::DrrValueOptions bone;
    bone.thresholdHU = 200.0;  // mostly empty bricks: the brick walk skips a lot
    for (const fm::DrrValueOptions& values : {fm::DrrValueOptions{}, bone}) {
        const fm::DrrVolumePtr v = fm::prepareDrrVolume(ct, values);
        const fm::ProjectionGeometry g =
            fm::test::orbitGeometry(ct.center(), 40.0, -25.0, 600.0, 400.0, 53, 2.3);
        const fm::Image dense = fm::renderDrr(*v, g, withWalk(fm::DrrExactWalk::Dense));
        const fm::Image bricks = fm::renderDrr(*v, g, withWalk(fm::DrrExactWalk::Bricks));
        const double peak = fm::test::maxAbs(bricks);
        EXPECT_GT(peak, 0.1);
        EXPECT_LE(fm::test::maxAbsDifference(dense, bricks), 1e-6 * peak);
    }
}

// A bone cropped from a CT: values in a ball (and one speck), zeros around it. The dense walk
// walks each ray only where its tile of pixels can meet a non-empty brick (BrickDepthTiles.h):
// every pixel within rounding of the walk over the whole box, exactly 0 where that walk gives 0,
// and the same pixels for any thread count.
TEST(DrrDenseWalk, SkipsEmptyBricksWithinRounding) {
    fm::Volume volume = fm::test::makeVolume({48, 40, 44}, {0.8, 0.9, 1.25}, 0.0f, {2.0, -1.0, 4.0},
                                             fm::test::rotation(19.0, {0.3, 1.0, 0.2}));
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> value(0.1f, 2.0f);
    for (int k = 0; k < 44; ++k)
        for (int j = 0; j < 40; ++j)
            for (int i = 0; i < 48; ++i) {
                const double x = (i - 23.5) / 14.0, y = (j - 19.5) / 11.0, z = (k - 21.5) / 9.0;
                if (x * x + y * y + z * z < 1.0 || (i == 45 && j == 3 && k == 40))
                    volume.values[i + 48 * (j + 40 * std::size_t(k))] = value(rng);
            }
    fm::DrrValueOptions raw;
    raw.values = fm::DrrValues::Raw;
    const fm::DrrVolumePtr v = fm::prepareDrrVolume(volume, raw);
    ASSERT_GT(fm::drrVolumeInfo(*v).bricksEmpty, fm::drrVolumeInfo(*v).bricksTotal / 5);
    int nonZero = 0, zero = 0;
    for (double azimuth : {0.0, 37.0, 90.0, 160.0, 250.0}) {
        const fm::ProjectionGeometry g =
            fm::test::orbitGeometry(volume.center(), azimuth, 23.0, 180.0, 120.0, 83, 0.8);
        const fm::Image image = fm::renderDrr(*v, g, withWalk(fm::DrrExactWalk::Dense, 1));
        EXPECT_EQ(image.pixels, fm::renderDrr(*v, g, withWalk(fm::DrrExactWalk::Dense, 2)).pixels);
        for (int row = 0; row < g.detector.size.y; ++row)
            for (int col = 0; col < g.detector.size.x; ++col) {
                const double whole =
                    fm::drrLineIntegral(*v, g.source, g.detector.pixelCenter(col, row), false);
                const float pixel = image.at(col, row);
                if (whole == 0.0) {
                    ASSERT_EQ(pixel, 0.0f) << col << "," << row;
                    ++zero;
                } else {
                    ASSERT_NEAR(pixel, whole, 1e-6 * whole) << col << "," << row;  // float pixels
                    ++nonZero;
                }
            }
    }
    EXPECT_GT(nonZero, 3000);  // the ball is in view
    EXPECT_GT(zero, 3000);     // and rays pass beside it
}

TEST(DrrDenseWalk, ThreadCountDoesNotChangeAPixel) {
    fm::Volume volume = fm::test::makeVolume({31, 29, 27}, {1.0, 1.0, 1.5}, 1.0f);
    for (std::size_t n = 0; n < volume.values.size(); ++n)
        volume.values[n] = float(n % 13) * 0.25f;
    fm::DrrValueOptions raw;
    raw.values = fm::DrrValues::Raw;
    const fm::DrrVolumePtr v = fm::prepareDrrVolume(volume, raw);
    const fm::ProjectionGeometry g =
        fm::test::orbitGeometry(volume.center(), 12.0, 34.0, 150.0, 100.0, 45, 1.0);
    const fm::Image one = fm::renderDrr(*v, g, withWalk(fm::DrrExactWalk::Dense, 1));
    for (int threads : {2, 3}) {
        const fm::Image many = fm::renderDrr(*v, g, withWalk(fm::DrrExactWalk::Dense, threads));
        EXPECT_EQ(one.pixels, many.pixels) << threads << " threads";
    }
}

}  // namespace

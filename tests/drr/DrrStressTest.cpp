// Stress cases of the exact traversal: rays on faces, edges and corners, parallel to axes, at
// 1e-6..1e-12 mm from a face, sources inside, films through the volume, far misses, poles of
// the pose sphere; skipping against plain traversal; threads and determinism.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "DrrTestUtil.h"
#include "core/Error.h"
#include "drr/Drr.h"
#include "geometry/Pose.h"
#include "phantom/AnalyticObjects.h"

namespace {

using fm::test::makeVolume;
using fm::test::slabChord;

// Exact traversal in double against analytic sums of a few dozen terms: ~1e-15 relative
// rounding per term; 1e-9 is the bound for exact paths.
constexpr double kExactRelTol = 1e-9;
// Skipping vs plain traversal: same segments, different summation order (a uniform brick is
// one product instead of a sum over its voxels; a brick restart re-derives indices by floor):
// differences of a few ulps of the running sum, far below 1e-12 relative.
constexpr double kSummationOrderRelTol = 1e-12;
// The prepared volume stores mu as float (rounded by at most 2^-24 = 6e-8 relative per voxel);
// all mu >= 0, so the integral moves by at most that fraction against the double reference.
constexpr double kFloatValueRelTol = 1.2e-7;
// Images are float: one rounding of the double result (2^-24 relative) with margin.
constexpr double kFloatRelTol = 3e-7;

fm::DrrValueOptions rawValues(int brickSize = 4) {
    fm::DrrValueOptions o;
    o.values = fm::DrrValues::Raw;
    o.brickSize = brickSize;
    return o;
}

// value(i, j, k) = 1 + i + 10 j + 100 k: every voxel distinct, so the wrong voxel shows.
fm::Volume distinctVolume(glm::ivec3 dims, glm::dvec3 spacing) {
    fm::Volume v = makeVolume(dims, spacing);
    for (int k = 0; k < dims.z; ++k)
        for (int j = 0; j < dims.y; ++j)
            for (int i = 0; i < dims.x; ++i) v.at(i, j, k) = float(1 + i + 10 * j + 100 * k);
    return v;
}

// Exact truth for any ray through a small volume: the sum over voxels of value times the
// chord through that voxel's box (slab method in long double, half-open like the renderer).
double voxelSumTruth(const fm::Volume& v, glm::dvec3 source, glm::dvec3 target) {
    long double sum = 0;
    for (int k = 0; k < v.dims.z; ++k)
        for (int j = 0; j < v.dims.y; ++j)
            for (int i = 0; i < v.dims.x; ++i)
                sum += v.at(i, j, k) * slabChord(v, source, target, {i, j, k}, {i, j, k});
    return static_cast<double>(sum);
}

void expectExact(double actual, double truth, const std::string& what) {
    EXPECT_NEAR(actual, truth, kExactRelTol * std::max(1.0, std::abs(truth))) << what;
}

// Fast (skipping and plain) and reference line integrals all equal `truth`.
void expectAllPaths(const fm::Volume& volume, glm::dvec3 s, glm::dvec3 t, double truth,
                    const std::string& what) {
    const auto options = rawValues();
    const auto prepared = fm::prepareDrrVolume(volume, options);
    expectExact(fm::drrLineIntegral(*prepared, s, t, true), truth, what + " (skipping)");
    expectExact(fm::drrLineIntegral(*prepared, s, t, false), truth, what + " (plain)");
    expectExact(fm::drrReferenceLineIntegral(volume, options, s, t), truth, what + " (reference)");
}

TEST(DrrStress, RayParallelToAxisOnInnerFaceTakesTheHigherVoxel) {
    // Voxel j spans [(j - 0.5) s, (j + 0.5) s): half-open, so a ray exactly on the face between
    // j = 1 and j = 2 integrates row j = 2 (documented convention, same in the reference).
    const glm::dvec3 s(1.5, 2.0, 0.75);
    const fm::Volume v = distinctVolume({5, 4, 3}, s);
    auto rowSum = [&](int j, int k) {
        double sum = 0;
        for (int i = 0; i < 5; ++i) sum += v.at(i, j, k) * s.x;
        return sum;
    };
    const double y = 1.5 * s.y, z = 2 * s.z;  // inner y face, k = 2 centre
    expectAllPaths(v, {-100, y, z}, {100, y, z}, rowSum(2, 2), "inner face");
    expectAllPaths(v, {100, y, z}, {-100, y, z}, rowSum(2, 2), "inner face, reversed");
    // Along an edge of four voxels (y face and z face at once): voxel (., 2, 2) again.
    const double zEdge = 1.5 * s.z;
    expectAllPaths(v, {-100, y, zEdge}, {100, y, zEdge}, rowSum(2, 2), "inner edge");
    // Outer faces: the low face belongs to the box, the high face does not.
    expectAllPaths(v, {-100, -0.5 * s.y, z}, {100, -0.5 * s.y, z}, rowSum(0, 2), "low face");
    expectAllPaths(v, {-100, 3.5 * s.y, z}, {100, 3.5 * s.y, z}, 0.0, "high face");
    // Parallel to the y-z plane but oblique in it: through the centres of column i = 2, and
    // exactly on the face between columns 1 and 2 (half-open: column 2 again).
    for (double x : {2 * s.x, 1.5 * s.x}) {
        const glm::dvec3 a(x, -3.0, -2.0), b(x, 11.0, 4.0);
        const double truth = voxelSumTruth(v, a, b);
        EXPECT_GT(truth, 100.0);
        expectAllPaths(v, a, b, truth, "in a plane x = " + std::to_string(x));
    }
}

TEST(DrrStress, RandomRaysMatchPerVoxelChordSums) {
    // Every voxel distinct, oblique and anisotropic grid: the fast paths and the reference
    // against the sum of value x per-voxel chord (independent of any traversal).
    fm::Volume v = distinctVolume({6, 5, 4}, {1.3, 0.7, 2.2});
    v.origin = {4.0, -3.0, 2.0};
    v.direction = fm::test::rotation(-57, {0.2, 1.0, 0.4});
    std::mt19937 rng(21);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    int hits = 0;
    for (int n = 0; n < 400; ++n) {
        const glm::dvec3 a = v.center() + 30.0 * glm::dvec3(unit(rng), unit(rng), unit(rng));
        const glm::dvec3 b =
            v.center() + (n % 4 == 0 ? 1.5 : 4.0) * glm::dvec3(unit(rng), unit(rng), unit(rng));
        const double truth = voxelSumTruth(v, a, b);
        if (truth > 0) ++hits;
        expectAllPaths(v, a, b, truth, "ray " + std::to_string(n));
    }
    EXPECT_GT(hits, 200);
}

TEST(DrrStress, TinyAndThinVolumes) {
    // One voxel, one row, one slice: bricks larger than the volume, partial last bricks.
    std::mt19937 rng(8);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (glm::ivec3 dims :
         {glm::ivec3(1, 1, 1), glm::ivec3(1, 9, 1), glm::ivec3(7, 1, 5), glm::ivec3(2, 3, 17)}) {
        const fm::Volume v = distinctVolume(dims, {0.9, 1.4, 0.6});
        for (int n = 0; n < 100; ++n) {
            const glm::dvec3 a = v.center() + 20.0 * glm::dvec3(unit(rng), unit(rng), unit(rng));
            const glm::dvec3 b = v.center() + 2.0 * glm::dvec3(unit(rng), unit(rng), unit(rng));
            expectAllPaths(v, a, b, voxelSumTruth(v, a, b), "tiny volume ray " + std::to_string(n));
        }
    }
}

TEST(DrrStress, DiagonalThroughVoxelCornersVisitsTheDiagonalVoxels) {
    // The box diagonal passes exactly through the shared corners of voxels (i, i, i): every
    // step is a three-way tie. Each of those voxels holds |diagonal| / n of the ray.
    const glm::dvec3 s(1.0, 1.25, 0.5);
    const int n = 6;
    const fm::Volume v = distinctVolume({n, n, n}, s);
    const glm::dvec3 lo = -0.5 * s, hi = (n - 0.5) * s;
    const glm::dvec3 diag = hi - lo;
    double truth = 0;
    for (int i = 0; i < n; ++i) truth += v.at(i, i, i) * glm::length(diag) / n;
    expectAllPaths(v, lo - 3.0 * diag, hi + 2.0 * diag, truth, "diagonal");
    expectAllPaths(v, hi + 2.0 * diag, lo - 3.0 * diag, truth, "diagonal reversed");
    // Through one outer corner only, grazing: the chord is a single point (length 0).
    expectAllPaths(v, lo + glm::dvec3(-10, 10, 0), lo + glm::dvec3(10, -10, 0), 0.0,
                   "corner graze");
}

TEST(DrrStress, RaysAtTinyDistancesFromAFace) {
    const glm::dvec3 s(1.0, 2.0, 1.5);
    const fm::Volume ones = makeVolume({7, 5, 4}, s, 1.0f);
    const double full = 7 * s.x;
    const double z = 1.0;
    for (double eps = 1e-6; eps >= 1e-12; eps /= 10) {
        const std::string tag = " eps " + std::to_string(eps);
        const double yLow = -0.5 * s.y, yHigh = 4.5 * s.y;
        expectAllPaths(ones, {-50, yLow + eps, z}, {50, yLow + eps, z}, full, "inside low" + tag);
        expectAllPaths(ones, {-50, yLow - eps, z}, {50, yLow - eps, z}, 0.0, "outside low" + tag);
        expectAllPaths(ones, {-50, yHigh - eps, z}, {50, yHigh - eps, z}, full,
                       "inside high" + tag);
        expectAllPaths(ones, {-50, yHigh + eps, z}, {50, yHigh + eps, z}, 0.0,
                       "outside high" + tag);
        // Slightly tilted rays that enter the box within eps of the face.
        const glm::dvec3 a(-50, yLow - eps, z), b(50, yLow + eps, z);
        expectAllPaths(ones, a, b, static_cast<double>(slabChord(ones, a, b)), "tilted" + tag);
    }
}

TEST(DrrStress, SourceInsideAndFilmThroughTheVolume) {
    const glm::dvec3 s(1.0, 1.0, 2.0);
    const fm::Volume ones = makeVolume({10, 10, 10}, s, 1.0f);
    const glm::dvec3 center = ones.center();  // (4.5, 4.5, 9)
    // From the centre out along +x: 5 mm to the face at x = 9.5.
    expectAllPaths(ones, center, center + glm::dvec3(100, 0, 0), 5.0, "source at centre");
    // Pixel inside the box: only the part up to the pixel counts.
    expectAllPaths(ones, center + glm::dvec3(-100, 0, 0), center + glm::dvec3(1.25, 0, 0),
                   4.5 + 0.5 + 1.25, "film inside");
    // Source and pixel both inside.
    expectAllPaths(ones, center, center + glm::dvec3(0, 0, 3.0), 3.0, "both inside");
    // A full image with the source inside: every pixel finite, and the exact chord.
    const auto prepared = fm::prepareDrrVolume(ones, rawValues());
    const fm::ProjectionGeometry g = fm::test::orbitGeometry(center, 10, 20, 2.0, 40.0, 24, 2.0);
    const fm::Image image = fm::renderDrr(*prepared, g, {});
    for (int r = 0; r < image.height; ++r)
        for (int c = 0; c < image.width; ++c) {
            const double truth =
                static_cast<double>(slabChord(ones, g.source, g.detector.pixelCenter(c, r)));
            ASSERT_NEAR(image.at(c, r), truth, kExactRelTol + kFloatRelTol * truth);
        }
}

TEST(DrrStress, FarOffsetsGiveExactZerosNeverNaN) {
    const fm::Volume v = distinctVolume({8, 8, 8}, {1, 1, 1});
    const auto prepared = fm::prepareDrrVolume(v, rawValues());
    for (double far : {1e3, 1e6, 1e9, 1e12}) {
        fm::ProjectionGeometry g = fm::test::orbitGeometry(v.center(), 30, 10, 500, 500, 16, 1.0);
        g.detector.origin += glm::dvec3(far, -far, far);  // film swung far to the side
        fm::DrrRenderOptions line, intensity;
        intensity.output = fm::DrrOutput::Intensity;
        const fm::Image a = fm::renderDrr(*prepared, g, line);
        const fm::Image b = fm::renderDrr(*prepared, g, intensity);
        for (float p : a.pixels) ASSERT_EQ(p, 0.0f) << far;  // a miss is structurally zero
        for (float p : b.pixels) ASSERT_EQ(p, 1.0f) << far;  // exp(-0)
        // The source far away too (but not in the film plane).
        g.source += glm::dvec3(-far, far, 2 * far);
        EXPECT_TRUE(fm::test::allFinite(fm::renderDrr(*prepared, g, line)));
    }
}

// The DRR of a volume that is zero except for the voxel block [lo, hi] is the chord through
// that block: the block shows where it is and nowhere else (no wrap-around).
void expectBlockOnlyWhereItIs(glm::ivec3 lo, glm::ivec3 hi, bool crop) {
    const glm::ivec3 dims(10, 9, 11);
    fm::Volume v =
        makeVolume(dims, {1.0, 1.5, 1.25}, 0.0f, {3, -2, 7}, fm::test::rotation(15, {1, 0, 1}));
    for (int k = lo.z; k <= hi.z; ++k)
        for (int j = lo.y; j <= hi.y; ++j)
            for (int i = lo.x; i <= hi.x; ++i) v.at(i, j, k) = 1.0f;
    auto options = rawValues();
    options.cropToContent = crop;
    const auto prepared = fm::prepareDrrVolume(v, options);
    int lit = 0;
    for (double az : {0.0, 90.0, 37.0}) {
        const fm::ProjectionGeometry g =
            fm::test::orbitGeometry(v.center(), az, 25, 80, 60, 48, 0.75);
        const fm::Image image = fm::renderDrr(*prepared, g, {});
        for (int r = 0; r < image.height; ++r)
            for (int c = 0; c < image.width; ++c) {
                const double truth = static_cast<double>(
                    slabChord(v, g.source, g.detector.pixelCenter(c, r), lo, hi));
                if (truth == 0.0) {
                    ASSERT_EQ(image.at(c, r), 0.0f) << "lit outside the block at " << c << "," << r;
                } else {
                    ++lit;
                    ASSERT_NEAR(image.at(c, r), truth, kExactRelTol + kFloatRelTol * truth);
                }
            }
    }
    EXPECT_GT(lit, 20);
}

TEST(DrrStress, LastSliceAppearsOnlyWhereItIs) {
    for (bool crop : {true, false}) {
        expectBlockOnlyWhereItIs({0, 0, 10}, {9, 8, 10}, crop);  // last k slice
        expectBlockOnlyWhereItIs({0, 0, 0}, {9, 8, 0}, crop);    // first k slice
        expectBlockOnlyWhereItIs({9, 0, 0}, {9, 8, 10}, crop);   // last i slice
        expectBlockOnlyWhereItIs({9, 8, 10}, {9, 8, 10}, crop);  // the far corner voxel
    }
}

// A CT-like HU volume: air, a noisy soft-tissue ellipsoid, a bone block and a few NaN voxels.
fm::Volume ctLikeVolume(glm::dmat3 direction = glm::dmat3(1.0)) {
    fm::Volume v = makeVolume({40, 34, 30}, {1.2, 0.9, 1.6}, -1000.0f, {-20, 10, 5}, direction);
    std::mt19937 rng(7);
    std::normal_distribution<float> noise(0.0f, 20.0f);
    for (int k = 0; k < 30; ++k)
        for (int j = 0; j < 34; ++j)
            for (int i = 0; i < 40; ++i) {
                const glm::dvec3 p((i - 20) / 14.0, (j - 17) / 12.0, (k - 14) / 12.0);
                if (glm::dot(p, p) < 1.0) v.at(i, j, k) = 40.0f + noise(rng);
                if (i >= 16 && i < 24 && j >= 12 && j < 20 && k >= 5 && k < 25)
                    v.at(i, j, k) = 900.0f + 10 * noise(rng);
            }
    v.at(0, 0, 0) = std::nanf("");
    return v;
}

TEST(DrrStress, SkippingPathsEqualPlainTraversal) {
    const fm::Volume ct = ctLikeVolume(fm::test::rotation(-25, {0.3, 1, 0.2}));
    std::mt19937 rng(99);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (std::optional<double> threshold :
         {std::optional<double>(), std::optional<double>(300.0)}) {
        for (int brick : {1, 3, 4, 8, 64}) {  // 3: not a power of two (no shift)
            fm::DrrValueOptions skip;
            skip.thresholdHU = threshold;
            skip.brickSize = brick;
            fm::DrrValueOptions plain = skip;
            plain.cropToContent = false;
            const auto a = fm::prepareDrrVolume(ct, skip);
            const auto b = fm::prepareDrrVolume(ct, plain);
            const fm::DrrVolumeInfo info = fm::drrVolumeInfo(*a);
            if (threshold && brick == 4) {
                // Only the bone block survives the threshold: the crop is exactly that block.
                EXPECT_EQ(info.cropBegin, glm::ivec3(16, 12, 5));
                EXPECT_EQ(info.dims, glm::ivec3(8, 8, 20));
            }
            for (int n = 0; n < 400; ++n) {
                const glm::dvec3 s =
                    ct.center() + 150.0 * glm::dvec3(unit(rng), unit(rng), unit(rng));
                const glm::dvec3 t =
                    ct.center() + 40.0 * glm::dvec3(unit(rng), unit(rng), unit(rng));
                const double plainValue = fm::drrLineIntegral(*b, s, t, false);
                const double tol = kSummationOrderRelTol * std::max(1.0, std::abs(plainValue));
                ASSERT_NEAR(fm::drrLineIntegral(*a, s, t, true), plainValue, tol)
                    << brick << " " << n;
                ASSERT_NEAR(fm::drrLineIntegral(*b, s, t, true), plainValue, tol)
                    << brick << " " << n;
                ASSERT_NEAR(fm::drrLineIntegral(*a, s, t, false), plainValue, tol)
                    << brick << " " << n;
                // And the independent reference (long double Siddon 1985).
                ASSERT_NEAR(fm::drrReferenceLineIntegral(ct, skip, s, t), plainValue,
                            1e-12 + kFloatValueRelTol * std::abs(plainValue))
                    << brick << " " << n;
            }
            // Whole images: projected box and bricks against every pixel traced plainly.
            const fm::ProjectionGeometry g =
                fm::test::orbitGeometry(ct.center(), 60, -30, 300, 200, 40, 3.0);
            fm::DrrRenderOptions fast, slow;
            slow.skipEmptySpace = false;
            const fm::Image fa = fm::renderDrr(*a, g, fast), sb = fm::renderDrr(*b, g, slow);
            EXPECT_LE(fm::test::maxAbsDifference(fa, sb), kFloatRelTol * fm::test::maxAbs(sb));
            EXPECT_GT(fm::test::maxAbs(sb), 0.0);
        }
    }
}

TEST(DrrStress, ThreadCountDoesNotChangeAPixel) {
    // Each pixel is computed by the same sequential code whatever thread runs its row chunk,
    // so the images are bit-identical by construction (stronger than "a given thread count").
    const fm::Volume ct = ctLikeVolume();
    const auto prepared = fm::prepareDrrVolume(ct, {});
    const fm::ProjectionGeometry g = fm::test::orbitGeometry(ct.center(), 10, 5, 400, 300, 64, 2.0);
    for (fm::DrrExactWalk walk : {fm::DrrExactWalk::Bricks, fm::DrrExactWalk::Dense}) {
        fm::DrrRenderOptions o;
        o.walk = walk;
        o.threads = 1;
        const fm::Image one = fm::renderDrr(*prepared, g, o);
        o.threads = 2;
        const fm::Image two = fm::renderDrr(*prepared, g, o);
        const fm::Image twoAgain = fm::renderDrr(*prepared, g, o);
        o.threads = 3;
        const fm::Image three = fm::renderDrr(*prepared, g, o);
        EXPECT_EQ(one.pixels, two.pixels);
        EXPECT_EQ(two.pixels, twoAgain.pixels);
        EXPECT_EQ(one.pixels, three.pixels);
        EXPECT_GT(fm::test::maxAbs(one), 0.1);
    }
}

TEST(DrrStress, PreparationThreadCountDoesNotChangeAPixel) {
    // Preparation runs per slice in parallel (conversion, downsampling, crop box, bricks):
    // the prepared volume, and so every pixel, must be the same for any thread count.
    const fm::Volume ct = ctLikeVolume(fm::test::rotation(10, {0, 0.2, 1}));
    const fm::ProjectionGeometry g =
        fm::test::orbitGeometry(ct.center(), 25, -10, 400, 300, 48, 2.0);
    for (int downsample : {1, 3}) {
        for (std::optional<double> threshold :
             {std::optional<double>(), std::optional<double>(300.0)}) {
            fm::DrrValueOptions v;
            v.downsample = downsample;
            v.thresholdHU = threshold;
            v.threads = 1;
            const auto one = fm::prepareDrrVolume(ct, v);
            const fm::Image reference = fm::renderDrr(*one, g, {});
            EXPECT_GT(fm::test::maxAbs(reference), 0.01);
            for (int threads : {2, 3, 7}) {
                v.threads = threads;
                const auto many = fm::prepareDrrVolume(ct, v);
                const fm::DrrVolumeInfo a = fm::drrVolumeInfo(*one), b = fm::drrVolumeInfo(*many);
                EXPECT_EQ(a.dims, b.dims);
                EXPECT_EQ(a.cropBegin, b.cropBegin);
                EXPECT_EQ(a.bricksEmpty, b.bricksEmpty);
                EXPECT_EQ(a.bricksUniform, b.bricksUniform);
                EXPECT_EQ(reference.pixels, fm::renderDrr(*many, g, {}).pixels)
                    << threads << " threads, downsample " << downsample;
            }
        }
    }
}

TEST(DrrStress, EveryPixelFiniteInAwkwardGeometries) {
    const fm::Volume ct = ctLikeVolume(fm::test::rotation(90, {0, 0, 1}));
    const auto prepared = fm::prepareDrrVolume(ct, {});
    const glm::dvec3 c = ct.center();
    std::vector<fm::ProjectionGeometry> geometries;
    geometries.push_back(fm::test::orbitGeometry(c, 0, 0, 0.0, 30, 32, 1.0));    // source at centre
    geometries.push_back(fm::test::orbitGeometry(c, 90, 0, 10, 5, 32, 1.0));     // film inside
    geometries.push_back(fm::test::orbitGeometry(c, 0, 90, 500, 500, 32, 4.0));  // pole
    geometries.push_back(fm::test::orbitGeometry(c, 180, -90, 500, 500, 32, 4.0));
    geometries.push_back(fm::test::orbitGeometry(c, 45, 0, 1e7, 1e7, 8, 1e4));  // far, huge pixels
    geometries.push_back(
        fm::test::orbitGeometry(ct.indexToWorld({-0.5, -0.5, -0.5}), 0, 0, 0, 20, 32, 0.5));
    for (const auto& g : geometries)
        for (fm::DrrExactWalk walk : {fm::DrrExactWalk::Bricks, fm::DrrExactWalk::Dense})
            for (fm::DrrOutput output : {fm::DrrOutput::LineIntegral, fm::DrrOutput::Intensity}) {
                fm::DrrRenderOptions o;
                o.walk = walk;
                o.output = output;
                const fm::Image image = fm::renderDrr(*prepared, g, o);
                EXPECT_TRUE(fm::test::allFinite(image));
                for (float p : image.pixels) ASSERT_GE(p, 0.0f);  // mu >= 0: no negative integral
            }
}

TEST(DrrStress, PosesAtThePolesAndTheAzimuthSeamAreContinuous) {
    // sceneGeometry (the 2011 pose) at elevation +-90 and azimuth +-180: neighbouring angles
    // give neighbouring images.
    fm::Volume blob =
        fm::voxelize(fm::EllipsoidShape{{0, 0, 0}, {40, 25, 60}},
                     fm::centeredGrid({48, 32, 64}, {2.0, 2.0, 2.0}), 1.0f, 0.0f, 2, 2);
    blob.values[blob.index(30, 10, 40)] = 3.0f;  // break the symmetry
    const auto prepared = fm::prepareDrrVolume(blob, rawValues(8));
    fm::SceneSetup setup = fm::defaultSceneSetup();
    setup.filmPixels = {64, 64};
    auto render = [&](double az, double el) {
        fm::Pose pose;
        pose.azimuthDeg = az;
        pose.elevationDeg = el;
        const fm::Image image =
            fm::renderDrr(*prepared, fm::sceneGeometry(pose, setup, blob.center()), {});
        EXPECT_TRUE(fm::test::allFinite(image));
        return image;
    };
    // A 1e-4 degree turn moves rays by ~2e-3 mm at the film; the partial-volume object changes
    // by at most ~1 (value) * 2e-3 mm / 2 mm (voxel) per mm of chord, far below 1e-2 of the peak.
    constexpr double kContinuityRelTol = 1e-2;
    // Azimuth -180 and +180 are the same pose: only sin/cos rounding (1e-16) differs.
    constexpr double kSamePoseRelTol = 1e-5;
    for (double el : {90.0, -90.0, 0.0, 45.0}) {
        const fm::Image a = render(180.0, el), b = render(-180.0, el);
        const double peak = fm::test::maxAbs(a);
        EXPECT_GT(peak, 10.0) << el;
        EXPECT_LE(fm::test::maxAbsDifference(a, b), kSamePoseRelTol * peak) << el;
        const fm::Image c = render(180.0 - 1e-4, el);
        EXPECT_LE(fm::test::maxAbsDifference(a, c), kContinuityRelTol * peak) << el;
    }
    for (double el : {90.0, -90.0}) {
        const fm::Image pole = render(30.0, el);
        const fm::Image near = render(30.0, el > 0 ? el - 1e-4 : el + 1e-4);
        EXPECT_LE(fm::test::maxAbsDifference(pole, near),
                  kContinuityRelTol * fm::test::maxAbs(pole));
    }
}

TEST(DrrStress, BadInputsThrowErrors) {
    fm::Volume v = makeVolume({4, 4, 4}, {1, 1, 1}, 1.0f);
    fm::DrrValueOptions bad;
    bad.brickSize = 0;
    EXPECT_THROW(fm::prepareDrrVolume(v, bad), fm::Error);
    bad = {};
    bad.downsample = 0;
    EXPECT_THROW(fm::prepareDrrVolume(v, bad), fm::Error);
    v.values[5] = std::numeric_limits<float>::infinity();
    v.values[60] = -std::numeric_limits<float>::infinity();
    for (int threads : {1, 2, 4}) {  // the message names the first one, whatever the threads
        bad = {};
        bad.threads = threads;
        try {
            fm::prepareDrrVolume(v, bad);
            ADD_FAILURE() << "an infinite voxel was accepted";
        } catch (const fm::Error& e) {
            EXPECT_NE(std::string(e.what()).find("infinite value at voxel 5:"), std::string::npos)
                << e.what();
        }
    }
    v.values[5] = v.values[60] = 1.0f;
    bad = {};
    bad.threads = -1;
    EXPECT_THROW(fm::prepareDrrVolume(v, bad), fm::Error);
    const auto prepared = fm::prepareDrrVolume(v, {});
    fm::ProjectionGeometry g = fm::test::orbitGeometry(v.center(), 0, 0, 100, 100, 8, 1.0);
    g.source.x = std::nan("");
    EXPECT_THROW(fm::renderDrr(*prepared, g, {}), fm::Error);
}

}  // namespace

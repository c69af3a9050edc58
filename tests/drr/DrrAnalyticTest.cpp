// Analytic truths beyond the box of ones: convergence to the line integral of a voxelized
// sphere/ellipsoid, mass conservation of one bright voxel, HU -> mu and thresholds, the same
// object stored LPS and RAS, and a downsampled volume staying close to the exact one.
#include <cmath>
#include <cstdio>
#include <random>

#include <gtest/gtest.h>

#include "DrrTestUtil.h"
#include "drr/Drr.h"
#include "phantom/AnalyticObjects.h"

namespace {

using fm::test::makeVolume;
using fm::test::slabChord;

// Images are float: one rounding of the double result (2^-24 relative) with margin.
constexpr double kFloatRelTol = 3e-7;

fm::DrrValueOptions rawValues() {
    fm::DrrValueOptions o;
    o.values = fm::DrrValues::Raw;
    return o;
}

TEST(DrrValues, HounsfieldToMuFollowsTheDefinition) {
    // Exact arithmetic on the cited constant (NIST XCOM water at 60 keV, 0.2059 cm^2/g).
    constexpr double kTol = 1e-15;
    EXPECT_NEAR(fm::kMuWaterPerMm, 0.02059, kTol);
    EXPECT_NEAR(fm::huToMu(0.0), fm::kMuWaterPerMm, kTol);
    EXPECT_NEAR(fm::huToMu(1000.0), 2.0 * fm::kMuWaterPerMm, kTol);
    EXPECT_NEAR(fm::huToMu(-500.0), 0.5 * fm::kMuWaterPerMm, kTol);
    EXPECT_EQ(fm::huToMu(-1000.0), 0.0);  // air: clamped, exactly zero
    EXPECT_EQ(fm::huToMu(-3024.0), 0.0);  // padding below air
    fm::DrrValueOptions bone;
    bone.thresholdHU = 200.0;
    EXPECT_EQ(fm::drrVoxelValue(199.0, bone), 0.0);
    EXPECT_NEAR(fm::drrVoxelValue(200.0, bone), fm::huToMu(200.0), kTol);
    EXPECT_EQ(fm::drrVoxelValue(std::nan(""), bone), 0.0);
}

TEST(DrrValues, WaterSlabGivesMuTimesChordAndBeerLambert) {
    // Layers along z: air, water, soft bone (500 HU), dense bone (1500 HU).
    fm::Volume v = makeVolume({12, 12, 8}, {1.0, 1.0, 2.5}, -1000.0f);
    const float layerHu[4] = {-1000.0f, 0.0f, 500.0f, 1500.0f};
    for (int k = 0; k < 8; ++k)
        for (int j = 0; j < 12; ++j)
            for (int i = 0; i < 12; ++i) v.at(i, j, k) = layerHu[k / 2];
    const glm::dvec3 s(-30.0, 3.2, 0.0), t(40.0, 8.1, 18.0);  // crosses every layer
    for (std::optional<double> threshold :
         {std::optional<double>(), std::optional<double>(400.0)}) {
        fm::DrrValueOptions o;
        o.thresholdHU = threshold;
        double truth = 0.0;
        for (int layer = 0; layer < 4; ++layer) {
            if (threshold && layerHu[layer] < *threshold) continue;
            const double mu = fm::kMuWaterPerMm * (1.0 + layerHu[layer] / 1000.0);
            const glm::ivec3 lo(0, 0, 2 * layer), hi(11, 11, 2 * layer + 1);
            truth += std::max(0.0, mu) * static_cast<double>(slabChord(v, s, t, lo, hi));
        }
        const auto prepared = fm::prepareDrrVolume(v, o);
        const double value = fm::drrLineIntegral(*prepared, s, t);
        constexpr double kFloatValueRelTol = 1.2e-7;  // mu stored as float (2^-24 relative)
        EXPECT_NEAR(value, truth, kFloatValueRelTol * truth);
        EXPECT_GT(truth, 0.1);
        // A single-pixel "radiograph" through the same ray: exp(-integral).
        fm::ProjectionGeometry g;
        g.source = s;
        g.detector.size = {1, 1};
        g.detector.origin = t;
        const glm::dvec3 axis = glm::normalize(t - s);
        g.detector.u = glm::normalize(glm::cross(axis, glm::dvec3(0, 0, 1)));
        g.detector.v = glm::cross(axis, g.detector.u);
        fm::DrrRenderOptions intensity;
        intensity.output = fm::DrrOutput::Intensity;
        // exp of a value good to 1.2e-7 relative (integral ~1), stored as float (6e-8).
        constexpr double kIntensityTol = 1e-6;
        EXPECT_NEAR(fm::renderDrr(*prepared, g, intensity).at(0, 0), std::exp(-truth),
                    kIntensityTol);
    }
}

TEST(DrrAnalytic, VoxelizedSphereConvergesToItsLineIntegral) {
    // Partial-volume voxelizations of a sphere (radius 20 mm) at 4, 2, 1 and 0.5 mm voxels;
    // rays from a source 400 mm away. The error against the exact chord must shrink at a
    // steady order; the measured order is printed (see docs/drr.md).
    const fm::SphereShape sphere{{1.3, -0.7, 0.4}, 20.0};
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::vector<std::pair<glm::dvec3, glm::dvec3>> rays;
    for (int n = 0; n < 400; ++n) {
        const glm::dvec3 dir = glm::normalize(glm::dvec3(unit(rng), unit(rng), unit(rng)));
        const glm::dvec3 offset =
            19.0 * glm::dvec3(unit(rng), unit(rng), unit(rng)) / std::sqrt(3.0);
        rays.push_back(
            {sphere.center + offset - 400.0 * dir, sphere.center + offset + 300.0 * dir});
    }
    std::vector<double> rms;
    for (double h : {4.0, 2.0, 1.0, 0.5}) {
        const int n = static_cast<int>(std::ceil(44.0 / h));
        const fm::Volume v = fm::voxelize(
            sphere, fm::centeredGrid({n, n, n}, {h, h, h}, sphere.center), 1.0f, 0.0f, 4, 2);
        const auto prepared = fm::prepareDrrVolume(v, rawValues());
        double sum2 = 0.0;
        for (const auto& [s, t] : rays) {
            const double truth = fm::chordLength(sphere, s, t - s, 0.0, 1.0);
            const double e = fm::drrLineIntegral(*prepared, s, t) - truth;
            sum2 += e * e;
        }
        rms.push_back(std::sqrt(sum2 / rays.size()) / (2.0 * sphere.radius));
    }
    for (std::size_t i = 0; i + 1 < rms.size(); ++i) {
        const double order = std::log2(rms[i] / rms[i + 1]);
        std::printf("sphere h=%g -> %g: RMS error/diameter %.3e -> %.3e, order %.2f\n",
                    4.0 / (1 << i), 2.0 / (1 << i), rms[i], rms[i + 1], order);
        // First order is what a piecewise-constant voxelization allows: each ray crosses the
        // partial-volume shell (~h thick) twice, with an O(h) error each (measured 1.06-1.10).
        // A method that does not converge, or converges erratically, fails here.
        EXPECT_GT(order, 0.9);
    }
    // First order means an error of a fraction of a voxel per ray: at 0.5 mm voxels the RMS
    // error must stay below a quarter voxel (0.125 mm) on the 40 mm diameter.
    EXPECT_LT(rms.back(), 0.25 * 0.5 / (2.0 * sphere.radius));
}

TEST(DrrAnalytic, OneBrightVoxelConservesMassAtEveryAngle) {
    // Integral of the DRR over the film = value * voxel volume * (R/r)^2 / cos(theta) for a
    // small object (R: source-film distance along the ray, r: source-object distance, theta:
    // obliquity). For the voxel on the central ray, cos = 1: sum * pixelArea / M^2 = v * V.
    const glm::dvec3 spacing(2.0, 1.5, 2.5);
    fm::Volume v =
        makeVolume({5, 5, 5}, spacing, 0.0f, {-4, -3, -5}, fm::test::rotation(30, {1, 1, 0}));
    v.at(2, 2, 2) = 7.0f;
    const double mass = 7.0 * spacing.x * spacing.y * spacing.z;
    const glm::dvec3 voxel = v.indexToWorld({2, 2, 2});
    const auto prepared = fm::prepareDrrVolume(v, rawValues());
    // Pixels of 0.04 mm against a shadow ~5-10 mm wide: the midpoint rule on a continuous,
    // piecewise-smooth function errs by O((pixel/shadow)^2) ~ 1e-4; the perspective factor
    // varies across the voxel by O((voxel/r)^2) ~ 1e-5. Hence 1e-3.
    constexpr double kMassRelTol = 1e-3;
    constexpr double kPixelMm = 0.04;
    const double sod = 300.0, sdd = 600.0, magnification = sdd / sod;
    for (auto [az, el] :
         {std::pair{0.0, 0.0}, {37.0, 12.0}, {90.0, 45.0}, {-150.0, -70.0}, {10.0, 90.0}}) {
        const fm::ProjectionGeometry g =
            fm::test::orbitGeometry(voxel, az, el, sod, sdd - sod, 500, kPixelMm);
        const fm::Image image = fm::renderDrr(*prepared, g, {});
        double sum = 0.0;
        for (float p : image.pixels) sum += p;
        const double film = sum * kPixelMm * kPixelMm / (magnification * magnification);
        EXPECT_NEAR(film, mass, kMassRelTol * mass) << "az " << az << " el " << el;
        // The shadow lies inside the film (otherwise mass would be lost at the border).
        for (int i = 0; i < 500; ++i) {
            ASSERT_EQ(image.at(i, 0), 0.0f);
            ASSERT_EQ(image.at(0, i), 0.0f);
        }
    }
}

TEST(DrrAnalytic, LpsAndRasStorageOfTheSameObjectGiveTheSameDrr) {
    // One object, stored twice: identity direction (LPS order) and diag(-1,-1,1) (RAS order,
    // arrays flipped in i and j, origin at the other corner). The world is the same.
    const glm::ivec3 dims(14, 11, 9);
    const glm::dvec3 spacing(1.1, 0.8, 1.7);
    fm::Volume lps = makeVolume(dims, spacing, 0.0f, {-5, 3, 2});
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> value(0.0f, 2.0f);
    for (float& x : lps.values) x = value(rng) > 1.2f ? value(rng) : 0.0f;
    fm::Volume ras =
        makeVolume(dims, spacing, 0.0f, lps.indexToWorld(glm::dvec3(dims.x - 1, dims.y - 1, 0)),
                   glm::dmat3(glm::dvec3(-1, 0, 0), glm::dvec3(0, -1, 0), glm::dvec3(0, 0, 1)));
    for (int k = 0; k < dims.z; ++k)
        for (int j = 0; j < dims.y; ++j)
            for (int i = 0; i < dims.x; ++i)
                ras.at(dims.x - 1 - i, dims.y - 1 - j, k) = lps.at(i, j, k);
    constexpr double kSameCentreMm = 1e-12;  // a few ulps of ~10 mm coordinates
    ASSERT_LT(glm::length(ras.center() - lps.center()), kSameCentreMm);
    const auto a = fm::prepareDrrVolume(lps, rawValues());
    const auto b = fm::prepareDrrVolume(ras, rawValues());
    for (double az : {0.0, 33.0, 120.0}) {
        const fm::ProjectionGeometry g =
            fm::test::orbitGeometry(lps.center(), az, 20, 150, 100, 48, 1.0);
        const fm::Image ia = fm::renderDrr(*a, g, {}), ib = fm::renderDrr(*b, g, {});
        const double peak = fm::test::maxAbs(ia);
        EXPECT_GT(peak, 1.0);
        // Same segments mirrored: only the order of the sum differs (a few ulps of double),
        // plus the float rounding of the pixel.
        EXPECT_LE(fm::test::maxAbsDifference(ia, ib), kFloatRelTol * peak) << az;
        // And both equal the independent reference of either storage.
        const fm::Image ref =
            fm::renderDrrReference(ras, rawValues(), g, fm::DrrOutput::LineIntegral);
        EXPECT_LE(fm::test::maxAbsDifference(ia, ref), kFloatRelTol * peak) << az;
    }
}

TEST(DrrAnalytic, ADownsampledVolumeStaysCloseToTheExactDrr) {
    const fm::EllipsoidShape shape{{0, 0, 0}, {30, 20, 25}};
    fm::Volume v =
        fm::voxelize(shape, fm::centeredGrid({40, 30, 34}, {1.6, 1.5, 1.6}), 1.0f, 0.0f, 3, 2);
    const auto prepared = fm::prepareDrrVolume(v, rawValues());
    const fm::ProjectionGeometry g = fm::test::orbitGeometry(v.center(), 25, 15, 400, 300, 64, 2.0);
    const fm::Image exact = fm::renderDrr(*prepared, g, {});
    const double peak = fm::test::maxAbs(exact);
    auto rmsError = [&](const fm::Image& image) {
        double sum2 = 0.0;
        for (std::size_t i = 0; i < image.pixels.size(); ++i)
            sum2 += std::pow(double(image.pixels[i]) - exact.pixels[i], 2);
        return std::sqrt(sum2 / image.pixels.size()) / peak;
    };
    // Downsampled volume, traced exactly: error grows with the factor but stays moderate.
    fm::DrrValueOptions coarse = rawValues();
    coarse.downsample = 2;
    const fm::Image down = fm::renderDrr(*fm::prepareDrrVolume(v, coarse), g, {});
    const double downError = rmsError(down);
    // Halving the resolution of a 1.5 mm partial-volume ellipsoid blurs its rim: a few
    // percent of the peak RMS at most.
    constexpr double kDownsampleRmsBound = 0.05;
    EXPECT_GT(downError, 0.0);
    EXPECT_LT(downError, kDownsampleRmsBound);
    // Downsampling by block means keeps the total mass: the summed film signal stays within 1%.
    double sumExact = 0, sumDown = 0;
    for (std::size_t i = 0; i < exact.pixels.size(); ++i) {
        sumExact += exact.pixels[i];
        sumDown += down.pixels[i];
    }
    // Block means keep the mass exactly except where a partial block sticks out of the grid
    // (its mean is spread over a larger box) and film pixels sample the blur: 1% covers it.
    constexpr double kDownsampleMassRelTol = 0.01;
    EXPECT_NEAR(sumDown, sumExact, kDownsampleMassRelTol * sumExact);
}

TEST(DrrAnalytic, FastImageMatchesTheReferenceRendererOnAnObliqueCt) {
    // Anisotropic, oblique, HU with threshold and mu conversion, cropped and bricked: the
    // whole pipeline against the long-double Siddon (1985) reference on the original grid.
    fm::Volume v = makeVolume({30, 26, 22}, {0.8, 1.3, 2.2}, -1000.0f, {10, -4, 6},
                              fm::test::rotation(41, {2, -1, 1}));
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> hu(-200.0f, 1800.0f);
    for (int k = 4; k < 18; ++k)
        for (int j = 3; j < 20; ++j)
            for (int i = 6; i < 27; ++i) v.at(i, j, k) = hu(rng);
    for (std::optional<double> threshold :
         {std::optional<double>(), std::optional<double>(700.0)}) {
        fm::DrrValueOptions o;
        o.thresholdHU = threshold;
        const auto prepared = fm::prepareDrrVolume(v, o);
        const fm::ProjectionGeometry g =
            fm::test::orbitGeometry(v.center(), -60, 35, 250, 250, 56, 1.5);
        for (fm::DrrOutput output : {fm::DrrOutput::LineIntegral, fm::DrrOutput::Intensity}) {
            fm::DrrRenderOptions ro;
            ro.output = output;
            const fm::Image fast = fm::renderDrr(*prepared, g, ro);
            const fm::Image ref = fm::renderDrrReference(v, o, g, output);
            // float mu storage (1.2e-7) plus float pixels (3e-7).
            constexpr double kFastVsReferenceRelTol = 5e-7;
            EXPECT_LE(fm::test::maxAbsDifference(fast, ref),
                      kFastVsReferenceRelTol * fm::test::maxAbs(ref));
            EXPECT_GT(fm::test::maxAbs(ref), 0.2);
        }
    }
}

}  // namespace

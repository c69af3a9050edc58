// Analytic truth: in a volume of ones the DRR of a ray is the length of its chord through the
// voxel box, computed here independently (slab method in long double, DrrTestUtil.h).
#include <random>

#include <gtest/gtest.h>

#include "DrrTestUtil.h"
#include "drr/Drr.h"

namespace {

using fm::test::makeVolume;
using fm::test::slabChord;

// Siddon in double: each segment is a difference of two crossing parameters, each computed
// with a relative error of a few ulps (1e-16) from the ray's scale. With up to ~100 segments
// and rays up to ~10x the box size, the sum is good to ~1e-13 relative; 1e-9 is the issue's
// bound and leaves margin for the world->local transform of rotated volumes.
constexpr double kChordRelTol = 1e-9;
// Absolute floor for chords that are (nearly) zero: 1e-9 of the typical 10 mm box.
constexpr double kChordAbsTol = 1e-8;

double tolerance(double truth) {
    return kChordAbsTol + kChordRelTol * std::abs(truth);
}

struct ChordCase {
    const char* name;
    glm::ivec3 dims;
    glm::dvec3 spacing;
    glm::dvec3 origin;
    glm::dmat3 direction;
};

void PrintTo(const ChordCase& c, std::ostream* os) {
    *os << c.name;
}

class OnesBox : public ::testing::TestWithParam<ChordCase> {};

TEST_P(OnesBox, EveryRayGivesItsExactChordLength) {
    const ChordCase& c = GetParam();
    const fm::Volume volume = makeVolume(c.dims, c.spacing, 1.0f, c.origin, c.direction);
    fm::DrrValueOptions raw;
    raw.values = fm::DrrValues::Raw;
    raw.brickSize = 4;  // several bricks even in these small volumes
    const fm::DrrVolumePtr prepared = fm::prepareDrrVolume(volume, raw);

    std::mt19937 rng(1234);
    const glm::dvec3 center = volume.center();
    const double size = glm::length(volume.extent());
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    auto randomPoint = [&](double scale) {
        return center + scale * size * glm::dvec3(unit(rng), unit(rng), unit(rng));
    };
    int sourcesInside = 0, hits = 0;
    constexpr int kRays = 3000;
    for (int n = 0; n < kRays; ++n) {
        // A third of the sources inside the box (RTK-style), the others outside up to 5x away;
        // targets (pixels) anywhere, also inside (film cutting the volume).
        const glm::dvec3 source = randomPoint(n % 3 == 0 ? 0.3 : 5.0);
        const glm::dvec3 target = randomPoint(n % 2 == 0 ? 0.4 : 3.0);
        const double truth = static_cast<double>(slabChord(volume, source, target));
        const glm::dvec3 idx = volume.worldToIndex(source);
        if (glm::all(glm::greaterThan(idx, glm::dvec3(-0.5))) &&
            glm::all(glm::lessThan(idx, glm::dvec3(c.dims) - 0.5)))
            ++sourcesInside;
        if (truth > 0.0) ++hits;
        const double skipping = fm::drrLineIntegral(*prepared, source, target, true);
        const double plain = fm::drrLineIntegral(*prepared, source, target, false);
        const double reference = fm::drrReferenceLineIntegral(volume, raw, source, target);
        ASSERT_NEAR(skipping, truth, tolerance(truth)) << c.name << " ray " << n;
        ASSERT_NEAR(plain, truth, tolerance(truth)) << c.name << " ray " << n;
        ASSERT_NEAR(reference, truth, tolerance(truth)) << c.name << " ray " << n;
    }
    // The random rays really covered both situations.
    EXPECT_GT(sourcesInside, kRays / 20);
    EXPECT_GT(hits, kRays / 5);
}

INSTANTIATE_TEST_SUITE_P(
    Drr, OnesBox,
    ::testing::Values(
        ChordCase{"cube", {8, 8, 8}, {1.0, 1.0, 1.0}, {0.0, 0.0, 0.0}, glm::dmat3(1.0)},
        ChordCase{"anisotropic", {7, 5, 9}, {0.7, 1.3, 2.1}, {-3.0, 4.0, 10.0}, glm::dmat3(1.0)},
        ChordCase{"ras",
                  {6, 9, 5},
                  {1.5, 0.5, 3.0},
                  {20.0, -7.0, 1.0},
                  glm::dmat3(glm::dvec3(-1, 0, 0), glm::dvec3(0, -1, 0), glm::dvec3(0, 0, 1))},
        ChordCase{"oblique",
                  {9, 6, 7},
                  {0.9, 1.7, 1.1},
                  {5.0, 5.0, -5.0},
                  fm::test::rotation(33.0, {1.0, 2.0, -0.5})}),
    [](const auto& info) { return std::string(info.param.name); });

TEST(DrrChord, ImageOfOnesMatchesChordsPixelByPixel) {
    // The image path (projected box, row chunks, float output) against the same truth.
    const fm::Volume volume = makeVolume({20, 16, 12}, {1.0, 1.25, 2.0}, 1.0f, {0, 0, 0},
                                         fm::test::rotation(20, {0, 1, 1}));
    fm::DrrValueOptions raw;
    raw.values = fm::DrrValues::Raw;
    const auto prepared = fm::prepareDrrVolume(volume, raw);
    const fm::ProjectionGeometry g =
        fm::test::orbitGeometry(volume.center(), 30.0, 20.0, 100.0, 60.0, 64, 1.0);
    fm::DrrRenderOptions options;
    options.threads = 2;
    const fm::Image image = fm::renderDrr(*prepared, g, options);
    // Float pixels: 2^-24 relative rounding of the double result, with margin.
    constexpr double kFloatRelTol = 3e-7;
    int nonZero = 0;
    for (int r = 0; r < image.height; ++r)
        for (int c = 0; c < image.width; ++c) {
            const double truth =
                static_cast<double>(slabChord(volume, g.source, g.detector.pixelCenter(c, r)));
            ASSERT_NEAR(image.at(c, r), truth, kChordAbsTol + kFloatRelTol * truth)
                << c << "," << r;
            if (truth > 0) ++nonZero;
        }
    EXPECT_GT(nonZero, 500);            // the volume is in view
    EXPECT_LT(nonZero, 64 * 64 - 500);  // and so is empty space around it
}

}  // namespace

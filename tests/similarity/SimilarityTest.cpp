// Similarity measures against independent truth: exact affine relations, the statistics of
// independent noise, Sobel's exactness on linear ramps, and where a shifted image matches.
#include <cmath>
#include <cstdint>

#include <gtest/gtest.h>

#include "core/Error.h"
#include "core/Random.h"
#include "similarity/Gradient.h"
#include "similarity/GradientDifference.h"
#include "similarity/GradientNcc.h"
#include "similarity/ImagePyramid.h"
#include "similarity/Mask.h"
#include "similarity/Ncc.h"
#include "similarity/Similarity.h"

namespace fm {
namespace {

// Pixels are floats: an affine transform of a float image is rounded to ~6e-8 relative per
// pixel, which moves a correlation by far less than this.
constexpr double kFloatCorrelationTolerance = 1e-5;

// A smooth image with structure at several scales (blobs and a soft edge), values ~0..3.
Image structuredImage(int w, int h, double shiftCols = 0.0) {
    Image img(w, h);
    for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c) {
            const double x = c - shiftCols, y = r;
            const double blob1 = std::exp(-((x - 20) * (x - 20) + (y - 25) * (y - 25)) / 40.0);
            const double blob2 =
                0.7 * std::exp(-((x - 42) * (x - 42) + (y - 14) * (y - 14)) / 20.0);
            const double edge = 1.0 / (1.0 + std::exp(-(x + 0.5 * y - 40.0) / 1.5));
            img.at(c, r) = static_cast<float>(blob1 + blob2 + edge);
        }
    return img;
}

Image noiseImage(int w, int h, std::uint64_t seed) {
    Rng rng(seed);
    Image img(w, h);
    for (float& p : img.pixels) p = static_cast<float>(rng.uniform());
    return img;
}

TEST(Ncc, PositiveAffineTransformGivesOne) {
    const Image a = structuredImage(64, 48);
    Image b = a;
    for (float& p : b.pixels) p = 2.5f * p - 3.0f;
    EXPECT_NEAR(ncc(a, b), 1.0, kFloatCorrelationTolerance);
}

TEST(Ncc, NegativeAffineTransformGivesMinusOne) {
    const Image a = structuredImage(64, 48);
    Image b = a;
    for (float& p : b.pixels) p = -0.4f * p + 7.0f;
    EXPECT_NEAR(ncc(a, b), -1.0, kFloatCorrelationTolerance);
}

TEST(Ncc, IndependentNoiseIsNearZero) {
    // The sample correlation of n independent pairs has standard deviation 1/sqrt(n - 1); a
    // bound of 5 standard deviations fails by chance with probability below 1e-6.
    const int w = 128, h = 128;
    const double bound = 5.0 / std::sqrt(double(w * h - 1));
    EXPECT_NEAR(ncc(noiseImage(w, h, 1), noiseImage(w, h, 2)), 0.0, bound);
    EXPECT_NEAR(ncc(noiseImage(w, h, 3), noiseImage(w, h, 4)), 0.0, bound);
}

TEST(Ncc, PixelsOutsideTheMaskAreIgnored) {
    const Image a = structuredImage(64, 48);
    Image b = a;
    Mask mask(64, 48, false);
    Rng rng(7);
    for (int r = 0; r < 48; ++r)
        for (int c = 0; c < 64; ++c) {
            if (c < 40) {
                mask.inside[r * 64 + c] = 1;
                b.at(c, r) = 3.0f * a.at(c, r) + 1.0f;
            } else {
                b.at(c, r) = static_cast<float>(100.0 * rng.uniform());  // garbage outside
            }
        }
    EXPECT_NEAR(ncc(a, b, &mask), 1.0, kFloatCorrelationTolerance);
    EXPECT_LT(ncc(a, b), 0.9);  // the garbage does count without the mask
}

TEST(Ncc, UndefinedCasesGiveZeroAndBadSizesThrow) {
    const Image a = structuredImage(32, 32);
    const Image flat(32, 32, 4.0f);
    EXPECT_EQ(ncc(a, flat), 0.0);
    const Mask none(32, 32, false);
    EXPECT_EQ(ncc(a, a, &none), 0.0);
    EXPECT_THROW(ncc(a, structuredImage(31, 32)), Error);
    const Mask wrong(8, 8, true);
    EXPECT_THROW(ncc(a, a, &wrong), Error);
}

TEST(Sobel, LinearRampGivesItsSlopesExactly) {
    // Sobel weights sum to zero and are antisymmetric: on a*c + b*r + k they return (a, b)
    // exactly at every interior pixel (values here are exact in float).
    Image ramp(20, 15);
    for (int r = 0; r < 15; ++r)
        for (int c = 0; c < 20; ++c) ramp.at(c, r) = 0.5f * c - 0.25f * r + 3.0f;
    const GradientImages g = sobel(ramp);
    for (int r = 1; r < 14; ++r)
        for (int c = 1; c < 19; ++c) {
            EXPECT_FLOAT_EQ(g.gx.at(c, r), 0.5f);
            EXPECT_FLOAT_EQ(g.gy.at(c, r), -0.25f);
        }
    EXPECT_EQ(g.gx.at(0, 0), 0.0f);  // border excluded
}

TEST(GradientNcc, InvariantToAddedConstantRampAndGain) {
    const Image a = structuredImage(64, 48);
    Image b = a;
    for (int r = 0; r < 48; ++r)
        for (int c = 0; c < 64; ++c) b.at(c, r) = 1.7f * a.at(c, r) + 5.0f + 0.03f * c - 0.02f * r;
    EXPECT_NEAR(gradientNcc(a, b), 1.0, kFloatCorrelationTolerance);
    // Plain NCC is not invariant to the ramp: it does see a difference.
    EXPECT_LT(ncc(a, b), 0.99);
}

TEST(GradientNcc, NotInvariantToCurvedBackground) {
    // What does not hold: a quadratic background has a varying gradient and lowers the score.
    const Image a = structuredImage(64, 48);
    Image b = a;
    for (int r = 0; r < 48; ++r)
        for (int c = 0; c < 64; ++c) b.at(c, r) += 0.002f * (c - 32) * (c - 32);
    EXPECT_LT(gradientNcc(a, b), 0.99);
}

TEST(GradientDifference, IsOneAtIdentityAndForAnyGain) {
    const Image a = structuredImage(64, 48);
    EXPECT_NEAR(gradientDifference(a, a), 1.0, kFloatCorrelationTolerance);
    Image scaled = a;
    for (float& p : scaled.pixels) p = 2.0f * p + 10.0f;  // gain is fitted, offset has no gradient
    EXPECT_NEAR(gradientDifference(a, scaled), 1.0, kFloatCorrelationTolerance);
}

TEST(GradientDifference, MaximalAtZeroShift) {
    const Image ref = structuredImage(64, 48);
    const double atZero = gradientDifference(ref, structuredImage(64, 48, 0.0));
    for (double shift : {-4.0, -2.0, -1.0, -0.5, 0.5, 1.0, 2.0, 4.0}) {
        const double gd = gradientDifference(ref, structuredImage(64, 48, shift));
        EXPECT_LT(gd, atZero) << "shift " << shift;
    }
    // And it decreases with the size of the shift on each side.
    EXPECT_GT(gradientDifference(ref, structuredImage(64, 48, 1.0)),
              gradientDifference(ref, structuredImage(64, 48, 3.0)));
    EXPECT_GT(gradientDifference(ref, structuredImage(64, 48, -1.0)),
              gradientDifference(ref, structuredImage(64, 48, -3.0)));
}

TEST(GradientDifference, PeakStaysAtZeroShiftDespiteAStrongOverlay) {
    // Soft tissue / an overlay in the reference only: a large bright smooth disc plus a
    // sharp-edged rectangle. The best shift must stay at zero.
    Image ref = structuredImage(64, 48);
    for (int r = 0; r < 48; ++r)
        for (int c = 0; c < 64; ++c) {
            const double d2 = (c - 45.0) * (c - 45.0) + (r - 35.0) * (r - 35.0);
            ref.at(c, r) += static_cast<float>(2.0 * std::exp(-d2 / 300.0));
            if (c > 5 && c < 12 && r > 30 && r < 44) ref.at(c, r) += 3.0f;
        }
    double best = -1.0, bestShift = 99.0;
    for (double shift = -4.0; shift <= 4.0; shift += 0.5) {
        const double gd = gradientDifference(ref, structuredImage(64, 48, shift));
        if (gd > best) best = gd, bestShift = shift;
    }
    EXPECT_EQ(bestShift, 0.0);
}

TEST(SimilarityDispatch, MatchesTheDirectFunctionsAndParsesNames) {
    const Image a = structuredImage(40, 30), b = structuredImage(40, 30, 1.5);
    const Mask mask = footprintMask(b, 0.5f);
    for (SimilarityMeasure m : {SimilarityMeasure::Ncc, SimilarityMeasure::GradientNcc,
                                SimilarityMeasure::GradientDifference}) {
        const double viaDispatch = similarity(m, prepareReference(a, m), b, &mask);
        const double direct = m == SimilarityMeasure::Ncc ? ncc(a, b, &mask)
                              : m == SimilarityMeasure::GradientNcc
                                  ? gradientNcc(a, b, &mask)
                                  : gradientDifference(a, b, &mask);
        EXPECT_DOUBLE_EQ(viaDispatch, direct) << toString(m);
        EXPECT_EQ(parseSimilarityMeasure(toString(m)), m);
    }
    EXPECT_THROW(parseSimilarityMeasure("mutual"), Error);  // "mi" is mutual information
}

TEST(Mask, FootprintDilationAndBoundingRect) {
    Image img(10, 8, 0.0f);
    img.at(4, 3) = 2.0f;
    const Mask m = footprintMask(img);
    EXPECT_EQ(m.count(), 1u);
    const Mask grown = dilate(m, 1);
    EXPECT_EQ(grown.count(), 9u);  // a 3x3 square
    const PixelRect r = boundingRect(grown);
    EXPECT_EQ(r.col0, 3);
    EXPECT_EQ(r.row0, 2);
    EXPECT_EQ(r.cols, 3);
    EXPECT_EQ(r.rows, 3);
    EXPECT_EQ(footprintMask(img, 2.0f).count(), 0u);  // strictly above the threshold
    EXPECT_TRUE(boundingRect(Mask(5, 5, false)).empty());
    // Dilation is clipped at the border.
    Image corner(5, 5, 0.0f);
    corner.at(0, 0) = 1.0f;
    EXPECT_EQ(footprintMask(corner, 0.0f, 2).count(), 9u);
}

TEST(Mask, DilationIsTheChebyshevNeighbourhoodForEveryRadius) {
    // Against the definition: a pixel is inside when some inside pixel lies within `p` rows
    // and `p` columns of it. Random masks, sizes below and above the radius.
    std::uint32_t state = 12345u;
    auto next = [&]() { return state = state * 1664525u + 1013904223u; };
    for (const auto& [w, h] : {std::pair{1, 1}, {2, 7}, {13, 5}, {40, 33}})
        for (int p : {1, 2, 3, 6}) {
            Mask m(w, h, false);
            for (auto& v : m.inside) v = (next() >> 24) < 20 ? 1 : 0;
            const Mask d = dilate(m, p);
            for (int r = 0; r < h; ++r)
                for (int c = 0; c < w; ++c) {
                    bool any = false;
                    for (int rr = std::max(0, r - p); rr <= std::min(h - 1, r + p); ++rr)
                        for (int cc = std::max(0, c - p); cc <= std::min(w - 1, c + p); ++cc)
                            any = any || m.at(cc, rr);
                    ASSERT_EQ(d.at(c, r), any) << w << "x" << h << " p " << p << " at " << c << "," << r;
                }
        }
}

TEST(ImagePyramid, LevelsAreBlockMeans) {
    Image img(9, 6);  // odd width: the last column is dropped
    for (int r = 0; r < 6; ++r)
        for (int c = 0; c < 9; ++c) img.at(c, r) = float(c + 10 * r);
    img.spacing = {0.5, 0.25};
    const ImagePyramid p = buildPyramid(img, 2);
    ASSERT_EQ(p.levels.size(), 2u);
    const Image& half = p.levels[1];
    EXPECT_EQ(half.width, 4);
    EXPECT_EQ(half.height, 3);
    EXPECT_DOUBLE_EQ(half.spacing.x, 1.0);
    EXPECT_DOUBLE_EQ(half.spacing.y, 0.5);
    // Mean of c + 10 r over the 2x2 block at (2c, 2r): (2c + 0.5) + 10 (2r + 0.5).
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c)
            EXPECT_FLOAT_EQ(half.at(c, r), 2 * c + 0.5f + 10 * (2 * r + 0.5f));
    const Image quarter = downsampleBy(img, 4);
    EXPECT_EQ(quarter.width, 2);
    EXPECT_FLOAT_EQ(quarter.at(0, 0), 1.5f + 10 * 1.5f);  // mean over the 4x4 block
    EXPECT_THROW(downsampleBy(img, 3), Error);
    EXPECT_THROW(downsample2x2(Image(1, 5)), Error);
}

}  // namespace
}  // namespace fm

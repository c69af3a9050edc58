#include <gtest/gtest.h>

#include <cmath>

#include "core/Error.h"
#include "core/Random.h"
#include "similarity/MutualInformation.h"
#include "similarity/Similarity.h"

using namespace fm;

namespace {

Image noise(int w, int h, std::uint64_t seed) {
    Rng rng(seed);
    Image im(w, h);
    for (float& p : im.pixels) p = static_cast<float>(rng.uniform(0, 1));
    return im;
}

// A smooth image with many grey levels.
Image blobs(int w, int h) {
    Image im(w, h);
    for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c)
            im.at(c, r) = static_cast<float>(std::sin(c * 0.21) * std::cos(r * 0.17) + 0.01 * c);
    return im;
}

}  // namespace

TEST(MutualInformation, TwoEqualHalvesShareExactlyOneBitInNats) {
    // Half the pixels 0, half 1: each value sits exactly on an end bin, H = log 2, MI(a, a) = H.
    Image a(16, 16);
    for (int i = 0; i < 256; ++i) a.pixels[i] = i % 2 ? 1.0f : 0.0f;
    EXPECT_NEAR(mutualInformation(a, a), std::log(2.0), 1e-12);
}

TEST(MutualInformation, InvariantToAnyAffineIntensityMapIncludingInversion) {
    const Image a = blobs(64, 48);
    const double self = mutualInformation(a, a);
    Image up = a, inverted = a;
    for (float& p : up.pixels) p = 3.0f * p + 10.0f;
    for (float& p : inverted.pixels) p = -2.0f * p + 1.0f;
    EXPECT_NEAR(mutualInformation(a, up), self, 1e-5 * self);
    EXPECT_NEAR(mutualInformation(a, inverted), self, 1e-5 * self);
    EXPECT_GT(self, 2.0);  // many levels: close to log(32) = 3.47
}

TEST(MutualInformation, RewardsANonlinearRelationThatNccMisses) {
    const Image a = blobs(64, 48);
    // A non-monotonic map (like a contrast change between sequences): b = (a - mean)^2.
    double mean = 0.0;
    for (float p : a.pixels) mean += p;
    mean /= double(a.pixels.size());
    Image b = a;
    for (float& p : b.pixels) p = static_cast<float>((p - mean) * (p - mean));
    PreparedReference ra = prepareReference(a, SimilarityMeasure::Ncc);
    const double nccAB = similarity(SimilarityMeasure::Ncc, ra, b, nullptr);
    EXPECT_LT(std::abs(nccAB), 0.3);
    const double miAB = mutualInformation(a, b), miNoise = mutualInformation(a, noise(64, 48, 3));
    EXPECT_GT(miAB, 1.0);
    EXPECT_LT(miNoise, 0.35);  // the plug-in estimate's bias with 3072 pixels and 32x32 bins
    EXPECT_GT(miAB, 5 * miNoise);
}

TEST(MutualInformation, IndependentNoiseIsNearZero) {
    const double mi = mutualInformation(noise(256, 256, 1), noise(256, 256, 2));
    EXPECT_GE(mi, 0.0);
    EXPECT_LT(mi, 0.03);  // bias ~ (bins - 1)^2 / 2N = 0.007 before smoothing
}

TEST(MutualInformation, MaskedOutPixelsHaveNoInfluence) {
    const Image a = blobs(40, 30);
    Image b = a, c = a;
    Mask mask(40, 30, true);
    for (int r = 0; r < 30; ++r)
        for (int col = 30; col < 40; ++col) {
            mask.inside[r * 40 + col] = 0;
            c.at(col, r) = 1e6f;  // garbage where nothing is compared
        }
    EXPECT_EQ(mutualInformation(a, b, &mask), mutualInformation(a, c, &mask));
    EXPECT_NE(mutualInformation(a, b), mutualInformation(a, c));
    EXPECT_EQ(mutualInformation(a, c, &mask),
              similarity(SimilarityMeasure::MutualInformation,
                         prepareReference(a, SimilarityMeasure::MutualInformation), c, &mask));
}

TEST(MutualInformation, DegenerateAndBadInput) {
    const Image a = blobs(8, 8);
    EXPECT_EQ(mutualInformation(a, Image(8, 8, 5.0f)), 0.0);  // constant: no information
    EXPECT_EQ(mutualInformation(a, a, nullptr, 2), mutualInformation(a, a, nullptr, 2));
    EXPECT_THROW(mutualInformation(a, Image(8, 9)), Error);
    EXPECT_THROW(mutualInformation(a, a, nullptr, 1), Error);
    Mask none(8, 8, false);
    EXPECT_EQ(mutualInformation(a, a, &none), 0.0);
    EXPECT_EQ(parseSimilarityMeasure("mi"), SimilarityMeasure::MutualInformation);
    EXPECT_STREQ(toString(SimilarityMeasure::MutualInformation), "mi");
}

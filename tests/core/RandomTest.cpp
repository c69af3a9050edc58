// fm::Rng: the SplitMix64 stream of the reference implementation, and its distributions.
#include <gtest/gtest.h>

#include <cmath>

#include "core/Random.h"

namespace {

TEST(Rng, MatchesTheSplitMix64ReferenceSequence) {
    // First outputs for seed 0 of the reference implementation (Vigna's splitmix64.c).
    fm::Rng rng(0);
    EXPECT_EQ(rng.next(), 0xE220A8397B1DCDAFull);
    EXPECT_EQ(rng.next(), 0x6E789E6AA1B965F4ull);
    EXPECT_EQ(rng.next(), 0x06C45D188009454Full);
}

TEST(Rng, UniformIsTheTop53BitsOfOneDraw) {
    fm::Rng a(123), b(123);
    for (int i = 0; i < 1000; ++i) {
        const double u = a.uniform();
        EXPECT_EQ(u, static_cast<double>(b.next() >> 11) * 0x1.0p-53);
        EXPECT_GE(u, 0.0);
        EXPECT_LT(u, 1.0);
    }
}

TEST(Rng, BelowIsUnbiasedEnoughAndInRange) {
    // 70000 draws over 7 bins: each count is within 5 standard deviations of 10000.
    fm::Rng rng(5);
    int counts[7] = {};
    for (int i = 0; i < 70000; ++i) {
        const auto x = rng.below(7);
        ASSERT_LT(x, 7u);
        ++counts[x];
    }
    const double sigma = std::sqrt(70000.0 * (1.0 / 7) * (6.0 / 7));
    for (int c : counts) EXPECT_NEAR(c, 10000.0, 5.0 * sigma);
}

}  // namespace

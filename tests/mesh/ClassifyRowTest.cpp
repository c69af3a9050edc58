// Marching cubes' row classification (mesh/ClassifyRow.h): both builds against a plain loop
// written here, on rows of every length up to a few vector widths, with values at, just
// below and just above the isovalue, NaN and infinities.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "mesh/ClassifyRow.h"

namespace {

using RowFunction = float (*)(const float*, std::uint8_t*, int, float);

void expectMatchesPlainLoop(RowFunction classify, const char* name) {
    constexpr float kIso = 300.0f;
    constexpr float kInf = std::numeric_limits<float>::infinity();
    const float special[] = {kIso,  std::nextafter(kIso, 0.0f), std::nextafter(kIso, 1e9f),
                             -kInf, kInf, std::numeric_limits<float>::quiet_NaN(), -1024.0f};
    std::mt19937 rng(3);
    std::uniform_int_distribution<int> pick(0, 9);
    std::uniform_real_distribution<float> value(-1000.0f, 2000.0f);
    for (int width = 1; width <= 70; ++width) {
        for (int trial = 0; trial < 20; ++trial) {
            std::vector<float> src(width);
            for (float& v : src) {
                const int k = pick(rng);
                v = k < 7 ? special[k] : value(rng);
            }
            if (trial == 0) src.assign(width, std::numeric_limits<float>::quiet_NaN());
            // A guard byte after the row: nothing may be written past `width`.
            std::vector<std::uint8_t> dst(width + 1, 0xAB);
            const float lowest = classify(src.data(), dst.data(), width, kIso);
            float expectedLowest = kInf;
            for (int x = 0; x < width; ++x) {
                ASSERT_EQ(dst[x], src[x] >= kIso ? 1 : 0)
                    << name << ", width " << width << ", x " << x << ", value " << src[x];
                if (src[x] < expectedLowest) expectedLowest = src[x];
            }
            EXPECT_EQ(dst[width], 0xAB) << name << ", width " << width;
            EXPECT_EQ(lowest, expectedLowest) << name << ", width " << width;
        }
    }
}

TEST(ClassifyRow, PortableAndDispatchedBuildsMatchAPlainLoop) {
    expectMatchesPlainLoop(fm::mc::classifyRowPortable, "portable");
    expectMatchesPlainLoop(fm::mc::classifyRow, "dispatched");  // what marching cubes calls
}

TEST(ClassifyRow, Avx2BuildMatchesAPlainLoop) {
    // A property of the CPU, not of the data: skipped only on a CPU without AVX2, where the
    // dispatched build above is the portable one.
    if (!fm::mc::classifyRowAvx2Available()) GTEST_SKIP() << "this CPU has no AVX2";
    expectMatchesPlainLoop(fm::mc::classifyRowAvx2, "AVX2");
}

}  // namespace

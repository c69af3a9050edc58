#pragma once
// Golden-image comparison: per-pixel tolerance plus a cap on the fraction of pixels that differ.
// On failure the actual image and a diff image are written next to the test's scratch folder.
// FM_UPDATE_GOLDENS=1 rewrites the goldens instead (scripts/refresh_goldens.sh).
#include <string>

#include <gtest/gtest.h>

#include "render/Screenshot.h"

namespace fm::test {

// llvmpipe output is byte-identical run to run; the tolerance absorbs what may legitimately
// move between machines: DRR summation order with another thread count changes a grey level by
// one or two, and anti-aliased edges of lines and text may shift slightly with another Mesa.
inline constexpr int kGoldenChannelTolerance = 12;            // of 255, per channel
inline constexpr double kGoldenMaxDifferingFraction = 0.003;  // 0.3% of the pixels

struct ImageDifference {
    long differingPixels = 0;
    double differingFraction = 0.0;
    int maxChannelDifference = 0;
    render::RgbaImage diff;  // differing pixels red over a dimmed copy of `actual`
};

// Sizes must match (checked by the caller).
ImageDifference compareImages(const render::RgbaImage& expected, const render::RgbaImage& actual,
                              int channelTolerance);

::testing::AssertionResult matchesGolden(const render::RgbaImage& actual, const std::string& name);

}  // namespace fm::test

// The golden comparison itself, against images whose differences are known by construction.
#include "GoldenImage.h"

namespace fm::test {
namespace {

render::RgbaImage gradient(int w, int h) {
    render::RgbaImage image{w, h, std::vector<std::uint8_t>(std::size_t(w) * h * 4)};
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            std::uint8_t* p = &image.pixels[(std::size_t(y) * w + x) * 4];
            p[0] = std::uint8_t(x * 255 / (w - 1));
            p[1] = std::uint8_t(y * 255 / (h - 1));
            p[2] = 128;
            p[3] = 255;
        }
    return image;
}

TEST(GoldenCompare, IdenticalImagesHaveNoDifference) {
    const auto a = gradient(40, 30);
    const ImageDifference d = compareImages(a, a, 0);
    EXPECT_EQ(d.differingPixels, 0);
    EXPECT_EQ(d.maxChannelDifference, 0);
}

TEST(GoldenCompare, CountsExactlyThePixelsBeyondTheTolerance) {
    const auto expected = gradient(40, 30);
    auto actual = expected;
    // 12 pixels changed by 20 in green (beyond 12), 7 pixels by 5 in blue (within).
    for (int i = 0; i < 12; ++i) {
        std::uint8_t& g = actual.pixels[std::size_t(100 + i) * 4 + 1];
        g = std::uint8_t(g < 128 ? g + 20 : g - 20);
    }
    for (int i = 0; i < 7; ++i) actual.pixels[std::size_t(500 + i) * 4 + 2] += 5;
    const ImageDifference d = compareImages(expected, actual, kGoldenChannelTolerance);
    EXPECT_EQ(d.differingPixels, 12);
    EXPECT_DOUBLE_EQ(d.differingFraction, 12.0 / (40 * 30));
    EXPECT_EQ(d.maxChannelDifference, 20);
    // The diff image marks exactly those pixels in pure red.
    for (int p = 0; p < 40 * 30; ++p) {
        const bool marked = d.diff.pixels[p * 4] == 255 && d.diff.pixels[p * 4 + 1] == 0 &&
                            d.diff.pixels[p * 4 + 2] == 0;
        EXPECT_EQ(marked, p >= 100 && p < 112) << "pixel " << p;
    }
}

TEST(GoldenCompare, AlphaIsIgnored) {
    const auto expected = gradient(8, 8);
    auto actual = expected;
    for (std::size_t i = 3; i < actual.pixels.size(); i += 4) actual.pixels[i] = 0;
    EXPECT_EQ(compareImages(expected, actual, 0).differingPixels, 0);
}

}  // namespace
}  // namespace fm::test

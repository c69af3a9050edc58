#include "GoldenImage.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>

#include "common/TestData.h"

namespace fm::test {

ImageDifference compareImages(const render::RgbaImage& expected, const render::RgbaImage& actual,
                              int channelTolerance) {
    ImageDifference d;
    d.diff = actual;
    const std::size_t pixels = std::size_t(actual.width) * actual.height;
    for (std::size_t p = 0; p < pixels; ++p) {
        int worst = 0;
        for (int c = 0; c < 3; ++c)
            worst = std::max(
                worst, std::abs(int(expected.pixels[4 * p + c]) - int(actual.pixels[4 * p + c])));
        d.maxChannelDifference = std::max(d.maxChannelDifference, worst);
        const bool differs = worst > channelTolerance;
        d.differingPixels += differs;
        for (int c = 0; c < 3; ++c)
            d.diff.pixels[4 * p + c] =
                differs ? (c == 0 ? 255 : 0) : std::uint8_t(actual.pixels[4 * p + c] / 4);
        d.diff.pixels[4 * p + 3] = 255;
    }
    d.differingFraction = pixels ? double(d.differingPixels) / double(pixels) : 0.0;
    return d;
}

::testing::AssertionResult matchesGolden(const render::RgbaImage& actual, const std::string& name) {
    const std::filesystem::path golden = std::filesystem::path(FM_GOLDEN_DIR) / (name + ".png");
    const char* update = std::getenv("FM_UPDATE_GOLDENS");
    if (update && std::string(update) == "1") {
        render::writePng(golden, actual);
        return ::testing::AssertionSuccess() << "rewrote " << golden;
    }
    if (!std::filesystem::exists(golden))
        return ::testing::AssertionFailure()
               << "golden " << golden << " is missing; run scripts/refresh_goldens.sh";
    const render::RgbaImage expected = render::readPng(golden);
    const std::filesystem::path out = scratchDir("golden-" + name);
    const auto actualPath = out / (name + ".actual.png");
    if (expected.width != actual.width || expected.height != actual.height) {
        render::writePng(actualPath, actual);
        return ::testing::AssertionFailure()
               << name << ": size " << actual.width << "x" << actual.height << " != golden "
               << expected.width << "x" << expected.height << "; actual written to " << actualPath;
    }
    const ImageDifference d = compareImages(expected, actual, kGoldenChannelTolerance);
    if (d.differingFraction <= kGoldenMaxDifferingFraction) return ::testing::AssertionSuccess();
    const auto diffPath = out / (name + ".diff.png");
    render::writePng(actualPath, actual);
    render::writePng(diffPath, d.diff);
    return ::testing::AssertionFailure()
           << name << ": " << d.differingPixels << " pixels (" << 100.0 * d.differingFraction
           << "%) differ by more than " << kGoldenChannelTolerance << " (max difference "
           << d.maxChannelDifference << "); allowed " << 100.0 * kGoldenMaxDifferingFraction
           << "%. Actual: " << actualPath << ", diff: " << diffPath
           << ". If the change is intended: scripts/refresh_goldens.sh";
}

}  // namespace fm::test

// Radiograph preparation on small synthetic images with answers worked out by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/Error.h"
#include "radiograph/RadiographPreparation.h"

namespace {

fm::Image ramp(int w, int h) {
    fm::Image img(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) img.at(x, y) = static_cast<float>(10 * x + y);
    return img;
}

TEST(Preparation, DefaultsChangeNothing) {
    const fm::Image img = ramp(5, 4);
    const fm::PreparedRadiograph p = fm::prepareRadiograph(img, {});
    EXPECT_EQ(p.image.pixels, img.pixels);
    EXPECT_EQ(p.valid.count(), 20u);
}

TEST(Preparation, InvertAndLog) {
    fm::Image img(4, 1);
    img.pixels = {0.0f, 100.0f, 1000.0f, 2000.0f};
    fm::RadiographPreparation o;
    o.invert = true;
    o.fullScale = 255;
    const auto inv = fm::prepareRadiograph(img, o);
    EXPECT_FLOAT_EQ(inv.image.pixels[1], 155.0f);
    EXPECT_FLOAT_EQ(inv.image.pixels[0], 255.0f);
    o = {};
    o.logTransform = true;
    o.i0 = 1000;
    const auto log = fm::prepareRadiograph(img, o);
    EXPECT_NEAR(log.image.pixels[0], std::log(1000.0), 1e-5);  // I clamped to 1 count
    EXPECT_NEAR(log.image.pixels[1], std::log(10.0), 1e-6);    // -ln(100/1000)
    EXPECT_FLOAT_EQ(log.image.pixels[2], 0.0f);
    EXPECT_FLOAT_EQ(log.image.pixels[3], 0.0f);  // brighter than I0: no attenuation
    o.i0 = 0;
    o.fullScale = 65535;
    EXPECT_NEAR(fm::prepareRadiograph(img, o).image.pixels[1], std::log(655.35), 1e-5);
}

TEST(Preparation, ZeroBorderIsExcludedAndEroded) {
    // A 12 x 10 image with a 2-pixel zero border: 8 x 6 pixels carry image; one more pixel of
    // erosion leaves 6 x 4.
    fm::Image img(12, 10, 0.0f);
    for (int y = 2; y < 8; ++y)
        for (int x = 2; x < 10; ++x) img.at(x, y) = 50.0f;
    fm::RadiographPreparation o;
    o.excludeBelow = 0.0;
    o.erodePixels = 0;
    EXPECT_EQ(fm::prepareRadiograph(img, o).valid.count(), 48u);
    o.erodePixels = 1;
    const auto p = fm::prepareRadiograph(img, o);
    EXPECT_EQ(p.valid.count(), 24u);
    EXPECT_TRUE(p.valid.at(3, 3));
    EXPECT_FALSE(p.valid.at(2, 2));
    // With a region of interest: columns 0..4, rows 0..9 leave columns 3..4 of rows 3..6.
    o.roi = fm::PixelRect{0, 0, 5, 10};
    EXPECT_EQ(fm::prepareRadiograph(img, o).valid.count(), 8u);
}

TEST(Preparation, NonsenseIsRefused) {
    const fm::Image img = ramp(5, 4);
    fm::RadiographPreparation o;
    o.invert = o.logTransform = true;
    EXPECT_THROW(fm::prepareRadiograph(img, o), fm::Error);
    o = {};
    o.roi = fm::PixelRect{3, 0, 3, 2};
    EXPECT_THROW(fm::prepareRadiograph(img, o), fm::Error);
    o = {};
    o.erodePixels = -1;
    o.excludeBelow = 1;
    EXPECT_THROW(fm::prepareRadiograph(img, o), fm::Error);
    o = {};
    o.logTransform = true;
    o.i0 = -5;
    EXPECT_THROW(fm::prepareRadiograph(img, o), fm::Error);
    EXPECT_THROW(fm::prepareRadiograph(fm::Image(), {}), fm::Error);
}

}  // namespace

namespace fm {
namespace {

// One full scale for every path that prepares a radiograph (the CLI's images and a trial's
// frames used to disagree for float TIFFs: 1.0 against 255).
TEST(Preparation, FullScaleOfEachSampleFormat) {
    EXPECT_EQ(radiographFullScale(8), 255.0);
    EXPECT_EQ(radiographFullScale(12), 4095.0);
    EXPECT_EQ(radiographFullScale(16), 65535.0);
    EXPECT_EQ(radiographFullScale(32), 1.0);  // float samples: 0..1
    EXPECT_EQ(radiographFullScale(64), 1.0);
    // Inverting a float image at its full scale: 0.25 -> 0.75.
    Image image(2, 1, 0.25f);
    RadiographPreparation p;
    p.invert = true;
    p.fullScale = radiographFullScale(32);
    EXPECT_FLOAT_EQ(prepareRadiograph(image, p).image.at(0, 0), 0.75f);
}

}  // namespace
}  // namespace fm

namespace fm {
namespace {

// NaN and infinite pixels of a float TIFF counted as valid: twenty inside an implant's outline
// made every gradient sum around them NaN. They and their 8 neighbours leave the mask, and no
// value computed from the image (log, invert, the mask's range) meets them.
TEST(Preparation, NonFinitePixelsAreInvalid) {
    Image image(20, 12, 0.5f);
    for (int x = 0; x < 20; ++x)
        for (int y = 0; y < 12; ++y) image.at(x, y) = 10.0f + float(x + y);
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    image.at(5, 5) = nan;
    image.at(12, 6) = inf;
    image.at(0, 0) = -inf;
    for (const bool log : {false, true}) {
        RadiographPreparation o;
        o.fullScale = 255.0;
        o.logTransform = log;
        o.invert = !log;
        const PreparedRadiograph p = prepareRadiograph(image, o);
        // 9 + 9 around the inner two, 4 in the corner.
        EXPECT_EQ(p.valid.count(), 20u * 12u - 9u - 9u - 4u);
        EXPECT_FALSE(p.valid.at(5, 5));
        EXPECT_FALSE(p.valid.at(6, 4));
        EXPECT_FALSE(p.valid.at(13, 7));
        EXPECT_FALSE(p.valid.at(1, 1));
        EXPECT_TRUE(p.valid.at(7, 5));
        for (float v : p.image.pixels) ASSERT_TRUE(std::isfinite(v)) << (log ? "log" : "invert");
        // The finite pixels are prepared as before.
        const double expected = log ? -std::log(28.0 / 255.0) : 255.0 - 28.0;
        EXPECT_NEAR(p.image.at(9, 9), expected, 1e-5);
    }
    // Finite images are untouched (no pixel leaves the mask, no value changes).
    Image finite(4, 4, 0.25f);
    EXPECT_EQ(prepareRadiograph(finite, {}).valid.count(), 16u);
}

}  // namespace
}  // namespace fm

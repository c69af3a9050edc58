// The overlay picture: the outline is exactly the silhouette's border, drawn in its colour over
// the grey radiograph, whose valid pixels are windowed to their 1st..99th percentile.
#include <gtest/gtest.h>

#include <cmath>

#include "core/Error.h"
#include "track/PoseOverlay.h"

namespace fm {
namespace {

Mask rectangle(int w, int h, int c0, int r0, int cols, int rows) {
    Mask m(w, h, false);
    for (int r = r0; r < r0 + rows; ++r)
        for (int c = c0; c < c0 + cols; ++c) m.inside[static_cast<std::size_t>(r) * w + c] = 1;
    return m;
}

TEST(PoseOverlay, OutlineOfARectangleIsItsBorder) {
    const Mask line = outlineOf(rectangle(20, 15, 3, 4, 8, 5));
    EXPECT_EQ(line.count(), static_cast<std::size_t>(2 * (8 + 5) - 4));
    for (int r = 0; r < 15; ++r)
        for (int c = 0; c < 20; ++c) {
            const bool inside = c >= 3 && c < 11 && r >= 4 && r < 9;
            const bool border = inside && (c == 3 || c == 10 || r == 4 || r == 8);
            EXPECT_EQ(line.at(c, r), border) << c << "," << r;
        }
    // A mask touching the image edge: the edge pixels are outline too.
    EXPECT_EQ(outlineOf(Mask(4, 3, true)).count(), 10u);
}

TEST(PoseOverlay, GreyWindowedImageWithColouredOutlines) {
    // A ramp 0..99 over 100 pixels; pixel 0 invalid (black whatever its value).
    Image image(10, 10);
    for (int i = 0; i < 100; ++i) image.pixels[static_cast<std::size_t>(i)] = static_cast<float>(i);
    Mask valid(10, 10, true);
    valid.inside[0] = 0;
    const Mask box = rectangle(10, 10, 2, 2, 4, 4);
    const auto rgb = overlayRgb(image, valid, {{box, {10, 20, 30}}});
    ASSERT_EQ(rgb.size(), 300u);
    const Mask line = outlineOf(box);
    // Valid values 1..99: the 1st and 99th percentiles by rank are 1.98 -> index 0 (value 1) and
    // index 97 (value 98); below is black, above white, between linear.
    for (std::size_t i = 0; i < 100; ++i) {
        const std::uint8_t* p = &rgb[3 * i];
        if (line.inside[i]) {
            EXPECT_EQ(p[0], 10);
            EXPECT_EQ(p[1], 20);
            EXPECT_EQ(p[2], 30);
            continue;
        }
        EXPECT_EQ(p[0], p[1]);
        EXPECT_EQ(p[1], p[2]);
        if (i == 0) {
            EXPECT_EQ(p[0], 0);
        } else if (i == 99) {
            EXPECT_EQ(p[0], 255);
        } else if (i == 50) {
            EXPECT_EQ(p[0], static_cast<int>(std::lround(255.0 * (50.0 - 1.0) / (98.0 - 1.0))));
        }
    }
}

TEST(PoseOverlay, RefusesMasksOfAnotherSize) {
    const Image image(8, 8, 1.0f);
    EXPECT_THROW(overlayRgb(image, Mask(8, 7, true), {}), Error);
    EXPECT_THROW(overlayRgb(image, std::nullopt, {{Mask(7, 8, true), {1, 2, 3}}}), Error);
    EXPECT_NO_THROW(overlayRgb(image, std::nullopt, {{Mask(8, 8, false), {1, 2, 3}}}));
}

}  // namespace
}  // namespace fm

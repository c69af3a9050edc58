// Area resampling against shares worked out by hand: 1760 -> 512 pixels is a factor of
// s = 3.4375, so output pixel 0 covers input [0, 3.4375), pixel 1 covers [3.4375, 6.875).
#include <gtest/gtest.h>

#include "camera/PinholeCamera.h"
#include "core/Error.h"
#include "similarity/AreaResample.h"
#include "similarity/ImagePyramid.h"

namespace fm {
namespace {

constexpr double kS = 1760.0 / 512.0;

TEST(AreaResample, OnePixelIsSharedByTheAreasItOverlaps) {
    Image one(1760, 1760, 0.0f);
    one.at(5, 5) = 1.0f;  // [5, 6): inside output pixel 1
    one.at(3, 9) = 1.0f;  // columns [3, 4): 0.4375 in output 0, 0.5625 in output 1; rows: in output 2
    one.spacing = {0.2, 0.1};
    const Image out = resampleByArea(one, {512, 512});
    ASSERT_EQ(out.width, 512);
    ASSERT_EQ(out.height, 512);
    EXPECT_DOUBLE_EQ(out.spacing.x, 0.2 * kS);
    EXPECT_DOUBLE_EQ(out.spacing.y, 0.1 * kS);
    EXPECT_FLOAT_EQ(out.at(1, 1), float(1.0 / (kS * kS)));
    EXPECT_FLOAT_EQ(out.at(0, 2), float(0.4375 / (kS * kS)));
    EXPECT_FLOAT_EQ(out.at(1, 2), float(0.5625 / (kS * kS)));
    double sum = 0.0;
    for (float p : out.pixels) sum += p;
    EXPECT_NEAR(sum * kS * kS, 2.0, 1e-6);  // nothing made or lost (to float rounding)
    EXPECT_FLOAT_EQ(out.at(2, 2), 0.0f);
}

TEST(AreaResample, SameSizeIsTheImageAndPowersOfTwoAreBlockMeans) {
    Image img(16, 8);
    for (int r = 0; r < 8; ++r)
        for (int c = 0; c < 16; ++c) img.at(c, r) = float(c * c + 7 * r);
    const Image same = resampleByArea(img, {16, 8});
    EXPECT_EQ(same.pixels, img.pixels);
    const Image quarter = resampleByArea(img, {4, 2});
    const Image blocks = downsampleBy(img, 4);
    ASSERT_EQ(quarter.pixels.size(), blocks.pixels.size());
    for (std::size_t i = 0; i < blocks.pixels.size(); ++i) EXPECT_FLOAT_EQ(quarter.pixels[i], blocks.pixels[i]);
    EXPECT_THROW(resampleByArea(img, {0, 4}), Error);
    EXPECT_THROW(resampleByArea(Image(), {4, 4}), Error);
}

TEST(AreaResample, AnOutputPixelIsValidOnlyIfAllItsSharesAre) {
    Mask m(1760, 1760, true);
    m.inside[3 + 1760 * 9] = 0;  // the shared pixel of the test above: spoils outputs 0 and 1
    const Mask out = resampleMaskByArea(m, {512, 512});
    EXPECT_FALSE(out.at(0, 2));
    EXPECT_FALSE(out.at(1, 2));
    EXPECT_TRUE(out.at(2, 2));
    EXPECT_TRUE(out.at(1, 1));
    EXPECT_EQ(out.count(), 512u * 512u - 2u);
}

TEST(AreaResample, MaskValidityFollowsTheOverlapOfIntervals) {
    // Against the definition: output (c, r) covers input [c s, (c + 1) s) x [r t, (r + 1) t);
    // it is valid when every input pixel overlapping that area (by more than rounding) is.
    std::uint32_t state = 777u;
    auto next = [&]() { return state = state * 1664525u + 1013904223u; };
    const int w = 37, h = 29;
    Mask m(w, h, true);
    for (auto& v : m.inside) v = (next() >> 24) < 12 ? 0 : 1;
    for (const glm::ivec2 size : {glm::ivec2(10, 8), glm::ivec2(37, 7), glm::ivec2(5, 29)}) {
        const Mask out = resampleMaskByArea(m, size);
        const double s = double(w) / size.x, t = double(h) / size.y;
        for (int r = 0; r < size.y; ++r)
            for (int c = 0; c < size.x; ++c) {
                bool all = true;
                for (int i = 0; i < w; ++i)
                    for (int j = 0; j < h; ++j) {
                        const double ox = std::min((c + 1) * s, i + 1.0) - std::max(c * s, double(i));
                        const double oy = std::min((r + 1) * t, j + 1.0) - std::max(r * t, double(j));
                        if (ox > 1e-9 && oy > 1e-9) all = all && m.at(i, j);
                    }
                ASSERT_EQ(out.at(c, r), all) << size.x << "x" << size.y << " at " << c << "," << r;
            }
    }
}

TEST(AreaResample, TheResizedCameraSeesAPointAtTheResampledPixel) {
    PinholeCamera c;
    c.fx = 6167.0;
    c.fy = 6170.0;
    c.cx = 880.3;
    c.cy = 871.9;
    c.imageSize = {1760, 1760};
    c.pixelPitch = 0.2;
    const PinholeCamera r = resizedCamera(c, {512, 512});
    EXPECT_EQ(r.imageSize, glm::ivec2(512, 512));
    const glm::dvec3 point{12.0, -30.0, 950.0};
    const glm::dvec2 full = *c.project(point), small = *r.project(point);
    // Output pixel k's centre is input coordinate (k + 0.5) s - 0.5.
    EXPECT_NEAR((small.x + 0.5) * kS - 0.5, full.x, 1e-9);
    EXPECT_NEAR((small.y + 0.5) * kS - 0.5, full.y, 1e-9);
    // The detector plane stays where it was.
    EXPECT_NEAR(toProjectionGeometry(r).detector.origin.z, toProjectionGeometry(c).detector.origin.z, 1e-9);
    EXPECT_THROW(resizedCamera(c, {512, 0}), Error);
}

}  // namespace
}  // namespace fm

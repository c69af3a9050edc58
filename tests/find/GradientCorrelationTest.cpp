// Every placement's score of the all-placements map (find/GradientCorrelation.h) against the
// registration's gradient NCC (similarity/GradientNcc.h, two-pass means) computed for that one
// placement on a canvas three times the reference's size: the reference's gradients in its middle
// (0 where unusable: outside it, outside its valid mask, next to an invalid pixel, on its border),
// the template's placed at the anchor, compared over the template's mask.
#include <gtest/gtest.h>

#include <cmath>

#include "core/Error.h"
#include "core/Random.h"
#include "find/GradientCorrelation.h"
#include "similarity/GradientNcc.h"

namespace fm {
namespace {

// A smooth random image: a few Gaussian blobs over a ramp, plus noise.
Image correlationTestImage(int w, int h, std::uint64_t seed) {
    Rng rng(seed);
    Image image(w, h);
    struct Blob {
        double x, y, r, a;
    };
    std::vector<Blob> blobs;
    for (int k = 0; k < 12; ++k) blobs.push_back({rng.uniform(0, w), rng.uniform(0, h), rng.uniform(2, 9), rng.uniform(-3, 3)});
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            double v = 0.02 * x - 0.01 * y + 0.3 * rng.normal();
            for (const Blob& b : blobs) v += b.a * std::exp(-((x - b.x) * (x - b.x) + (y - b.y) * (y - b.y)) / (2 * b.r * b.r));
            image.at(x, y) = static_cast<float>(v);
        }
    return image;
}

// A model's render: an ellipse of varying thickness, zero outside.
Image correlationTestRender(int w, int h) {
    Image render(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const double u = (x - 17.0) / 9.0, v = (y - 12.0) / 5.0, r = u * u + v * v;
            if (r < 1.0) render.at(x, y) = static_cast<float>(std::sqrt(1.0 - r) * (1.0 + 0.3 * u));
        }
    return render;
}

TEST(GradientCorrelation, EveryPlacementScoresTheRegistrationsGradientNccThere) {
    const int W = 48, H = 40;
    const Image reference = correlationTestImage(W, H, 7);
    Mask valid(W, H, true);
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x)
            if ((x - 44) * (x - 44) + (y - 4) * (y - 4) < 64) valid.inside[static_cast<std::size_t>(y) * W + x] = 0;
    const int erode = 1;
    const CorrelationReference prepared(reference, &valid, erode);
    const GradientTemplate t = gradientTemplate(correlationTestRender(40, 30), {15.3, 13.6}, {W, H});
    ASSERT_FALSE(t.empty());
    EXPECT_EQ(t.anchor, glm::ivec2(15 - 7, 14 - 6));  // footprint from column 9, row 8, less two
    const double minCoverage = 0.6;
    const std::vector<float> map = gradientNccMap(prepared, t, minCoverage);

    // The canvas: the reference's usable gradients in the middle.
    const GradientImages g = sobel(reference);
    GradientImages canvas{Image(3 * W, 3 * H), Image(3 * W, 3 * H)};
    Image usable(3 * W, 3 * H);
    for (int y = 1; y < H - 1; ++y)
        for (int x = 1; x < W - 1; ++x) {
            bool ok = true;
            for (int dy = -erode; dy <= erode; ++dy)
                for (int dx = -erode; dx <= erode; ++dx) {
                    const int sx = x + dx, sy = y + dy;
                    if (sx >= 0 && sy >= 0 && sx < W && sy < H && !valid.at(sx, sy)) ok = false;
                }
            if (!ok) continue;
            canvas.gx.at(x + W, y + H) = g.gx.at(x, y);
            canvas.gy.at(x + W, y + H) = g.gy.at(x, y);
            usable.at(x + W, y + H) = 1.0f;
        }
    int scored = 0, refused = 0;
    for (int Y = 0; Y < H; ++Y)
        for (int X = 0; X < W; ++X) {
            GradientImages placed{Image(3 * W, 3 * H), Image(3 * W, 3 * H)};
            Mask mask(3 * W, 3 * H, false);
            double n = 0.0, covered = 0.0;
            for (int j = 0; j < t.mask.height; ++j)
                for (int i = 0; i < t.mask.width; ++i) {
                    if (!t.mask.at(i, j)) continue;
                    const int cx = X - t.anchor.x + i + W, cy = Y - t.anchor.y + j + H;
                    placed.gx.at(cx, cy) = t.gradients.gx.at(i, j);
                    placed.gy.at(cx, cy) = t.gradients.gy.at(i, j);
                    mask.inside[static_cast<std::size_t>(cy) * 3 * W + cx] = 1;
                    n += 1.0;
                    covered += usable.at(cx, cy);
                }
            const float got = map[static_cast<std::size_t>(Y) * W + X];
            if (covered < minCoverage * n) {
                EXPECT_EQ(got, kNoPlacement) << X << "," << Y;
                ++refused;
                continue;
            }
            EXPECT_NEAR(got, gradientNcc(placed, canvas, mask), 2e-5) << X << "," << Y;
            ++scored;
        }
    // Both kinds of placement were checked (the template is a third of the reference wide).
    EXPECT_GT(scored, W * H / 3);
    EXPECT_GT(refused, W * H / 10);
}

TEST(GradientCorrelation, PlacementsApartScoreWhatEveryPlacementScoresThere) {
    // The same reference and template at strides 1, 2 and 3: the same bits at the placements kept
    // (the same sums, added in the same order).
    const int W = 47, H = 38;
    const Image reference = correlationTestImage(W, H, 11);
    const GradientTemplate t = gradientTemplate(correlationTestRender(40, 30), {20.0, 10.0}, {W, H});
    const std::vector<float> all = gradientNccMap(CorrelationReference(reference, nullptr, 0), t, 0.5);
    for (int stride : {2, 3}) {
        const CorrelationReference apart(reference, nullptr, 0, stride);
        ASSERT_EQ(apart.mapWidth(), (W + stride - 1) / stride);
        ASSERT_EQ(apart.mapHeight(), (H + stride - 1) / stride);
        const std::vector<float> map = gradientNccMap(apart, t, 0.5);
        int scored = 0;
        for (int y = 0; y < apart.mapHeight(); ++y)
            for (int x = 0; x < apart.mapWidth(); ++x) {
                const float want = all[static_cast<std::size_t>(stride * y) * W + stride * x];
                EXPECT_EQ(map[static_cast<std::size_t>(y) * apart.mapWidth() + x], want) << stride << ": " << x << "," << y;
                scored += want != kNoPlacement;
            }
        EXPECT_GT(scored, apart.mapWidth() * apart.mapHeight() / 3);
    }
    EXPECT_THROW(CorrelationReference(reference, nullptr, 0, 0), Error);
}

TEST(GradientCorrelation, ATemplateScoresOneWhereItWasCutFrom) {
    // The reference is the render itself, shifted: its peak is 1 at the shift.
    const Image render = correlationTestRender(40, 30);
    Image reference(48, 40);
    for (int y = 0; y < 30; ++y)
        for (int x = 0; x < 40; ++x) reference.at(x + 5, y + 7) = render.at(x, y);
    const GradientTemplate t = gradientTemplate(render, {17.0, 12.0}, {48, 40});
    const std::vector<float> map = gradientNccMap(CorrelationReference(reference, nullptr, 0), t, 0.9);
    const auto best = std::max_element(map.begin(), map.end()) - map.begin();
    EXPECT_EQ(best % 48, 17 + 5);
    EXPECT_EQ(best / 48, 12 + 7);
    EXPECT_NEAR(map[static_cast<std::size_t>(best)], 1.0, 1e-5);
    // Nothing rendered, or a footprint larger than the reference: no template.
    EXPECT_TRUE(gradientTemplate(Image(40, 30), {17.0, 12.0}, {48, 40}).empty());
    EXPECT_TRUE(gradientTemplate(render, {17.0, 12.0}, {20, 20}).empty());
}

}  // namespace
}  // namespace fm

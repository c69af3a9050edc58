// The silhouette-to-edge measure: the distance transform equals brute force, a disc's edges
// are found on its rim, and the score is 1 at the truth and falls with the shift.
#include <cmath>

#include <gtest/gtest.h>

#include "core/Error.h"
#include "core/Random.h"
#include "similarity/EdgeDistance.h"
#include "similarity/Similarity.h"

namespace fm {
namespace {

Image disc(int size, double cx, double cy, double radius, float inside) {
    Image im(size, size, 0.0f);
    for (int r = 0; r < size; ++r)
        for (int c = 0; c < size; ++c)
            if (std::hypot(c - cx, r - cy) <= radius) im.at(c, r) = inside;
    return im;
}

TEST(EdgeDistance, DistanceTransformIsTheBruteForceEuclideanDistance) {
    Rng rng(7);
    Mask m(37, 23, false);
    for (auto& v : m.inside) v = rng.uniform() < 0.03;
    m.inside[5] = 1;
    const Image d = distanceToMask(m);
    for (int r = 0; r < m.height; ++r)
        for (int c = 0; c < m.width; ++c) {
            double best = 1e30;
            for (int rr = 0; rr < m.height; ++rr)
                for (int cc = 0; cc < m.width; ++cc)
                    if (m.at(cc, rr)) best = std::min(best, std::hypot(c - cc, r - rr));
            EXPECT_NEAR(d.at(c, r), best, 1e-5) << c << "," << r;
        }
    EXPECT_GE(distanceToMask(Mask(4, 4, false)).at(0, 0), 1e8f);  // no edge at all
}

TEST(EdgeDistance, EdgesOfADiscLieOnItsRim) {
    // A soft-edged disc (a radiograph's blur): edges within a pixel of radius 20.
    Image im(80, 80, 0.0f);
    for (int r = 0; r < 80; ++r)
        for (int c = 0; c < 80; ++c)
            im.at(c, r) = static_cast<float>(
                100.0 / (1.0 + std::exp((std::hypot(c - 40.0, r - 40.0) - 20.0) / 0.8)));
    const Mask e = strongEdges(im);
    ASSERT_GT(e.count(), 60u);  // about the circumference, 2 pi 20 = 126
    for (int r = 0; r < 80; ++r)
        for (int c = 0; c < 80; ++c)
            if (e.at(c, r)) {
                EXPECT_NEAR(std::hypot(c - 40.0, r - 40.0), 20.0, 1.5);
            }
}

TEST(EdgeDistance, ScoreIsOneAtTheTruthAndFallsWithTheShift) {
    const Image reference = disc(100, 50.0, 50.0, 20.0, 200.0f);
    const PreparedReference prepared =
        prepareReference(reference, SimilarityMeasure::EdgeDistance);
    double previous = 2.0;
    for (double shift : {0.0, 1.0, 2.0, 4.0, 8.0}) {
        const Image moving = disc(100, 50.0 + shift, 50.0, 20.0, 3.0f);  // scale does not matter
        const double s = similarity(SimilarityMeasure::EdgeDistance, prepared, moving, nullptr);
        EXPECT_LT(s, previous) << shift;
        // A step's edge lies between two pixels and thinning keeps one of them: at the truth
        // each outline pixel is at most 1 pixel from an edge, so the score is >= 1 - 1/cap.
        if (shift == 0.0) {
            EXPECT_GE(s, 1.0 - 1.0 / kEdgeCapPixels);
        }
        previous = s;
    }
    // Outline pixels outside the mask do not count; none counting gives 0.
    const Image moving = disc(100, 50.0, 50.0, 20.0, 1.0f);
    const Mask none(100, 100, false);
    EXPECT_EQ(similarity(SimilarityMeasure::EdgeDistance, prepared, moving, &none), 0.0);
    EXPECT_EQ(parseSimilarityMeasure("edge"), SimilarityMeasure::EdgeDistance);
    EXPECT_STREQ(toString(SimilarityMeasure::EdgeDistance), "edge");
    EXPECT_THROW(similarity(SimilarityMeasure::EdgeDistance, prepared, Image(10, 10), nullptr),
                 Error);
}

TEST(EdgeDistance, OutlineIsTheFootprintsBoundary) {
    Image im(6, 5, 0.0f);
    for (int r = 1; r <= 3; ++r)
        for (int c = 1; c <= 4; ++c) im.at(c, r) = 1.0f;
    const Mask o = footprintOutline(im);
    EXPECT_EQ(o.count(), 10u);  // a 4x3 block: 12 pixels, the 2 inner ones excluded
    EXPECT_FALSE(o.at(2, 2));
    EXPECT_FALSE(o.at(3, 2));
    EXPECT_TRUE(o.at(1, 1));
}

}  // namespace
}  // namespace fm

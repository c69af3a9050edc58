// Mesh DRR images: pixel values against independent chords along each pixel's ray, the
// projected-box pixel limit (changes nothing), determinism across thread counts, silhouettes,
// open models and bad parameters.
#include <gtest/gtest.h>

#include <cstring>

#include "ChordTruth.h"
#include "common/TestMeshes.h"
#include "core/Error.h"
#include "meshdrr/MeshDrr.h"

namespace {

using glm::dvec3;

// A tilted camera 600 mm from the origin looking at it, with a 96 x 80 detector of 0.8 mm
// pixels 400 mm behind the origin.
fm::ProjectionGeometry tiltedCamera(const dvec3& source = dvec3(120, -80, 580)) {
    fm::ProjectionGeometry g;
    g.source = source;
    const dvec3 view = glm::normalize(-source);
    const dvec3 u = glm::normalize(glm::cross(view, dvec3(0.3, 1, 0.1)));
    const dvec3 v = glm::cross(view, u);
    g.detector.size = {96, 80};
    g.detector.spacing = {0.8, 0.8};
    g.detector.u = u;
    g.detector.v = v;
    const dvec3 center = source + (glm::length(source) + 400.0) * view;
    g.detector.origin = center - 0.5 * (96 - 1) * 0.8 * u - 0.5 * (80 - 1) * 0.8 * v;
    return g;
}

bool sameBits(const fm::Image& a, const fm::Image& b) {
    return a.width == b.width && a.height == b.height &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)) == 0;
}

TEST(MeshDrrImage, BoxPixelsAreMuTimesTheSlabChord) {
    const dvec3 lo(-12, -7, -9), hi(10, 15, 6);
    const auto model = fm::prepareMeshDrr(fm::test::boxMesh(lo, hi), true);
    const fm::ProjectionGeometry g = tiltedCamera();
    const double mu = 0.5;
    const fm::Image image = fm::renderMeshDrr(*model, g, mu);
    EXPECT_EQ(image.spacing, g.detector.spacing);
    int inside = 0;
    for (int r = 0; r < g.detector.size.y; ++r)
        for (int c = 0; c < g.detector.size.x; ++c) {
            const double truth = mu * fm::test::boxChord(lo, hi, g.source, g.detector.pixelCenter(c, r));
            ASSERT_NEAR(image.at(c, r), truth, 1e-6 * std::max(truth, 1.0)) << c << " " << r;  // float image
            inside += truth > 0;
        }
    EXPECT_GT(inside, 500);
    EXPECT_LT(inside, 96 * 80 - 500);  // the box does not fill the film: the pixel limit matters
}

TEST(MeshDrrImage, SameBitsForAnyThreadCountAndWithoutThePixelLimit) {
    const fm::Mesh mesh = fm::test::mergeMeshes(fm::test::uvSphereMesh({-5, 3, 2}, 9.f, 16, 32),
                                                fm::test::squareFrameMesh(6.f, 3.f, 8.f, 12.f));
    const auto model = fm::prepareMeshDrr(mesh, true);
    for (const dvec3 source : {dvec3(120, -80, 580), dvec3(-3, 2, 1)}) {  // outside; inside
        const fm::ProjectionGeometry g = tiltedCamera(source);
        fm::MeshDrrOptions o;
        o.threads = 1;
        const fm::Image one = fm::renderMeshDrr(*model, g, 1.0, o);
        for (int threads : {2, 3, 0}) {
            o.threads = threads;
            EXPECT_TRUE(sameBits(fm::renderMeshDrr(*model, g, 1.0, o), one)) << threads;
        }
        o.limitToProjectedBox = false;
        EXPECT_TRUE(sameBits(fm::renderMeshDrr(*model, g, 1.0, o), one));
        float peak = 0;
        for (float p : one.pixels) peak = std::max(peak, p);
        EXPECT_GT(peak, 5.0f);  // from inside the sphere: 9 - 2.45 mm to its wall
    }
}

TEST(MeshDrrImage, SourceInsideTheModelTracesEveryPixel) {
    // The source in the box's centre: every ray leaves through a wall, so every pixel is the
    // distance to that wall (the box's projection covers the whole film).
    const dvec3 lo(-50, -50, -50), hi(50, 50, 50);
    const auto model = fm::prepareMeshDrr(fm::test::boxMesh(lo, hi), true);
    fm::ProjectionGeometry g = tiltedCamera(dvec3(1, 2, 3));
    const fm::Image image = fm::renderMeshDrr(*model, g, 1.0);
    for (int r = 0; r < g.detector.size.y; r += 7)
        for (int c = 0; c < g.detector.size.x; c += 5) {
            const double truth = fm::test::boxChord(lo, hi, g.source, g.detector.pixelCenter(c, r));
            ASSERT_GT(truth, 40.0);
            ASSERT_NEAR(image.at(c, r), truth, 1e-5) << c << " " << r;
        }
}

TEST(MeshDrrImage, SilhouetteIsWhereTheChordIsPositive) {
    const fm::Mesh frame = fm::test::squareFrameMesh(30.f, 12.f, -5.f, 5.f);
    const auto model = fm::prepareMeshDrr(frame, true);
    const fm::ProjectionGeometry g = tiltedCamera(dvec3(20, -10, 600));
    const fm::Mask mask = fm::renderMeshSilhouette(*model, g);
    std::size_t disagreements = 0, inside = 0;
    for (int r = 0; r < g.detector.size.y; ++r)
        for (int c = 0; c < g.detector.size.x; ++c) {
            const dvec3 e = g.detector.pixelCenter(c, r);
            const double truth = fm::test::boxChord({-30, -30, -5}, {30, 30, 5}, g.source, e) -
                                 fm::test::boxChord({-12, -12, -5}, {12, 12, 5}, g.source, e);
            disagreements += mask.at(c, r) != (truth > 1e-6);
            inside += mask.at(c, r);
        }
    EXPECT_EQ(disagreements, 0u);
    EXPECT_GT(inside, 1000u);
    // The hole is seen through: its centre pixel is outside the silhouette.
    const auto centre = g.projectToPixel({0, 0, 0});
    ASSERT_TRUE(centre);
    EXPECT_FALSE(mask.at(int(std::lround(centre->x)), int(std::lround(centre->y))));
}

TEST(MeshDrrImage, OpenModelGivesSilhouetteOnly) {
    fm::Mesh box = fm::test::boxMesh({-10, -10, -10}, {10, 10, 10});
    const fm::Mesh closedBox = box;
    box.triangles.erase(box.triangles.begin());  // a hole in the z = -10 face (facing away)
    const auto open = fm::prepareMeshDrr(box, false);
    const fm::ProjectionGeometry g = tiltedCamera(dvec3(0, 0, 600));
    EXPECT_THROW(fm::renderMeshDrr(*open, g, 1.0), fm::Error);
    const fm::Mask openMask = fm::renderMeshSilhouette(*open, g);
    const fm::Mask closedMask = fm::renderMeshSilhouette(*fm::prepareMeshDrr(closedBox, true), g);
    // Seen from +z, every ray that enters the box crosses the (intact) top face: same outline.
    EXPECT_EQ(openMask.inside, closedMask.inside);
    EXPECT_GT(openMask.count(), 100u);
}

TEST(MeshDrrImage, TwoModelsAddIntoOneImage) {
    const auto a = fm::prepareMeshDrr(fm::test::boxMesh({-10, -10, -10}, {0, 5, 10}), true);
    const auto b = fm::prepareMeshDrr(fm::test::cylinderMesh(8.f, -6.f, 6.f, 24), true);
    const fm::ProjectionGeometry g = tiltedCamera();
    const fm::Image ia = fm::renderMeshDrr(*a, g, 0.06), ib = fm::renderMeshDrr(*b, g, 1.2);
    fm::Image sum(g.detector.size.x, g.detector.size.y, 0.0f);
    fm::addMeshDrr(*a, g, 0.06, sum);
    fm::addMeshDrr(*b, g, 1.2, sum);
    for (std::size_t i = 0; i < sum.pixels.size(); ++i) ASSERT_EQ(sum.pixels[i], ia.pixels[i] + ib.pixels[i]);
}

TEST(MeshDrrImage, RefusesBadParameters) {
    const auto model = fm::prepareMeshDrr(fm::test::boxMesh({0, 0, 0}, {1, 1, 1}), true);
    fm::ProjectionGeometry g = tiltedCamera();
    EXPECT_THROW(fm::renderMeshDrr(*model, g, -1.0), fm::Error);
    EXPECT_THROW(fm::renderMeshDrr(*model, g, std::nan("")), fm::Error);
    fm::Image wrong(10, 10);
    EXPECT_THROW(fm::addMeshDrr(*model, g, 1.0, wrong), fm::Error);
    g.detector.spacing.x = 0;
    EXPECT_THROW(fm::renderMeshDrr(*model, g, 1.0), fm::Error);
    EXPECT_THROW(fm::renderMeshSilhouette(*model, g), fm::Error);
}

}  // namespace

// The pose as a camera sees it (find/SeenPose.h) against projective arithmetic: the pivot
// projects at the pixel, lies at the depth along the optical axis, and the angles come back.
#include <gtest/gtest.h>

#include "core/Random.h"
#include "find/SeenPose.h"

namespace fm {
namespace {

ProjectionGeometry camera(bool flipped) {
    ProjectionGeometry g;
    g.source = {10.0, -20.0, 900.0};
    g.detector.size = {400, 300};
    g.detector.spacing = {0.5, 0.6};
    g.detector.u = {1, 0, 0};
    g.detector.v = flipped ? glm::dvec3(0, 1, 0) : glm::dvec3(0, -1, 0);
    g.detector.origin = {-90.0, flipped ? -110.0 : 70.0, -100.0};  // film 1000 mm from the source
    return g;
}

TEST(SeenPose, PivotProjectsAtThePixelAndTheAnglesRoundTrip) {
    for (bool flipped : {false, true}) {
        const ProjectionGeometry g = camera(flipped);
        const CameraAxes axes = cameraAxes(g);
        EXPECT_NEAR(axes.distance, 1000.0, 1e-9);
        EXPECT_NEAR(axes.rollSign, flipped ? -1.0 : 1.0, 0.0);
        // The principal pixel is where the source's perpendicular meets the film.
        const glm::dvec2 foot = *g.projectToPixel(g.source + 500.0 * axes.view);
        EXPECT_NEAR(foot.x, axes.principalPixel.x, 1e-9);
        EXPECT_NEAR(foot.y, axes.principalPixel.y, 1e-9);
        // The base orientation: x along the columns, z towards the source, right-handed.
        const glm::dmat3 base = baseOrientation(axes);
        EXPECT_NEAR(glm::determinant(base), 1.0, 1e-12);
        EXPECT_NEAR(glm::dot(base[2], -axes.view), 1.0, 1e-12);
        Rng rng(7);
        const glm::dvec3 pivot{3.0, -4.0, 12.0};
        for (int i = 0; i < 50; ++i) {
            SeenPose s;
            s.pixel = {rng.uniform(0.0, 399.0), rng.uniform(0.0, 299.0)};
            s.depth = rng.uniform(200.0, 950.0);
            s.rollDeg = rng.uniform(-179.0, 179.0);
            s.tiltUDeg = rng.uniform(-60.0, 60.0);
            s.tiltVDeg = rng.uniform(-60.0, 60.0);
            const RigidTransform t = worldFromSeen(axes, s, pivot);
            const glm::dvec3 p = t.applyToPoint(pivot);
            const glm::dvec2 px = *g.projectToPixel(p);
            EXPECT_NEAR(px.x, s.pixel.x, 1e-7);
            EXPECT_NEAR(px.y, s.pixel.y, 1e-7);
            EXPECT_NEAR(glm::dot(p - g.source, axes.view), s.depth, 1e-7);
            const SeenPose back = seenFrom(axes, t, pivot);
            EXPECT_NEAR(back.pixel.x, s.pixel.x, 1e-7);
            EXPECT_NEAR(back.pixel.y, s.pixel.y, 1e-7);
            EXPECT_NEAR(back.depth, s.depth, 1e-7);
            EXPECT_NEAR(back.rollDeg, s.rollDeg, 1e-7);
            EXPECT_NEAR(back.tiltUDeg, s.tiltUDeg, 1e-7);
            EXPECT_NEAR(back.tiltVDeg, s.tiltVDeg, 1e-7);
        }
    }
}

TEST(SeenPose, ARollTurnsTheImageAboutThePivot) {
    // On the optical axis, a roll of 90 deg takes a point one step along the model's x (the film's
    // columns at roll 0) to one step along the rows: counter-clockwise in (column, row) when the view
    // is u x v.
    for (bool flipped : {false, true}) {
        const ProjectionGeometry g = camera(flipped);
        const CameraAxes axes = cameraAxes(g);
        SeenPose s;
        s.pixel = axes.principalPixel;
        s.depth = 500.0;
        s.rollDeg = 90.0;
        const RigidTransform t = worldFromSeen(axes, s, glm::dvec3(0.0));
        const glm::dvec2 centre = *g.projectToPixel(t.applyToPoint({0, 0, 0}));
        const glm::dvec2 tip = *g.projectToPixel(t.applyToPoint({10, 0, 0}));
        const glm::dvec2 d = tip - centre;
        EXPECT_NEAR(d.x, 0.0, 1e-9);
        EXPECT_NEAR(d.y, axes.rollSign * 10.0 * 2.0 / g.detector.spacing.y, 1e-7);  // magnification 2
    }
}

}  // namespace
}  // namespace fm

// Finite but absurd parameters: geometry whose arithmetic would overflow is refused before a
// ray is traced (core/WorldLimits.h), and the largest accepted geometry still gives finite pixels
// (no NaN reaches an output).
#include <cmath>
#include <functional>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "DrrTestUtil.h"
#include "core/Error.h"
#include "core/WorldLimits.h"
#include "drr/Drr.h"
#include "geometry/Pose.h"

namespace {

using fm::test::makeVolume;

std::string messageOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const fm::Error& e) {
        return e.what();
    }
    return "(no fm::Error)";
}

fm::Volume cube() {
    fm::Volume v = makeVolume({8, 8, 8}, {1, 1, 1}, 1.0f, {-3.5, -3.5, -3.5});
    return v;
}

fm::DrrValueOptions raw() {
    fm::DrrValueOptions o;
    o.values = fm::DrrValues::Raw;
    return o;
}

// A head-on view of the cube: source on -z at `distance`, film on +z.
fm::ProjectionGeometry headOn(double distance, glm::ivec2 pixels, double spacing) {
    fm::ProjectionGeometry g;
    g.source = {0, 0, -distance};
    g.detector.size = pixels;
    g.detector.spacing = {spacing, spacing};
    g.detector.u = {1, 0, 0};
    g.detector.v = {0, 1, 0};
    g.detector.origin = {-0.5 * spacing * (pixels.x - 1), -0.5 * spacing * (pixels.y - 1), 10.0};
    return g;
}

TEST(DrrLimits, OverflowingGeometryIsRefusedByName) {
    fm::ProjectionGeometry far = headOn(1e308, {4, 4}, 1.0);
    EXPECT_NE(messageOf([&] { far.validate("g"); }).find("\"source\" must lie within"),
              std::string::npos);
    fm::ProjectionGeometry wide = headOn(100, {4, 4}, 1e300);
    wide.detector.origin = {0, 0, 10};
    EXPECT_NE(messageOf([&] { wide.validate("g"); }).find("detector.spacing[0]"),
              std::string::npos);
    // The scene builder: distances, film and offsets of 1e308.
    fm::SceneSetup s = fm::defaultSceneSetup();
    s.sourceToIsocenterMm = 1e308;
    EXPECT_NE(messageOf([&] { fm::validateSceneSetup(s); }).find("source-to-isocenter"),
              std::string::npos);
    s = fm::defaultSceneSetup();
    s.filmSizeMm = {1e308, 1e308};
    EXPECT_NE(messageOf([&] { fm::validateSceneSetup(s); }).find("film width"), std::string::npos);
    fm::Pose p;
    p.offset.x = 1e308;
    EXPECT_NE(messageOf([&] { fm::validatePose(p); }).find("x offset"), std::string::npos);
    EXPECT_THROW(fm::sceneGeometry(p, fm::defaultSceneSetup(), glm::dvec3(0.0)), fm::Error);
    // A volume whose spacing would put its far corner at 1e300 mm.
    fm::Volume v = cube();
    v.spacing.y = 1e300;
    EXPECT_NE(messageOf([&] { v.validate("ct"); }).find("axis 1"), std::string::npos);
}

TEST(DrrLimits, LargestAcceptedGeometryGivesFinitePixels) {
    // Source at the limit, a film as wide as the limit in 16383 pixels: every figure at its
    // limit, and every pixel a finite number (double still resolves ~0.1 mm out there).
    const auto prepared = fm::prepareDrrVolume(cube(), raw());
    for (double distance : {1e6, fm::kMaxWorldMm}) {
        fm::ProjectionGeometry g = headOn(distance, {16383, 1}, distance / 16384);
        g.validate("limit");
        const fm::Image image = fm::renderDrr(*prepared, g, {});
        for (float px : image.pixels) ASSERT_TRUE(std::isfinite(px)) << distance;
        // The central ray (pixel 8191 is at x = 0) crosses 8 mm of ones along z; at 1e15 mm
        // the ray parameter's rounding (1e15 * 2^-52 = 0.2 mm) bounds the accuracy.
        EXPECT_NEAR(image.at(8191, 0), 8.0, distance * 1e-15) << distance;
    }

    fm::SceneSetup s = fm::defaultSceneSetup();
    s.sourceToIsocenterMm = s.isocenterToFilmMm = fm::kMaxWorldMm / 2;
    s.filmSizeMm = {fm::kMaxWorldMm, fm::kMaxWorldMm};
    fm::Pose p;
    p.offset = {1000, -1000, 500};
    p.azimuthDeg = 30;
    const fm::Image scene = fm::renderDrr(*prepared, fm::sceneGeometry(p, s, glm::dvec3(0.0)), {});
    for (float px : scene.pixels) ASSERT_TRUE(std::isfinite(px));
}

}  // namespace

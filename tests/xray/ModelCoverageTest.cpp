// What a model covers at a pose (xray/ModelCoverage.h), against exact chords: the footprint is
// the pixels whose ray crosses the box (analytic slab test), and each blind case is named by
// its cause: behind the source, a model in metres, on excluded pixels, over the whole image.
#include <gtest/gtest.h>

#include "common/TestMeshes.h"
#include "meshdrr/MeshDrr.h"
#include "scene/MeshXrayModel.h"
#include "xray/ModelCoverage.h"

namespace {

using glm::dvec3;

fm::ProjectionGeometry frontCamera() {  // source at z = 800 looking along -z, film at z = -300
    fm::ProjectionGeometry g;
    g.source = {0, 0, 800};
    g.detector.size = {64, 48};
    g.detector.spacing = {1.5, 1.5};
    g.detector.origin = {-0.5 * 63 * 1.5, -0.5 * 47 * 1.5, -300};
    return g;
}

fm::SceneObject box(const dvec3& lo, const dvec3& hi, const fm::RigidTransform& pose) {
    auto m = std::make_shared<fm::MeshXrayModel>(fm::prepareMeshDrr(fm::test::boxMesh(lo, hi), true), 0.1);
    return {"box", m, pose, true};
}

// Does the segment s -> e cross the box [lo, hi] (length > 0)?
bool crosses(const dvec3& lo, const dvec3& hi, const dvec3& s, const dvec3& e) {
    double t0 = 0, t1 = 1;
    for (int a = 0; a < 3; ++a) {
        const double d = e[a] - s[a];
        if (d == 0) {
            if (s[a] < lo[a] || s[a] > hi[a]) return false;
            continue;
        }
        double u = (lo[a] - s[a]) / d, v = (hi[a] - s[a]) / d;
        if (u > v) std::swap(u, v);
        t0 = std::max(t0, u);
        t1 = std::min(t1, v);
    }
    return t1 > t0;
}

TEST(ModelCoverage, FootprintIsThePixelsWhoseRayCrossesTheModel) {
    const fm::ProjectionGeometry g = frontCamera();
    const dvec3 shift{7, -4, 30};
    const fm::SceneObject o = box({-20, -10, -3}, {20, 10, 3}, fm::RigidTransform::translate(shift));
    std::size_t truth = 0;
    for (int r = 0; r < g.detector.size.y; ++r)
        for (int c = 0; c < g.detector.size.x; ++c)
            truth += crosses(dvec3(-20, -10, -3) + shift, dvec3(20, 10, 3) + shift, g.source,
                             g.detector.pixelCenter(c, r)) ? 1 : 0;
    ASSERT_GT(truth, 100u);
    const fm::Mask all(64, 48, true);
    const fm::ModelCoverage c = fm::modelCoverage(o, g, all);
    // Rays that graze an edge may go either way: at most the pixels of the outline differ.
    EXPECT_NEAR(static_cast<double>(c.footprint), static_cast<double>(truth), 0.02 * truth);
    EXPECT_EQ(c.onValid, c.footprint);
    EXPECT_EQ(c.valid, 64u * 48u);
    EXPECT_DOUBLE_EQ(c.sidMm, 1100.0);
    EXPECT_NEAR(c.depthMm, 800.0 - 30.0, 1e-9);
    EXPECT_NEAR(c.sizeMm, std::sqrt(40.0 * 40 + 20 * 20 + 6 * 6), 1e-4);
    EXPECT_EQ(fm::blindness(c), "");
}

TEST(ModelCoverage, BlindPosesAreNamedByTheirCause) {
    const fm::ProjectionGeometry g = frontCamera();
    const fm::Mask all(64, 48, true);
    auto why = [&](const fm::SceneObject& o, const fm::Mask& valid) {
        return fm::blindness(fm::modelCoverage(o, g, valid));
    };
    // Behind the source (z = 900 > 800): nothing projects.
    const std::string behind = why(box({-20, -10, -3}, {20, 10, 3}, fm::RigidTransform::translate({0, 0, 900})), all);
    EXPECT_NE(behind.find("behind the source"), std::string::npos) << behind;
    EXPECT_NE(behind.find("covers 0 valid pixels"), std::string::npos) << behind;
    // The same box in metres: 0.04 x 0.02 x 0.006 falls between the pixel centres.
    const std::string metres = why(box({-0.02, -0.01, -0.003}, {0.02, 0.01, 0.003}, {}), all);
    EXPECT_NE(metres.find("in metres"), std::string::npos) << metres;
    // Valid pixels only in the top-left corner (an ROI beside the model).
    fm::Mask corner(64, 48, false);
    for (int r = 0; r < 8; ++r)
        for (int c = 0; c < 8; ++c) corner.inside[static_cast<std::size_t>(r) * 64 + c] = 1;
    const std::string roi = why(box({-20, -10, -3}, {20, 10, 3}, {}), corner);
    EXPECT_NE(roi.find("excluded pixels"), std::string::npos) << roi;
    // A box far larger than the field of view covers every pixel: no outline.
    const std::string whole = why(box({-500, -500, -3}, {500, 500, 3}, {}), all);
    EXPECT_NE(whole.find("covers every valid pixel"), std::string::npos) << whole;
}

}  // namespace

// Coarse volumes for coarse search levels: the factor rule, the ray spacing at a point (exact
// similar triangles) and which objects are replaced.
#include <gtest/gtest.h>

#include "drr/Drr.h"
#include "scene/CoarseVolumes.h"
#include "scene/VolumeScene.h"
#include "volume/Volume.h"

namespace {

fm::ProjectionGeometry camera(double pixelMm) {
    fm::ProjectionGeometry g;
    g.source = {0, 0, 0};
    g.detector.size = {64, 64};
    g.detector.spacing = {pixelMm, 1.5 * pixelMm};
    g.detector.u = {1, 0, 0};
    g.detector.v = {0, 1, 0};
    g.detector.origin = {-31.5 * pixelMm, -47.25 * pixelMm, 1000.0};
    return g;
}

TEST(CoarseVolumes, FactorIsTheCoarsestPowerOfTwoWithinTheRatio) {
    EXPECT_EQ(fm::coarseningFactor(2.0, 5.47, 1.25), 2);  // 4 <= 6.84 < 8
    EXPECT_EQ(fm::coarseningFactor(3.0, 5.47, 1.25), 2);  // 6 <= 6.84
    EXPECT_EQ(fm::coarseningFactor(3.0, 2.73, 1.25), 1);  // 6 > 3.42
    EXPECT_EQ(fm::coarseningFactor(0.5, 100.0, 1.0), 16);  // capped
    EXPECT_EQ(fm::coarseningFactor(1.0, 10.0, 0.0), 1);    // off
    EXPECT_EQ(fm::coarseningFactor(1.0, 0.0, 1.25), 1);    // not in front of the source
}

TEST(CoarseVolumes, RaySpacingScalesWithTheDistanceFromTheSource) {
    const fm::ProjectionGeometry g = camera(2.0);
    EXPECT_DOUBLE_EQ(fm::raySpacingAt(g, {0, 0, 500}), 1.0);   // half way: half the pitch
    EXPECT_DOUBLE_EQ(fm::raySpacingAt(g, {30, -20, 250}), 0.5);
    EXPECT_EQ(fm::raySpacingAt(g, {0, 0, -10}), 0.0);  // behind the source
}

TEST(CoarseVolumes, ReplacesVolumesOnlyWhereTheRaysAreCoarser) {
    fm::Volume v = fm::Volume::allocate({16, 16, 16}, 1.0f);
    v.spacing = {1.0, 1.0, 1.0};
    v.origin = {-7.5, -7.5, 492.5};  // centred 500 mm from the source
    fm::DrrValueOptions raw;
    raw.values = fm::DrrValues::Raw;
    const fm::Scene scene = fm::volumeScene(fm::prepareDrrVolume(v, raw));
    auto dimsOf = [](const fm::Scene& s) {
        const auto* m = dynamic_cast<const fm::VolumeXrayModel*>(s.objects[0].model.get());
        return fm::drrVolumeInfo(*m->volume()).dims;
    };
    // Rays 4 mm apart at the volume (8 mm pixels): 4 mm voxels (factor 4) fit within 1.25x.
    EXPECT_EQ(dimsOf(fm::withCoarseVolumes(scene, {camera(8.0)}, 1.25)), glm::ivec3(4));
    // The finer of two cameras counts: 1 mm rays keep the 1 mm voxels.
    EXPECT_EQ(dimsOf(fm::withCoarseVolumes(scene, {camera(8.0), camera(2.0)}, 1.25)),
              glm::ivec3(16));
    // The original scene is untouched.
    EXPECT_EQ(dimsOf(scene), glm::ivec3(16));
}

}  // namespace

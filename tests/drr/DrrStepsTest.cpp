// drrTraversalSteps: the voxel segments of the exact traversal, counted on rays whose crossings
// are known: along an axis (one per voxel) and parallel to the diagonal (every inner plane of
// every axis once).
#include <gtest/gtest.h>

#include "DrrTestUtil.h"
#include "drr/Drr.h"

namespace {

fm::ProjectionGeometry onePixel(glm::dvec3 source, glm::dvec3 target) {
    fm::ProjectionGeometry g;
    g.source = source;
    g.detector.size = {1, 1};
    g.detector.spacing = {1.0, 1.0};
    const glm::dvec3 d = glm::normalize(target - source);
    g.detector.u = glm::normalize(glm::cross(d, std::abs(d.z) < 0.9 ? glm::dvec3(0, 0, 1)
                                                                     : glm::dvec3(1, 0, 0)));
    g.detector.v = glm::cross(d, g.detector.u);
    g.detector.origin = target;
    return g;
}

TEST(DrrSteps, CountsOneStepPerVoxelEntered) {
    // Voxel centres at 0..9 (box -0.5 .. 9.5 on every axis), 1 mm.
    const fm::Volume volume = fm::test::makeVolume({10, 10, 10}, {1, 1, 1}, 1.0f);
    fm::DrrValueOptions raw;
    raw.values = fm::DrrValues::Raw;
    const fm::DrrVolumePtr v = fm::prepareDrrVolume(volume, raw);
    // Along x through the middle of a row: the 10 voxels of the row.
    EXPECT_EQ(fm::drrTraversalSteps(*v, onePixel({-50, 4.2, 3.3}, {50, 4.2, 3.3})), 10u);
    // Parallel to (1, 1, 1), offset (0.1, 0.2, 0): enters at t = -0.5 in voxel (0, 0, 0), leaves
    // at t = 9.3 in voxel (9, 9, 9): 9 inner planes per axis, 1 + 27 voxels.
    const glm::dvec3 offset(0.1, 0.2, 0.0), diagonal(1, 1, 1);
    EXPECT_EQ(fm::drrTraversalSteps(*v, onePixel(offset - 20.0 * diagonal, offset + 20.0 * diagonal)),
              28u);
    // A ray that misses the box: none.
    EXPECT_EQ(fm::drrTraversalSteps(*v, onePixel({-50, 40, 3}, {50, 40, 3})), 0u);
}

}  // namespace

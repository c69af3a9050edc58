// Autoscoper's corner frame of a volume (pose/AutoscoperVolumeFrame.h): voxel centres land at
// the corner frame's half-voxel positions for any origin and direction of the same voxels.
#include <gtest/gtest.h>

#include "pose/AutoscoperVolumeFrame.h"

namespace {

TEST(AutoscoperVolumeFrame, VoxelCentresGoToTheCornerFrame) {
    fm::Volume v = fm::Volume::allocate({6, 9, 4});
    v.spacing = {0.5, 0.25, 2.0};
    const double H = 9;
    for (int pass = 0; pass < 2; ++pass) {
        const fm::RigidTransform t = fm::autoscoperVolumeFromWorld(v);
        for (const glm::ivec3 ijk : {glm::ivec3(0, 0, 0), glm::ivec3(5, 8, 3), glm::ivec3(2, 3, 1)}) {
            const glm::dvec3 p = t.applyToPoint(v.indexToWorld(glm::dvec3(ijk)));
            EXPECT_NEAR(p.x, 0.5 * (ijk.x + 0.5), 1e-12);
            EXPECT_NEAR(p.y, 0.25 * (H - ijk.y - 0.5), 1e-12);
            EXPECT_NEAR(p.z, -2.0 * (ijk.z + 0.5), 1e-12);
        }
        // Any placement of the same voxels gives the same corner coordinates.
        v.origin = {10, -20, 5};
        v.direction = glm::dmat3(glm::dvec3(0, 1, 0), glm::dvec3(-1, 0, 0), glm::dvec3(0, 0, 1));
    }
}

}  // namespace

// The 3D view's surface (scene/DisplaySurface.h): the volume's own when it fits the cap, else the
// surface of block means, the coarsest factor that fits; the full count reported either way.
#include <gtest/gtest.h>

#include "mesh/MarchingCubes.h"
#include "scene/DisplaySurface.h"
#include "source/VolumeSource.h"
#include "volume/BlockMean.h"

namespace fm::test {
namespace {

TEST(DisplaySurface, ASurfaceOverTheCapIsDrawnFromBlockMeansUnderIt) {
    const Volume knee = loadVolume("phantom:knee");
    MarchingCubesOptions options;
    options.isoValue = 300.0;
    const Mesh full = marchingCubes(knee, options);
    ASSERT_GT(full.triangleCount(), 20000u);
    // Under the cap: the volume's own surface, unchanged.
    const app::DisplaySurface own = app::displaySurface(knee, options, full.triangleCount());
    EXPECT_EQ(own.factor, 1);
    EXPECT_EQ(own.mesh->triangleCount(), full.triangleCount());
    EXPECT_EQ(own.fullTriangles, full.triangleCount());
    // Over it: block means, under the cap, and the same surface as meshing them directly.
    const std::size_t cap = full.triangleCount() / 5;
    const app::DisplaySurface coarse = app::displaySurface(knee, options, cap);
    EXPECT_GT(coarse.factor, 1);
    EXPECT_LE(coarse.mesh->triangleCount(), cap);
    EXPECT_GT(coarse.mesh->triangleCount(), 0u);
    EXPECT_EQ(coarse.fullTriangles, full.triangleCount());
    EXPECT_EQ(coarse.mesh->triangleCount(),
              marchingCubes(blockMean(knee, coarse.factor), options).triangleCount());
}

}  // namespace
}  // namespace fm::test

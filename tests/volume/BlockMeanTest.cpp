// Block means (volume/BlockMean.h) against arithmetic done here: a linear field's block mean is
// its value at the block's centre, where the coarse voxel is placed (oblique axes, anisotropic
// spacing); blocks cut by the far faces average what they hold; factor 1 is a copy.
#include <gtest/gtest.h>

#include <cmath>

#include "core/Error.h"
#include "volume/BlockMean.h"

namespace {

fm::Volume linearField(glm::ivec3 dims) {
    fm::Volume v = fm::Volume::allocate(dims);
    v.spacing = {0.7, 1.1, 2.3};
    v.origin = {-10.0, 5.0, 30.0};
    const double c = std::cos(0.4), s = std::sin(0.4);
    v.direction = glm::dmat3(glm::dvec3(c, s, 0), glm::dvec3(-s, c, 0), glm::dvec3(0, 0, 1));
    for (int k = 0; k < dims.z; ++k)
        for (int j = 0; j < dims.y; ++j)
            for (int i = 0; i < dims.x; ++i) {
                const glm::dvec3 p = v.indexToWorld(glm::dvec3(i, j, k));
                v.at(i, j, k) = static_cast<float>(2.0 * p.x - 0.5 * p.y + 0.25 * p.z + 7.0);
            }
    return v;
}

TEST(BlockMean, ALinearFieldsBlockMeanIsItsValueWhereTheCoarseVoxelSits) {
    const fm::Volume v = linearField({12, 9, 7});
    for (int f : {2, 3}) {
        const fm::Volume b = fm::blockMean(v, f, 2);
        EXPECT_EQ(b.dims, glm::ivec3((12 + f - 1) / f, (9 + f - 1) / f, (7 + f - 1) / f));
        EXPECT_EQ(b.spacing, v.spacing * double(f));
        EXPECT_EQ(b.direction, v.direction);
        for (int K = 0; K < b.dims.z; ++K)
            for (int J = 0; J < b.dims.y; ++J)
                for (int I = 0; I < b.dims.x; ++I) {
                    const bool full = (I + 1) * f <= 12 && (J + 1) * f <= 9 && (K + 1) * f <= 7;
                    if (!full) continue;
                    const glm::dvec3 p = b.indexToWorld(glm::dvec3(I, J, K));
                    const double expected = 2.0 * p.x - 0.5 * p.y + 0.25 * p.z + 7.0;
                    EXPECT_NEAR(b.at(I, J, K), expected, 1e-4) << f << ": " << I << "," << J << "," << K;
                }
    }
}

TEST(BlockMean, PartialBlocksAverageWhatTheyHoldAndFactorOneCopies) {
    fm::Volume v = fm::Volume::allocate({5, 1, 1});
    for (int i = 0; i < 5; ++i) v.at(i, 0, 0) = float(i * i);  // 0 1 4 9 16
    const fm::Volume b = fm::blockMean(v, 2);
    ASSERT_EQ(b.dims, glm::ivec3(3, 1, 1));
    EXPECT_FLOAT_EQ(b.at(0, 0, 0), 0.5f);
    EXPECT_FLOAT_EQ(b.at(1, 0, 0), 6.5f);
    EXPECT_FLOAT_EQ(b.at(2, 0, 0), 16.0f);  // the last block holds one voxel
    EXPECT_EQ(fm::blockMean(v, 1).values, v.values);
    EXPECT_THROW(fm::blockMean(v, 0), fm::Error);
    // The same sums in the same order whatever the thread count.
    const fm::Volume big = linearField({20, 18, 16});
    EXPECT_EQ(fm::blockMean(big, 3, 1).values, fm::blockMean(big, 3, 2).values);
}

}  // namespace

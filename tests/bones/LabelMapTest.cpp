// Label maps on the CT's grid: kept when the grids agree, resampled by nearest neighbour when
// only the world geometry agrees, refused when they do not overlap or hold non-labels.
#include <gtest/gtest.h>

#include "bones/LabelMap.h"
#include "core/Error.h"
#include "test_support_bones.h"

namespace {

TEST(LabelMapTest, SameGridIsKeptWithTheCtGeometry) {
    const fm::Volume ct = fm::test::grid({8, 6, 5}, {1.0, 1.5, 2.0}, {-3.0, 4.0, 10.0});
    fm::Volume labels = ct;
    labels.values.assign(labels.values.size(), 0.0f);
    labels.at(2, 3, 4) = 7.0f;
    labels.origin.x += 1e-5;  // rounding in another tool's header
    const fm::Volume on = fm::labelsOnGrid(labels, ct, "labels");
    EXPECT_EQ(on.origin, ct.origin);
    EXPECT_EQ(on.at(2, 3, 4), 7.0f);
    EXPECT_EQ(fm::labelVoxelCounts(on).at(7), 1u);
}

TEST(LabelMapTest, CoarserMapIsResampledByNearestNeighbour) {
    // CT: 1 mm voxels 0..9 along each axis. Labels: 2 mm voxels whose centres are at 0.5, 2.5,
    // ... mm, so CT voxel x (centre x mm) lies in label voxel floor(x / 2).
    const fm::Volume ct = fm::test::grid({10, 10, 10}, {1.0, 1.0, 1.0}, {0.0, 0.0, 0.0});
    fm::Volume labels = fm::test::grid({5, 5, 5}, {2.0, 2.0, 2.0}, {0.5, 0.5, 0.5});
    for (int k = 0; k < 5; ++k)
        for (int j = 0; j < 5; ++j)
            for (int i = 0; i < 5; ++i) labels.at(i, j, k) = static_cast<float>(1 + i + 5 * j);
    const fm::Volume on = fm::labelsOnGrid(labels, ct, "labels");
    ASSERT_EQ(on.dims, ct.dims);
    for (int x : {0, 1, 2, 5, 8, 9})
        for (int y : {0, 3, 9}) EXPECT_EQ(on.at(x, y, 4), 1 + x / 2 + 5 * (y / 2)) << x << "," << y;
}

TEST(LabelMapTest, PartialOverlapLeavesTheRestBackground) {
    const fm::Volume ct = fm::test::grid({10, 4, 4}, {1.0, 1.0, 1.0}, {0.0, 0.0, 0.0});
    fm::Volume labels = fm::test::grid({3, 4, 4}, {1.0, 1.0, 1.0}, {7.0, 0.0, 0.0});
    labels.values.assign(labels.values.size(), 3.0f);
    const fm::Volume on = fm::labelsOnGrid(labels, ct, "labels");
    EXPECT_EQ(on.at(6, 1, 1), 0.0f);
    EXPECT_EQ(on.at(7, 1, 1), 3.0f);
    EXPECT_EQ(on.at(9, 1, 1), 3.0f);
}

TEST(LabelMapTest, RefusesDisjointGridsAndNonLabels) {
    const fm::Volume ct = fm::test::grid({10, 10, 10}, {1.0, 1.0, 1.0}, {0.0, 0.0, 0.0});
    fm::Volume far = fm::test::grid({10, 10, 10}, {1.0, 1.0, 1.0}, {500.0, 0.0, 0.0});
    try {
        fm::labelsOnGrid(far, ct, "label map seg.nii.gz");
        FAIL() << "disjoint grids accepted";
    } catch (const fm::Error& e) {
        EXPECT_NE(std::string(e.what()).find("seg.nii.gz"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("cannot be resampled"), std::string::npos);
    }
    fm::Volume fractional = ct;
    fractional.at(1, 1, 1) = 2.5f;
    EXPECT_THROW(fm::labelsOnGrid(fractional, ct, "labels"), fm::Error);
    fm::Volume negative = ct;
    negative.at(1, 1, 1) = -1.0f;
    EXPECT_THROW(fm::labelsOnGrid(negative, ct, "labels"), fm::Error);
    EXPECT_THROW(fm::loadLabelMap("/nonexistent/seg.nii.gz", ct), fm::Error);
}

}  // namespace

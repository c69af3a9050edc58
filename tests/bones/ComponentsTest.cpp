// Bones without a label map: threshold + connected components, and seeded region growing.
#include <map>
#include <set>

#include <gtest/gtest.h>

#include <cmath>

#include "bones/ConnectedComponents.h"
#include "bones/LabelMap.h"
#include "bones/RegionGrow.h"
#include "core/Error.h"
#include "phantom/KneePhantom.h"
#include "test_support_bones.h"

namespace {

TEST(ConnectedComponents, SeparatesPiecesRankedBySize) {
    fm::Volume ct = fm::test::grid({16, 10, 10}, {1.0, 1.0, 1.0}, {0.0, 0.0, 0.0}, -1000.0f);
    fm::test::fillBox(ct, {1, 1, 1}, {3, 3, 3}, 500.0f);    // 27 voxels
    fm::test::fillBox(ct, {6, 1, 1}, {12, 4, 4}, 800.0f);   // 112 voxels
    fm::test::fillBox(ct, {14, 8, 8}, {14, 8, 8}, 400.0f);  // 1 voxel
    // Touching only along an edge (diagonal): not face-connected, so a piece of its own.
    fm::test::fillBox(ct, {4, 4, 1}, {4, 4, 1}, 400.0f);
    const fm::Volume labels = fm::labelConnectedComponents(ct, {.threshold = 300.0});
    const auto counts = fm::labelVoxelCounts(labels);
    EXPECT_EQ(counts.at(1), 112u);
    EXPECT_EQ(counts.at(2), 27u);
    EXPECT_EQ(counts.at(3), 1u);  // (4,4,1) comes first in storage order
    EXPECT_EQ(counts.at(4), 1u);
    EXPECT_EQ(labels.at(4, 4, 1), 3.0f);
    EXPECT_EQ(labels.at(14, 8, 8), 4.0f);
    const fm::Volume big = fm::labelConnectedComponents(ct, {.threshold = 300.0, .minVoxels = 2});
    EXPECT_EQ(fm::labelVoxelCounts(big).size(), 3u);  // background and two pieces
    EXPECT_EQ(fm::componentLabelTable(big).find("component 2")->label, 2);
    EXPECT_THROW(fm::labelConnectedComponents(ct, {.maxComponents = 0}), fm::Error);
}

TEST(ConnectedComponents, KneePhantomFallsApartIntoItsFourBones) {
    fm::KneePhantomParams p;
    p.dims = {96, 96, 106};
    const fm::Volume ct = fm::makeKneePhantom(p);
    const fm::Volume truth = fm::makeKneeBoneLabels(p);
    const fm::Volume labels = fm::labelConnectedComponents(ct, {.threshold = 300.0, .minVoxels = 50});
    const auto counts = fm::labelVoxelCounts(labels);
    ASSERT_EQ(counts.size(), 5u) << "background + femur, tibia, fibula, patella";
    // Each component lies inside exactly one true bone, and the four bones differ.
    std::map<int, std::set<int>> boneOf;
    for (std::size_t n = 0; n < labels.values.size(); ++n)
        if (labels.values[n] != 0.0f)
            boneOf[int(labels.values[n])].insert(int(truth.values[n]));
    std::set<int> bones;
    for (const auto& [component, owners] : boneOf) {
        ASSERT_EQ(owners.size(), 1u) << "component " << component;
        EXPECT_NE(*owners.begin(), 0);
        bones.insert(*owners.begin());
    }
    EXPECT_EQ(bones.size(), 4u);
    // Sizes: femur and tibia the largest, the patella the smallest.
    const std::set<int> largestTwo{*boneOf[1].begin(), *boneOf[2].begin()};
    EXPECT_EQ(largestTwo, (std::set<int>{1, 2}));
}

TEST(RegionGrow, GrowsTheClickedPieceOnly) {
    fm::Volume ct = fm::test::grid({16, 10, 10}, {1.0, 1.0, 1.0}, {0.0, 0.0, 0.0}, -1000.0f);
    fm::test::fillBox(ct, {1, 1, 1}, {3, 3, 3}, 500.0f);
    fm::test::fillBox(ct, {6, 1, 1}, {12, 4, 4}, 800.0f);
    fm::test::fillBox(ct, {4, 2, 2}, {5, 2, 2}, 350.0f);  // a bridge at 350 HU
    const fm::Volume a = fm::regionGrow(ct, {2, 2, 2}, {.lower = 400.0});
    EXPECT_EQ(fm::labelVoxelCounts(a).at(1), 27u);
    const fm::Volume ab = fm::regionGrow(ct, {2, 2, 2}, {.lower = 300.0});
    EXPECT_EQ(fm::labelVoxelCounts(ab).at(1), 27u + 112u + 2u);
    const fm::Volume band = fm::regionGrow(ct, {8, 2, 2}, {.lower = 700.0, .upper = 900.0});
    EXPECT_EQ(fm::labelVoxelCounts(band).at(1), 112u);
    EXPECT_THROW(fm::regionGrow(ct, {0, 0, 0}), fm::Error);    // soft tissue / air
    EXPECT_THROW(fm::regionGrow(ct, {16, 0, 0}), fm::Error);   // outside
    EXPECT_THROW(fm::regionGrow(ct, {2, 2, 2}, {.lower = 10.0, .upper = 5.0}), fm::Error);
    EXPECT_EQ(fm::nearestVoxel(ct, {2.4, 1.6, 7.0}), glm::ivec3(2, 2, 7));
}

TEST(RegionGrow, TheFirstBoneVoxelAlongARayIsWhereItEntersTheBone) {
    fm::Volume ct = fm::test::grid({16, 10, 10}, {1.0, 1.0, 1.0}, {0.0, 0.0, 0.0}, -1000.0f);
    fm::test::fillBox(ct, {1, 1, 1}, {3, 3, 3}, 500.0f);
    fm::test::fillBox(ct, {6, 1, 1}, {12, 4, 4}, 800.0f);
    // Along +x through row (y, z) = (2, 2): the first box from the left, the second from the
    // right; voxel centres are at whole mm, a voxel spans +-0.5 mm.
    EXPECT_EQ(fm::firstVoxelAlong(ct, {-5.0, 2.0, 2.0}, {20.0, 2.0, 2.0}, 300.0),
              glm::ivec3(1, 2, 2));
    EXPECT_EQ(fm::firstVoxelAlong(ct, {20.0, 2.0, 2.0}, {-5.0, 2.0, 2.0}, 300.0),
              glm::ivec3(12, 2, 2));
    EXPECT_EQ(fm::firstVoxelAlong(ct, {-5.0, 2.0, 2.0}, {20.0, 2.0, 2.0}, 600.0),
              glm::ivec3(6, 2, 2)) << "the first box is below this level";
    // Obliquely through both boxes' gap at y = 8 nothing is bone; outside the volume neither.
    EXPECT_FALSE(fm::firstVoxelAlong(ct, {-5.0, 8.0, 2.0}, {20.0, 8.0, 8.0}, 300.0));
    EXPECT_FALSE(fm::firstVoxelAlong(ct, {-5.0, 50.0, 2.0}, {20.0, 50.0, 2.0}, 300.0));
    EXPECT_THROW(fm::firstVoxelAlong(ct, {NAN, 0, 0}, {1, 1, 1}, 300.0), fm::Error);
    // The seed grows into the whole box.
    const auto seed = fm::firstVoxelAlong(ct, {2.0, -3.0, 2.0}, {2.0, 20.0, 2.0}, 300.0);
    ASSERT_TRUE(seed);
    EXPECT_EQ(fm::labelVoxelCounts(fm::regionGrow(ct, *seed)).at(1), 27u);
}

}  // namespace

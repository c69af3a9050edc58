// The BVH: every triangle in exactly one leaf, every node's box holding its triangles, the
// same tree for the same mesh, bounded depth on degenerate input.
#include <gtest/gtest.h>

#include <algorithm>

#include "common/TestMeshes.h"
#include "meshdrr/MeshBvh.h"

namespace {

// Checks the subtree at `node` and returns how many triangle slots it covers.
std::size_t checkNode(const fm::MeshBvh& bvh, std::uint32_t node, std::vector<int>& seen) {
    const fm::MeshBvh::Node& n = bvh.nodes.at(node);
    if (n.count > 0) {
        for (std::uint32_t s = n.first; s < n.first + n.count; ++s) {
            ++seen.at(s);
            for (int k = 0; k < 3; ++k) {
                const glm::dvec3 c = bvh.corners[3 * s + k];
                EXPECT_TRUE(glm::all(glm::lessThanEqual(n.lo, c)) && glm::all(glm::lessThanEqual(c, n.hi)));
            }
        }
        return n.count;
    }
    const fm::MeshBvh::Node &left = bvh.nodes.at(node + 1), &right = bvh.nodes.at(n.first);
    for (const auto* child : {&left, &right}) {
        EXPECT_TRUE(glm::all(glm::lessThanEqual(n.lo, child->lo)));
        EXPECT_TRUE(glm::all(glm::lessThanEqual(child->hi, n.hi)));
    }
    return checkNode(bvh, node + 1, seen) + checkNode(bvh, n.first, seen);
}

TEST(MeshBvh, CoversEveryTriangleOnceAndIsDeterministic) {
    const fm::Mesh mesh = fm::test::mergeMeshes(fm::test::uvSphereMesh({0, 0, 0}, 10.f, 24, 48),
                                                fm::test::squareFrameMesh(30.f, 20.f, -2.f, 2.f));
    const fm::MeshBvh bvh = fm::buildMeshBvh(mesh);
    std::vector<int> seen(mesh.triangles.size(), 0);
    EXPECT_EQ(checkNode(bvh, 0, seen), mesh.triangles.size());
    EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int c) { return c == 1; }));
    std::vector<std::uint32_t> slots = bvh.triangleOfSlot;
    std::sort(slots.begin(), slots.end());
    for (std::size_t i = 0; i < slots.size(); ++i) ASSERT_EQ(slots[i], i);
    const fm::MeshBvh again = fm::buildMeshBvh(mesh);
    ASSERT_EQ(again.nodes.size(), bvh.nodes.size());
    EXPECT_EQ(again.triangleOfSlot, bvh.triangleOfSlot);
    for (std::size_t i = 0; i < bvh.nodes.size(); ++i) {
        EXPECT_EQ(again.nodes[i].first, bvh.nodes[i].first);
        EXPECT_EQ(again.nodes[i].count, bvh.nodes[i].count);
    }
    EXPECT_LT(bvh.depth, 30);
}

TEST(MeshBvh, CoincidentCentroidsStayShallow) {
    // 5000 copies of one triangle: no split separates them; halves by index keep depth ~log2.
    fm::Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    for (int i = 0; i < 5000; ++i) m.triangles.push_back(glm::uvec3(0, 1, 2));
    const fm::MeshBvh bvh = fm::buildMeshBvh(m);
    std::vector<int> seen(m.triangles.size(), 0);
    EXPECT_EQ(checkNode(bvh, 0, seen), m.triangles.size());
    EXPECT_LE(bvh.depth, 16);
}

}  // namespace

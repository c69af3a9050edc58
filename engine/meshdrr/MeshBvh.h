#pragma once
// A bounding-volume hierarchy over a mesh's triangles, for ray casting (meshdrr/MeshRayCast.h).
// Built once per mesh, deterministically (same mesh, same tree): binned surface-area heuristic
// (16 bins on the axis of largest centroid spread, leaves of at most 4 triangles unless
// splitting does not pay), a median split by index when all centroids coincide or the tree gets
// deeper than 48 levels (so depth stays bounded on any input).
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "mesh/Mesh.h"

namespace fm {

struct MeshBvh {
    struct Node {
        glm::dvec3 lo, hi;        // exact bounds of the triangles below (no padding)
        std::uint32_t first = 0;  // leaf: first triangle slot; inner: index of the right child
        std::uint32_t count = 0;  // leaf: triangles in it (> 0); inner: 0 (left child = this + 1)
    };
    std::vector<Node> nodes;  // nodes[0] is the root
    // The triangles' corners in leaf order, three per slot, in double (exactly the mesh's float
    // positions): a vertex shared by several triangles has the same value in each, which the
    // watertight test needs.
    std::vector<glm::dvec3> corners;
    std::vector<std::uint32_t> triangleOfSlot;  // slot -> index in the mesh
    int depth = 0;

    std::size_t triangleCount() const { return triangleOfSlot.size(); }
};

// Throws fm::Error for an empty mesh or indices out of range.
MeshBvh buildMeshBvh(const Mesh& mesh);

}  // namespace fm

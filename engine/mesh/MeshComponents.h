#pragma once
// Connected components of a triangle mesh: label them, keep the largest N or pick one
// (the 2011 wish list: "femur only", "tibia only").
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "mesh/Mesh.h"

namespace fm {

// Triangles sharing a vertex are connected. Fills mesh.component with ranks: 0 = the component
// with the most triangles; ties go to the component whose first triangle comes first.
// Returns the number of components. `threads` (0 = all cores) changes the speed, not the labels.
std::size_t labelComponents(Mesh& mesh, int threads = 1);

// The same labels from a finished forest (mesh/VertexForest.h) over the mesh's vertices in which
// the vertices of every triangle are united: marching cubes builds it while it writes the
// triangles. `parent` (one entry per vertex) is overwritten.
std::size_t labelComponentsFromForest(Mesh& mesh, std::uint32_t* parent, int threads);

// The number of sets of a finished forest over `vertexCount` vertices: the mesh's components
// when every vertex lies on a triangle, as marching cubes' vertices do.
std::size_t countForestRoots(const std::uint32_t* parent, std::size_t vertexCount, int threads);

// Triangles per component rank (needs mesh.component).
std::vector<std::size_t> componentSizes(const Mesh& mesh);

// Keeps the triangles whose rank has keep[rank] true, drops the vertices no longer used
// (order preserved). Needs mesh.component; ranks are left as they were.
void keepComponents(Mesh& mesh, const std::vector<bool>& keep, int threads = 1);

// Keeps the `count` largest components (count <= 0 keeps all).
void keepLargestComponents(Mesh& mesh, int count, int threads = 1);

// Rank of the component owning the vertex nearest to `world` (needs mesh.component and a
// non-empty mesh).
std::uint32_t componentNearest(const Mesh& mesh, const glm::dvec3& world);

}  // namespace fm

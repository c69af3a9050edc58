#pragma once
// Merging vertices that sit at the same place, so that triangles share them (STL repeats every
// facet's vertices; a closed-surface check needs shared edges).
#include <cstddef>

#include "mesh/Mesh.h"

namespace fm {

struct WeldReport {
    std::size_t verticesBefore = 0;
    std::size_t verticesAfter = 0;
    std::size_t collapsedTriangles = 0;  // two or three corners became one vertex: dropped
};

// Vertices at exactly the same position (toleranceMm = 0), or within toleranceMm of each other
// in every coordinate (Chebyshev distance; each vertex joins the first earlier kept vertex
// within reach, so the result depends only on the input order), become one: the first one in
// file order, at its position. Unused vertices are dropped, triangles that collapse are
// removed, normals are cleared (recompute them if needed). Throws fm::Error for a negative or
// non-finite tolerance.
Mesh weldVertices(const Mesh& mesh, double toleranceMm = 0.0, WeldReport* report = nullptr);

}  // namespace fm

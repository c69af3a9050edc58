#pragma once
// Independent checks of a triangle mesh through CGAL (implemented in cgal/MeshCheck.cpp, the
// only CGAL translation unit; link fm_meshcheck). This header is CGAL-free.
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "mesh/Mesh.h"

namespace fm {

struct MeshCheckReport {
    bool isPolygonMesh = false;  // CGAL accepts the soup as an oriented 2-manifold (with boundary)
    bool closed = false;         // no border edges
    bool manifold = false;       // every edge has exactly two triangles, no pinched vertices
    bool selfIntersecting = true;  // checked only for polygon meshes
    bool outwardOriented = false;  // checked only on closed, non-self-intersecting meshes
    bool boundsVolume = false;     //   "
    long eulerCharacteristic = 0;  // V - E + F
    double volume = 0.0;           // mm^3 (signed: positive when outward oriented)
    double area = 0.0;             // mm^2
    std::size_t components = 0;
    std::size_t degenerateTriangles = 0;  // zero area (collinear or repeated vertices)
    std::size_t duplicateVertices = 0;    // vertices at the same position as an earlier one
    std::size_t unusedVertices = 0;
    std::size_t nonManifoldEdges = 0;  // edges with other than two triangles
    bool validIndices = false;

    // Closed, manifold, no self-intersection, outward, bounds a volume, no degenerate
    // triangle, no duplicate vertex.
    bool watertight() const;
    std::string summary() const;
};

// `checkSelfIntersection = false` skips the slowest check (then selfIntersecting stays true
// and the orientation checks are not run).
MeshCheckReport checkMesh(const Mesh& mesh, bool checkSelfIntersection = true);

// Diagnostics: the pairs of triangles (indices) that intersect other than along a shared edge
// or vertex. Needs a mesh that CGAL accepts as a polygon mesh (else returns nothing).
std::vector<std::pair<std::size_t, std::size_t>> selfIntersections(const Mesh& mesh);

}  // namespace fm

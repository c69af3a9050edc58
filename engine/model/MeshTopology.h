#pragma once
// What a model's triangles enclose: closedness (every edge shared by exactly two triangles
// that traverse it in opposite directions), signed volume, area and bounds. A line integral
// through a mesh is only defined when the surface is closed.
#include <cstddef>
#include <string>

#include <glm/glm.hpp>

#include "mesh/Mesh.h"

namespace fm {

struct MeshTopology {
    std::size_t edges = 0;              // distinct undirected edges
    std::size_t boundaryEdges = 0;      // used by one triangle only (a hole's rim)
    std::size_t nonManifoldEdges = 0;   // used by three or more triangles
    std::size_t misorientedEdges = 0;   // used by two triangles in the same direction
    double signedVolume = 0.0;          // mm^3, positive when the winding is outward
    double area = 0.0;                  // mm^2
    glm::dvec3 boundsMin{0.0}, boundsMax{0.0};

    // Every edge shared by exactly two triangles with opposite orientation.
    bool closed() const { return boundaryEdges == 0 && nonManifoldEdges == 0 && misorientedEdges == 0; }
    // "12 boundary edges, 0 non-manifold, 0 misoriented" (for messages).
    std::string edgeSummary() const;
};

// Needs welded vertices (shared indices) and valid indices (throws fm::Error otherwise).
MeshTopology analyseMesh(const Mesh& mesh);

}  // namespace fm

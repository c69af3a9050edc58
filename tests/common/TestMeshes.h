#pragma once
// Closed, outward test meshes with known geometry (boxes, UV spheres, cylinders, a square
// frame with a hole) for the model readers and the mesh DRR tests.
#include <glm/glm.hpp>

#include "mesh/Mesh.h"

namespace fm::test {

// Axis-aligned box [lo, hi]: 8 vertices, 12 triangles, outward.
Mesh boxMesh(const glm::vec3& lo, const glm::vec3& hi);
// UV sphere: `rings` latitude bands (poles are single vertices), `segments` longitudes;
// vertices on the sphere of `radius` around `center`.
// `planarQuads`: radii, heights and cos/sin rounded to multiples of 1/64 and 1/4096 so that
// every product is an exact float: each quad is then exactly planar and the polyhedron exactly
// convex (its vertices are off the sphere by up to ~1e-2 mm). `center` must then be a
// multiple of 1/64 below 16 mm.
Mesh uvSphereMesh(const glm::vec3& center, float radius, int rings, int segments,
                  bool planarQuads = false);
// Cylinder along z from z0 to z1 with `segments` sides (vertices on the circle), capped by fans
// around a centre vertex.
Mesh cylinderMesh(float radius, float z0, float z1, int segments);
// The square frame [-outer, outer]^2 x [z0, z1] minus the hole [-inner, inner]^2 x [z0, z1]:
// a closed surface of genus 1 (32 triangles), not convex.
Mesh squareFrameMesh(float outer, float inner, float z0, float z1);
// Both meshes in one (indices of `b` shifted).
Mesh mergeMeshes(const Mesh& a, const Mesh& b);
// Reverses every triangle's winding.
Mesh flippedMesh(const Mesh& m);

}  // namespace fm::test

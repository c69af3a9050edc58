#pragma once
// The watertight ray-triangle test of Woop, Benthin and Wald, "Watertight Ray/Triangle
// Intersection", JCGT 2(1), 2013, in double, with an exact tie rule so that a ray through a
// shared edge or vertex of a closed mesh crosses the surface exactly once.
//
// Per ray: kz = the axis of largest |d|, kx = kz+1, ky = kx+1 (mod 3), kx and ky swapped when
// d[kz] < 0 (keeps the frame right-handed); the shear (Sx, Sy, Sz) = (d[kx], d[ky], 1)/d[kz]
// maps the ray onto +z. Per triangle ABC: the corners relative to the origin are sheared to 2D
// (the same arithmetic for every corner, so a shared vertex lands at the same point for every
// triangle), and the edge functions U (B->C), V (C->A), W (A->B) are 2D cross products. An
// edge function computed as 0 is recomputed exactly (products split into value + error by FMA;
// the paper recomputes float in double for the same end): every sign is then exact for the
// sheared corners, and a shared edge gets exactly opposite values in its two triangles.
// The triangle is hit when all signs agree; t = (U Az + V Bz + W Cz) / (U + V + W).
//
// Tie rule (an edge function exactly 0: the ray passes exactly through the edge or a vertex):
// decided as if the ray were moved by (eps, eps^2) in the sheared plane, eps -> 0. For a
// triangle of orientation s (the sign of U + V + W) an edge P->Q with value 0 counts as inside
// when s (Q - P) has y > 0, or y = 0 and x < 0. One rule for every triangle and the same exact
// values give: each crossing counted once at shared edges and vertices; a ray grazing the
// silhouette either hits both sides or neither (they cancel); nothing between triangles.
//
// Orientation: det = U + V + W > 0 when the ray enters through the triangle's front (the side
// its counter-clockwise winding faces; outward for an outward mesh), < 0 when it leaves.
#include <glm/glm.hpp>

namespace fm {

struct WatertightRay {
    glm::dvec3 origin;
    glm::dvec3 dir;  // not normalised: t is in units of dir
    int kx = 0, ky = 1, kz = 2;
    double sx = 0.0, sy = 0.0, sz = 1.0;
};

// `dir` must not be zero.
WatertightRay makeWatertightRay(const glm::dvec3& origin, const glm::dvec3& dir);

struct TriangleHit {
    double t = 0.0;     // origin + t dir is the crossing (t >= 0)
    bool entering = false;  // through the front face (det > 0)
};

// The hit of the ray (t >= 0 only) with triangle abc, or false.
bool intersectTriangle(const WatertightRay& ray, const glm::dvec3& a, const glm::dvec3& b,
                       const glm::dvec3& c, TriangleHit& hit);

}  // namespace fm

#pragma once
// Independent chord lengths for the mesh DRR tests, computed without any ray-triangle test:
// slab clipping for axis-aligned boxes and half-space clipping (Cyrus-Beck) against the face
// planes of a convex mesh, in long double.
#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

#include "mesh/Mesh.h"

namespace fm::test {

using LVec = long double[3];

// Length of the segment s -> e inside the box [lo, hi] (mm).
inline double boxChord(const glm::dvec3& lo, const glm::dvec3& hi, const glm::dvec3& s,
                       const glm::dvec3& e) {
    long double t0 = 0.0L, t1 = 1.0L;
    for (int a = 0; a < 3; ++a) {
        const long double d = (long double)e[a] - s[a];
        if (d == 0.0L) {
            if (s[a] < lo[a] || s[a] > hi[a]) return 0.0;
            continue;
        }
        long double u = (lo[a] - (long double)s[a]) / d, v = (hi[a] - (long double)s[a]) / d;
        if (u > v) std::swap(u, v);
        t0 = std::max(t0, u);
        t1 = std::min(t1, v);
    }
    if (t1 <= t0) return 0.0;
    long double len2 = 0;
    for (int a = 0; a < 3; ++a) len2 += ((long double)e[a] - s[a]) * ((long double)e[a] - s[a]);
    return double((t1 - t0) * std::sqrt(len2));
}

// Length of s -> e inside the intersection of the inner half-spaces of every face plane of
// an outward mesh: the polyhedron itself when the mesh is convex.
inline double convexChord(const Mesh& m, const glm::dvec3& s, const glm::dvec3& e) {
    long double t0 = 0.0L, t1 = 1.0L;
    long double d[3], len2 = 0;
    for (int a = 0; a < 3; ++a) {
        d[a] = (long double)e[a] - s[a];
        len2 += d[a] * d[a];
    }
    for (const auto& tri : m.triangles) {
        long double p[3][3];
        for (int k = 0; k < 3; ++k)
            for (int a = 0; a < 3; ++a) p[k][a] = m.positions[tri[k]][a];
        long double u[3], v[3], n[3];
        for (int a = 0; a < 3; ++a) {
            u[a] = p[1][a] - p[0][a];
            v[a] = p[2][a] - p[0][a];
        }
        n[0] = u[1] * v[2] - u[2] * v[1];
        n[1] = u[2] * v[0] - u[0] * v[2];
        n[2] = u[0] * v[1] - u[1] * v[0];
        long double f0 = 0, f1 = 0;  // inside: f0 + t f1 <= 0
        for (int a = 0; a < 3; ++a) {
            f0 += n[a] * ((long double)s[a] - p[0][a]);
            f1 += n[a] * d[a];
        }
        if (f1 == 0.0L) {
            if (f0 > 0.0L) return 0.0;
            continue;
        }
        const long double t = -f0 / f1;
        if (f1 > 0.0L)
            t1 = std::min(t1, t);
        else
            t0 = std::max(t0, t);
    }
    return t1 > t0 ? double((t1 - t0) * std::sqrt(len2)) : 0.0;
}

}  // namespace fm::test

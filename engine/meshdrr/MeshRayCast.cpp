#include "meshdrr/MeshRayCast.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "meshdrr/WatertightTriangle.h"

namespace fm {
namespace {

// A box test may only err on the side of visiting: the far parameter is widened by far more
// than the rounding of the slab arithmetic (a few ulps), and an axis along which the ray
// barely moves is tested as parallel with a margin.
constexpr double kFarWiden = 1e-12;
constexpr double kParallelLimit = 1e-200;
constexpr int kStackSize = 128;  // > the BVH's bounded depth (48 + log2 of the triangle count)

struct BoxRay {
    glm::dvec3 origin, invDir;
    bool parallel[3];
};

inline bool hitsBox(const BoxRay& r, const MeshBvh::Node& n) {
    double tNear = 0.0, tFar = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a) {
        if (r.parallel[a]) {
            const double margin = 1e-9 * (1.0 + std::abs(r.origin[a]));
            if (r.origin[a] < n.lo[a] - margin || r.origin[a] > n.hi[a] + margin) return false;
            continue;
        }
        double t0 = (n.lo[a] - r.origin[a]) * r.invDir[a];
        double t1 = (n.hi[a] - r.origin[a]) * r.invDir[a];
        if (t0 > t1) std::swap(t0, t1);
        tNear = std::max(tNear, t0);
        tFar = std::min(tFar, t1);
    }
    return tNear <= tFar + std::abs(tFar) * kFarWiden;
}

}  // namespace

RayCrossings castRay(const MeshBvh& bvh, const glm::dvec3& origin, const glm::dvec3& dir) {
    const WatertightRay ray = makeWatertightRay(origin, dir);
    BoxRay box;
    box.origin = origin;
    for (int a = 0; a < 3; ++a) {
        box.parallel[a] = std::abs(dir[a]) < kParallelLimit;
        box.invDir[a] = box.parallel[a] ? 0.0 : 1.0 / dir[a];
    }
    RayCrossings out;
    std::uint32_t stack[kStackSize];
    int top = 0;
    std::uint32_t node = 0;
    for (;;) {
        const MeshBvh::Node& n = bvh.nodes[node];
        if (hitsBox(box, n)) {
            if (n.count == 0) {
                stack[top++] = n.first;  // right child later
                node = node + 1;         // left child now
                continue;
            }
            for (std::uint32_t s = n.first; s < n.first + n.count; ++s) {
                TriangleHit hit;
                const glm::dvec3* c = &bvh.corners[3 * std::size_t(s)];
                if (!intersectTriangle(ray, c[0], c[1], c[2], hit)) continue;
                const double clamped = std::min(hit.t, 1.0);
                out.signedParameter += hit.entering ? -clamped : clamped;
                if (hit.t <= 1.0) ++out.hitsInSegment;
            }
        }
        if (top == 0) break;
        node = stack[--top];
    }
    return out;
}

}  // namespace fm

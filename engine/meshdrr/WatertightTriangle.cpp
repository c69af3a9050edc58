// Compiled with -ffp-contract=off (engine/CMakeLists.txt): a fused multiply-add in one corner's
// shear and not in another's would break the bit-identical shared values the test relies on.
#include "meshdrr/WatertightTriangle.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace fm {
namespace {

// Sign of qx*py - qy*px, exact. `fast` is that value rounded; when it is not 0 its sign is
// already right (rounding is monotonic); when it is 0 the two rounded products are equal and
// the sign is that of the difference of their exact rounding errors (FMA gives them exactly).
inline int edgeSign(double qx, double py, double qy, double px, double fast) {
    if (fast > 0.0) return 1;
    if (fast < 0.0) return -1;
    const double p1 = qx * py, p2 = qy * px;
    const double e = std::fma(qx, py, -p1) - std::fma(qy, px, -p2);
    return (e > 0.0) - (e < 0.0);
}

// The tie rule for an edge P->Q of a triangle of orientation s whose edge function is 0.
inline bool ownsEdge(int s, double px, double py, double qx, double qy) {
    double dx = qx - px, dy = qy - py;
    if (s < 0) {
        dx = -dx;
        dy = -dy;
    }
    return dy > 0.0 || (dy == 0.0 && dx < 0.0);
}

}  // namespace

WatertightRay makeWatertightRay(const glm::dvec3& origin, const glm::dvec3& dir) {
    WatertightRay r;
    r.origin = origin;
    r.dir = dir;
    const glm::dvec3 m = glm::abs(dir);
    r.kz = m.x >= m.y ? (m.x >= m.z ? 0 : 2) : (m.y >= m.z ? 1 : 2);
    r.kx = (r.kz + 1) % 3;
    r.ky = (r.kx + 1) % 3;
    if (dir[r.kz] < 0.0) std::swap(r.kx, r.ky);
    r.sx = dir[r.kx] / dir[r.kz];
    r.sy = dir[r.ky] / dir[r.kz];
    r.sz = 1.0 / dir[r.kz];
    return r;
}

bool intersectTriangle(const WatertightRay& r, const glm::dvec3& a, const glm::dvec3& b,
                       const glm::dvec3& c, TriangleHit& hit) {
    const glm::dvec3 A = a - r.origin, B = b - r.origin, C = c - r.origin;
    const double ax = A[r.kx] - r.sx * A[r.kz], ay = A[r.ky] - r.sy * A[r.kz];
    const double bx = B[r.kx] - r.sx * B[r.kz], by = B[r.ky] - r.sy * B[r.kz];
    const double cx = C[r.kx] - r.sx * C[r.kz], cy = C[r.ky] - r.sy * C[r.kz];
    // Edge P->Q: Qx Py - Qy Px (the same expression for every edge, so a shared edge traversed
    // the other way gives exactly the negated value).
    const double U = cx * by - cy * bx;  // B->C
    const double V = ax * cy - ay * cx;  // C->A
    const double W = bx * ay - by * ax;  // A->B
    const int su = edgeSign(cx, by, cy, bx, U);
    const int sv = edgeSign(ax, cy, ay, cx, V);
    const int sw = edgeSign(bx, ay, by, ax, W);
    if ((su < 0 || sv < 0 || sw < 0) && (su > 0 || sv > 0 || sw > 0)) return false;
    const int sum = su + sv + sw;
    if (sum == 0) return false;  // all three 0: the triangle is seen edge-on
    const int s = sum > 0 ? 1 : -1;
    if (su == 0 && !ownsEdge(s, bx, by, cx, cy)) return false;
    if (sv == 0 && !ownsEdge(s, cx, cy, ax, ay)) return false;
    if (sw == 0 && !ownsEdge(s, ax, ay, bx, by)) return false;
    const double az = r.sz * A[r.kz], bz = r.sz * B[r.kz], cz = r.sz * C[r.kz];
    const double T = U * az + V * bz + W * cz;
    if (s > 0 ? T < 0.0 : T > 0.0) return false;  // behind the origin
    const double det = U + V + W;
    // det is 0 only when every edge function rounded to 0 while their exact signs agree: a
    // sliver of ~1e-300 mm^2 around the ray; its depth is then that of its corners.
    hit.t = det != 0.0 ? T / det : std::max(0.0, (az + bz + cz) / 3.0);
    hit.entering = s > 0;
    return true;
}

}  // namespace fm

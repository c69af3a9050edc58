#include "mesh/MarchingCubesTable.h"

#include <stdexcept>
#include <vector>

#include <glm/glm.hpp>

namespace fm::mc {
namespace {

glm::dvec3 cornerPosition(int c) {
    return glm::dvec3(c & 1, (c >> 1) & 1, (c >> 2) & 1);
}

// The two axes other than `axis`, lower first.
void otherAxes(int axis, int& u, int& w) {
    u = axis == 0 ? 1 : 0;
    w = axis == 2 ? 1 : 2;
}

int cornerOf(int axis, int offsetAlongAxis, int u, int uOffset, int w, int wOffset) {
    return (offsetAlongAxis << axis) | (uOffset << u) | (wOffset << w);
}

int edgeBetween(int c0, int c1) {
    const int diff = c0 ^ c1;
    const int axis = diff == 1 ? 0 : diff == 2 ? 1 : 2;
    int u, w;
    otherAxes(axis, u, w);
    return axis * 4 + ((c0 >> u) & 1) + 2 * ((c0 >> w) & 1);
}

glm::dvec3 edgeMidpoint(int e) {
    return 0.5 * (cornerPosition(edgeCorner(e, 0)) + cornerPosition(edgeCorner(e, 1)));
}

bool shareFace(int a, int b) {
    for (int f = 0; f < 6; ++f)
        if (edgeOnFace(a, f) && edgeOnFace(b, f)) return true;
    return false;
}

// A fan from loop[apex] over the rest of the loop, if no fan chord joins two points on a
// common cube face. Such a fan cannot cross itself: apart from the two segments at the apex,
// the loop then runs on faces that do not hold the apex, and rays from a point of a convex
// surface meet the rest of that surface at most once, so the fan's triangles (cones from the
// apex over loop segments) overlap only along their shared chords.
bool fanTriangulation(const std::vector<int>& loop, int apex,
                      std::vector<std::array<int, 3>>& out) {
    const int n = static_cast<int>(loop.size());
    for (int k = 2; k <= n - 2; ++k)
        if (shareFace(loop[apex], loop[(apex + k) % n])) return false;
    for (int k = 1; k + 1 < n; ++k)
        out.push_back({loop[apex], loop[(apex + k) % n], loop[(apex + k + 1) % n]});
    return true;
}

CubeCase buildCase(int caseIndex) {
    const auto inside = [&](int c) { return ((caseIndex >> c) & 1) != 0; };
    CubeCase result;
    for (int e = 0; e < 12; ++e)
        if (inside(edgeCorner(e, 0)) != inside(edgeCorner(e, 1))) result.edgeMask |= 1 << e;

    // Directed segments on the faces: next[e] is the edge point that follows e in its loop.
    std::array<int, 12> next;
    next.fill(-1);
    std::array<int, 12> incoming{};
    for (int axis = 0; axis < 3; ++axis) {
        int u, w;
        otherAxes(axis, u, w);
        for (int side = 0; side < 2; ++side) {
            const glm::dvec3 normal =
                glm::dvec3(axis == 0, axis == 1, axis == 2) * (side ? 1.0 : -1.0);
            // Face corners in cyclic order and the face edges between them.
            const int q[4] = {cornerOf(axis, side, u, 0, w, 0), cornerOf(axis, side, u, 1, w, 0),
                              cornerOf(axis, side, u, 1, w, 1), cornerOf(axis, side, u, 0, w, 1)};
            int faceEdge[4];
            for (int n = 0; n < 4; ++n) faceEdge[n] = edgeBetween(q[n], q[(n + 1) % 4]);
            std::vector<std::array<int, 3>> segments;  // edge, edge, inside corner beside them
            int crossings = 0;
            for (int n = 0; n < 4; ++n) crossings += (result.edgeMask >> faceEdge[n]) & 1;
            if (crossings == 2) {
                int a = -1, b = -1, in = -1;
                for (int n = 0; n < 4; ++n) {
                    if ((result.edgeMask >> faceEdge[n]) & 1) (a < 0 ? a : b) = faceEdge[n];
                    if (inside(q[n])) in = q[n];
                }
                segments.push_back({a, b, in});
            } else if (crossings == 4) {
                // Ambiguous face: cut each inside corner off on its own (inside separated).
                for (int n = 0; n < 4; ++n)
                    if (inside(q[n]))
                        segments.push_back({faceEdge[(n + 3) % 4], faceEdge[n], q[n]});
            }
            for (auto [a, b, in] : segments) {
                const glm::dvec3 p = edgeMidpoint(a), r = edgeMidpoint(b);
                // Inside on the right of a->b seen from outside the cube gives outward triangles.
                if (glm::dot(glm::cross(r - p, cornerPosition(in) - p), normal) > 0)
                    std::swap(a, b);
                if (next[a] >= 0) throw std::logic_error("marching cubes table: two exits");
                next[a] = b;
                ++incoming[b];
            }
        }
    }

    std::vector<std::array<int, 3>> triangles;
    std::array<bool, 12> used{};
    for (int start = 0; start < 12; ++start) {
        if (!((result.edgeMask >> start) & 1) || used[start]) continue;
        if (incoming[start] != 1) throw std::logic_error("marching cubes table: open loop");
        std::vector<int> loop;
        for (int e = start; !used[e]; e = next[e]) {
            if (e < 0) throw std::logic_error("marching cubes table: open loop");
            used[e] = true;
            loop.push_back(e);
        }
        std::vector<std::array<int, 3>> loopTriangles;
        bool done = false;
        for (int apex = 0; apex < static_cast<int>(loop.size()) && !done; ++apex)
            done = fanTriangulation(loop, apex, loopTriangles);
        // Every loop of every case has such a fan (checked here at start-up for all 256).
        if (!done) throw std::logic_error("marching cubes table: loop without a valid fan");
        triangles.insert(triangles.end(), loopTriangles.begin(), loopTriangles.end());
    }
    if (triangles.size() > kMaxTriangles)
        throw std::logic_error("marching cubes table: case too large");
    result.triangleCount = static_cast<std::uint8_t>(triangles.size());
    for (std::size_t t = 0; t < triangles.size() && t < result.triangles.size(); ++t)
        for (int v = 0; v < 3; ++v)
            result.triangles[t][v] = static_cast<std::uint8_t>(triangles[t][v]);
    return result;
}

}  // namespace

int edgeAxis(int edge) {
    return edge / 4;
}

int edgeCorner(int edge, int end) {
    const int axis = edge / 4;
    int u, w;
    otherAxes(axis, u, w);
    return cornerOf(axis, end, u, edge & 1, w, (edge >> 1) & 1);
}

bool edgeOnFace(int edge, int face) {
    const int axis = face / 2, side = face % 2;
    if (edgeAxis(edge) == axis) return false;
    return ((edgeCorner(edge, 0) >> axis) & 1) == side;
}

const std::array<CubeCase, 256>& cubeCases() {
    static const std::array<CubeCase, 256> table = [] {
        std::array<CubeCase, 256> t;
        for (int c = 0; c < 256; ++c) t[c] = buildCase(c);
        return t;
    }();
    return table;
}

}  // namespace fm::mc

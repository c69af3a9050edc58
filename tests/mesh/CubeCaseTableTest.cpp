// Exhaustive checks of the generated marching-cubes case table: every one of the 256 cases
// closes up inside its cube, and every face decision agrees with every possible neighbour.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "mesh/MarchingCubesTable.h"

namespace {

using fm::mc::CubeCase;
using fm::mc::cubeCases;
using fm::mc::edgeCorner;
using fm::mc::edgeOnFace;

bool inside(int caseIndex, int corner) {
    return ((caseIndex >> corner) & 1) != 0;
}

bool onCommonFace(int a, int b) {
    for (int f = 0; f < 6; ++f)
        if (edgeOnFace(a, f) && edgeOnFace(b, f)) return true;
    return false;
}

// Directed triangle edges of a case lying on face f (both ends on edges of that face).
std::set<std::pair<int, int>> faceSegments(const CubeCase& c, int f) {
    std::set<std::pair<int, int>> out;
    for (int t = 0; t < c.triangleCount; ++t)
        for (int k = 0; k < 3; ++k) {
            const int a = c.triangles[t][k], b = c.triangles[t][(k + 1) % 3];
            if (edgeOnFace(a, f) && edgeOnFace(b, f)) out.insert({a, b});
        }
    return out;
}

// The same cube edge seen from the neighbour across face (axis, side 1): the offset along
// `axis` drops from 1 to 0.
int acrossFace(int edge, int axis) {
    const int c0 = edgeCorner(edge, 0) & ~(1 << axis);
    const int c1 = edgeCorner(edge, 1) & ~(1 << axis);
    for (int e = 0; e < 12; ++e)
        if ((edgeCorner(e, 0) == c0 && edgeCorner(e, 1) == c1)) return e;
    return -1;
}

TEST(CubeCaseTable, TrivialCasesAreEmpty) {
    EXPECT_EQ(cubeCases()[0].triangleCount, 0);
    EXPECT_EQ(cubeCases()[255].triangleCount, 0);
}

TEST(CubeCaseTable, EveryCrossedEdgeIsUsedAndOnlyThose) {
    for (int ci = 0; ci < 256; ++ci) {
        const CubeCase& c = cubeCases()[ci];
        std::set<int> used;
        for (int t = 0; t < c.triangleCount; ++t)
            for (int k = 0; k < 3; ++k) {
                const int v = c.triangles[t][k];
                ASSERT_LT(v, 12) << "case " << ci;
                used.insert(v);
            }
        for (int e = 0; e < 12; ++e) {
            const bool crossed = inside(ci, edgeCorner(e, 0)) != inside(ci, edgeCorner(e, 1));
            EXPECT_EQ(used.count(e) == 1, crossed) << "case " << ci << " edge " << e;
        }
    }
}

// Inside one cube: a chord through the cube's interior has two triangles (opposite
// directions); a segment on a cube face has exactly one (its partner is in the neighbour);
// no triangle edge joins two points of a common face other than such a face segment, and
// each face has at most two segments that do not share points.
TEST(CubeCaseTable, TrianglesCloseUpInsideTheCube) {
    for (int ci = 0; ci < 256; ++ci) {
        const CubeCase& c = cubeCases()[ci];
        std::map<std::pair<int, int>, int> directed;
        for (int t = 0; t < c.triangleCount; ++t) {
            const auto& tri = c.triangles[t];
            EXPECT_TRUE(tri[0] != tri[1] && tri[1] != tri[2] && tri[0] != tri[2]) << "case " << ci;
            for (int k = 0; k < 3; ++k) ++directed[{tri[k], tri[(k + 1) % 3]}];
        }
        for (const auto& [edge, count] : directed) {
            EXPECT_EQ(count, 1) << "case " << ci << ": directed edge used twice";
            const bool reverse = directed.count({edge.second, edge.first}) > 0;
            if (onCommonFace(edge.first, edge.second))
                EXPECT_FALSE(reverse) << "case " << ci << ": chord lies in a cube face";
            else
                EXPECT_TRUE(reverse) << "case " << ci << ": interior chord with one triangle";
        }
        for (int f = 0; f < 6; ++f) {
            const auto segs = faceSegments(c, f);
            int crossed = 0;
            for (int e = 0; e < 12; ++e)
                if (edgeOnFace(e, f) &&
                    inside(ci, edgeCorner(e, 0)) != inside(ci, edgeCorner(e, 1)))
                    ++crossed;
            EXPECT_EQ(static_cast<int>(segs.size()) * 2, crossed) << "case " << ci << " face " << f;
        }
    }
}

// For every face and every pair of cases that agree on that face's four corners, the two
// cubes draw the same segments there, in opposite directions: the surface is watertight and
// consistently oriented across the face whatever the rest of the two cubes holds.
TEST(CubeCaseTable, NeighboursAgreeOnEveryFace) {
    int comparisons = 0;
    for (int axis = 0; axis < 3; ++axis) {
        const int upperFace = 2 * axis + 1, lowerFace = 2 * axis;
        for (int a = 0; a < 256; ++a) {
            const auto segsA = faceSegments(cubeCases()[a], upperFace);
            for (int b = 0; b < 256; ++b) {
                bool match = true;
                for (int corner = 0; corner < 8; ++corner)
                    if (((corner >> axis) & 1) &&
                        inside(a, corner) != inside(b, corner & ~(1 << axis)))
                        match = false;
                if (!match) continue;
                std::set<std::pair<int, int>> mapped;
                for (auto [p, q] : segsA) mapped.insert({acrossFace(q, axis), acrossFace(p, axis)});
                EXPECT_EQ(mapped, faceSegments(cubeCases()[b], lowerFace))
                    << "cases " << a << " | " << b << " across axis " << axis;
                ++comparisons;
            }
        }
    }
    EXPECT_EQ(comparisons, 3 * 256 * 16);  // each case meets 16 neighbour cases per face
}

// One inside corner: a single triangle whose normal points away from that corner (outside =
// below the isovalue), for each of the 8 corners.
TEST(CubeCaseTable, SingleCornerTriangleFacesAwayFromTheCorner) {
    for (int corner = 0; corner < 8; ++corner) {
        const CubeCase& c = cubeCases()[1 << corner];
        ASSERT_EQ(c.triangleCount, 1);
        glm::dvec3 p[3];
        for (int k = 0; k < 3; ++k) {
            const int e = c.triangles[0][k];
            const int c0 = edgeCorner(e, 0), c1 = edgeCorner(e, 1);
            p[k] = 0.5 * (glm::dvec3(c0 & 1, (c0 >> 1) & 1, c0 >> 2) +
                          glm::dvec3(c1 & 1, (c1 >> 1) & 1, c1 >> 2));
        }
        const glm::dvec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);
        const glm::dvec3 cornerPos(corner & 1, (corner >> 1) & 1, corner >> 2);
        EXPECT_GT(glm::dot(n, p[0] - cornerPos), 0.0) << "corner " << corner;
    }
}

}  // namespace

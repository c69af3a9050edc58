// Chord lengths through closed meshes (meshdrr/MeshRayCast via meshChordMm) against
// independent truth: slab clipping of boxes, half-space clipping of convex meshes, and exact
// values for rays through vertices, along edges and exactly through shared edges.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "ChordTruth.h"
#include "common/TestMeshes.h"
#include "core/Error.h"
#include "meshdrr/MeshDrr.h"
#include "model/WeldVertices.h"

namespace {

using glm::dvec3;
using fm::test::boxChord;
using fm::test::convexChord;

fm::MeshDrrModelPtr closedModel(const fm::Mesh& m) { return fm::prepareMeshDrr(m, true); }

double chord(const fm::MeshDrrModel& m, const dvec3& s, const dvec3& e) {
    return fm::meshChordMm(m, s, e);
}

// Random segments between points of a sphere around the model and points of its (enlarged)
// box: a mix of hits, misses and near-grazing rays; some ends inside the model.
struct RandomRays {
    std::mt19937_64 rng;
    dvec3 center;
    double radius;
    explicit RandomRays(unsigned seed, dvec3 c, double r) : rng(seed), center(c), radius(r) {}
    double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); }
    dvec3 onSphere() {
        dvec3 v;
        do v = dvec3(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
        while (glm::length(v) < 0.1 || glm::length(v) > 1);
        return center + 3.0 * radius * glm::normalize(v);
    }
    dvec3 inBox() { return center + dvec3(uniform(-1.3, 1.3), uniform(-1.3, 1.3), uniform(-1.3, 1.3)) * radius; }
};

TEST(MeshChord, BoxMatchesSlabClippingTo1e9) {
    const dvec3 lo(-3, 1, 2), hi(4, 2.5, 9);
    const auto model = closedModel(fm::test::boxMesh(lo, hi));
    RandomRays rays(7, 0.5 * (lo + hi), 4.0);
    int hits = 0;
    for (int i = 0; i < 4000; ++i) {
        const dvec3 s = i % 4 == 0 ? rays.inBox() : rays.onSphere();
        const dvec3 e = i % 3 == 0 ? rays.onSphere() : rays.inBox();
        const double truth = boxChord(lo, hi, s, e), got = chord(*model, s, e);
        ASSERT_NEAR(got, truth, 1e-9 * std::max(truth, 1e-3)) << i;
        hits += truth > 0;
    }
    EXPECT_GT(hits, 800);
}

TEST(MeshChord, MissesAreExactlyZeroAndSourceInsideCountsFromTheSource) {
    const auto model = closedModel(fm::test::boxMesh({0, 0, 0}, {1, 1, 1}));
    EXPECT_EQ(chord(*model, {-1, 2, 0.5}, {2, 2, 0.5}), 0.0);         // passes beside
    EXPECT_EQ(chord(*model, {-3, 0.5, 0.5}, {-2, 0.5, 0.5}), 0.0);    // stops before the box
    EXPECT_EQ(chord(*model, {3, 0.5, 0.5}, {2, 0.5, 0.5}), 0.0);      // points away
    EXPECT_NEAR(chord(*model, {0.25, 0.5, 0.5}, {5, 0.5, 0.5}), 0.75, 1e-15);  // source inside
    EXPECT_NEAR(chord(*model, {-5, 0.5, 0.5}, {0.6, 0.5, 0.5}), 0.6, 1e-15);   // target inside
    EXPECT_NEAR(chord(*model, {0.2, 0.3, 0.4}, {0.7, 0.9, 0.1}),
                glm::length(dvec3(0.5, 0.6, -0.3)), 1e-15);  // both ends inside
}

TEST(MeshChord, RaysExactlyThroughFaceDiagonalsCountOnce) {
    // Every face of the box is two triangles sharing a diagonal; these rays cross faces exactly
    // on the diagonal (the sheared coordinates are exact, so the edge function is exactly 0).
    const auto model = closedModel(fm::test::boxMesh({0, 0, 0}, {1, 1, 1}));
    for (double u : {0.125, 0.25, 0.5, 0.75}) {
        // x = 0 face diagonal is y = z (vertices 0 and 6): along x at y = z = u.
        EXPECT_DOUBLE_EQ(chord(*model, {-2, u, u}, {3, u, u}), 1.0) << u;
        EXPECT_DOUBLE_EQ(chord(*model, {3, u, u}, {-2, u, u}), 1.0) << u;
        EXPECT_DOUBLE_EQ(chord(*model, {u, -2, u}, {u, 3, u}), 1.0) << u;
        EXPECT_DOUBLE_EQ(chord(*model, {u, u, 3}, {u, u, -2}), 1.0) << u;
        EXPECT_DOUBLE_EQ(chord(*model, {u, 1 - u, -2}, {u, 1 - u, 3}), 1.0) << u;
        // Oblique, still through the diagonal point (0, u, u) on entry.
        const dvec3 s(-1, u - 0.25, u - 0.125), e = dvec3(0, u, u) + 2.0 * (dvec3(0, u, u) - s);
        EXPECT_NEAR(chord(*model, s, e), boxChord({0, 0, 0}, {1, 1, 1}, s, e), 1e-14) << u;
    }
}

TEST(MeshChord, RaysThroughVerticesAndAlongEdges) {
    const auto model = closedModel(fm::test::boxMesh({0, 0, 0}, {1, 1, 1}));
    // Corner to corner through the body diagonal: enters at vertex 0, leaves at vertex 7.
    EXPECT_NEAR(chord(*model, {-1, -1, -1}, {2, 2, 2}), std::sqrt(3.0), 1e-15);
    EXPECT_NEAR(chord(*model, {2, -1, 2}, {-1, 2, -1}), std::sqrt(3.0), 1e-15);
    // Touching one corner only (the line meets the closed box in that point): 0, not +-t.
    EXPECT_NEAR(chord(*model, {0, 0, 2}, {2, 2, 0}), 0.0, 1e-15);
    EXPECT_NEAR(chord(*model, {2, 2, 0}, {0, 0, 2}), 0.0, 1e-15);
    // Along an edge or inside a face plane: the ray is on the surface. The tie rule decides as
    // for a ray moved by an infinitesimal amount: all (1) or nothing (0), never a half count.
    const dvec3 onSurface[][2] = {{{-1, 0, 0}, {2, 0, 0}},     {{-1, 1, 1}, {2, 1, 1}},
                                  {{0, -1, 0.5}, {0, 2, 0.5}}, {{0.5, 1, -1}, {0.5, 1, 2}},
                                  {{2, 0, 1}, {-1, 0, 1}},     {{0.3, 0, -1}, {0.3, 0, 2}}};
    for (const auto& r : onSurface) {
        const double c = chord(*model, r[0], r[1]);
        EXPECT_TRUE(std::abs(c) < 1e-15 || std::abs(c - 1.0) < 1e-15) << c;
    }
}

// A cube [0, n]^3 with every face cut into n x n unit squares (2 triangles each): rays along
// the axes through every grid vertex and edge midpoint of the faces.
TEST(MeshChord, SubdividedCubeCountsEveryGridVertexAndEdgeOnce) {
    const int n = 4;
    fm::Mesh soup;
    auto quad = [&](dvec3 o, dvec3 u, dvec3 v) {  // counter-clockwise seen from outside: u x v out
        const auto i = static_cast<unsigned>(soup.positions.size());
        for (dvec3 p : {o, o + u, o + u + v, o + v}) soup.positions.push_back(glm::vec3(p));
        soup.triangles.push_back(glm::uvec3(i, i + 1, i + 2));
        soup.triangles.push_back(glm::uvec3(i, i + 2, i + 3));
    };
    for (int a = 0; a < 3; ++a) {
        const int b = (a + 1) % 3, c = (a + 2) % 3;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                dvec3 o(0.0), u(0.0), v(0.0);
                o[b] = i;
                o[c] = j;
                u[b] = 1;
                v[c] = 1;
                quad(o, v, u);  // face a = 0, normal -a
                o[a] = n;
                quad(o, u, v);  // face a = n, normal +a
            }
    }
    const fm::Mesh cube = fm::weldVertices(soup);
    ASSERT_EQ(cube.positions.size(), std::size_t(6 * n * n + 2));
    const auto model = closedModel(cube);
    for (int a = 0; a < 3; ++a)
        for (int i = 1; i < 2 * n; ++i)
            for (int j = 1; j < 2 * n; ++j) {
                dvec3 s(0.5 * i), e(0.5 * i);
                s[(a + 1) % 3] = e[(a + 1) % 3] = 0.5 * i;
                s[(a + 2) % 3] = e[(a + 2) % 3] = 0.5 * j;
                s[a] = -3;
                e[a] = n + 2;
                ASSERT_DOUBLE_EQ(chord(*model, s, e), n) << a << " " << i << " " << j;
                ASSERT_DOUBLE_EQ(chord(*model, e, s), n) << a << " " << i << " " << j;
            }
    // Oblique rays through grid vertices of the x = 0 face.
    for (int i = 1; i < n; ++i)
        for (int j = 1; j < n; ++j) {
            const dvec3 hitPoint(0, i, j), s = hitPoint - dvec3(2, 0.5, 0.25);
            const dvec3 e = hitPoint + 3.0 * (hitPoint - s);
            ASSERT_NEAR(chord(*model, s, e), boxChord({0, 0, 0}, dvec3(n), s, e), 1e-13);
        }
}

TEST(MeshChord, CylinderMatchesConvexClippingTo1e9) {
    // Exactly planar faces (vertical rectangles, flat caps): the polyhedron is convex.
    const fm::Mesh cyl = fm::test::cylinderMesh(6.f, -4.f, 9.f, 40);
    const auto model = closedModel(cyl);
    RandomRays rays(11, {0, 0, 2.5}, 7.0);
    int hits = 0;
    for (int i = 0; i < 3000; ++i) {
        const dvec3 s = i % 5 == 0 ? rays.inBox() : rays.onSphere(), e = rays.inBox();
        const double truth = convexChord(cyl, s, e);
        ASSERT_NEAR(chord(*model, s, e), truth, 1e-9 * std::max(truth, 1e-3)) << i;
        hits += truth > 0;
    }
    EXPECT_GT(hits, 1000);
    // Along the axis through both cap centres (40 triangles meet at each): the full height.
    EXPECT_DOUBLE_EQ(chord(*model, {0, 0, -20}, {0, 0, 20}), 13.0);
    EXPECT_DOUBLE_EQ(chord(*model, {0, 0, 20}, {0, 0, -20}), 13.0);
}

TEST(MeshChord, UvSphereMatchesConvexClippingTo1e9AndPoles) {
    // Planar quads (coordinates rounded so that the faces are exactly flat): exactly convex.
    const fm::Mesh sphere = fm::test::uvSphereMesh({1, 2, 3}, 10.f, 12, 24, true);
    const auto model = closedModel(sphere);
    RandomRays rays(13, {1, 2, 3}, 10.0);
    int hits = 0;
    for (int i = 0; i < 3000; ++i) {
        const dvec3 s = i % 5 == 0 ? rays.inBox() : rays.onSphere(), e = rays.inBox();
        const double truth = convexChord(sphere, s, e);
        ASSERT_NEAR(chord(*model, s, e), truth, 1e-9 * std::max(truth, 1e-3)) << i;
        hits += truth > 0;
    }
    EXPECT_GT(hits, 1000);
    // Through the poles along z (24 triangles meet at each pole vertex).
    EXPECT_NEAR(chord(*model, {1, 2, -30}, {1, 2, 30}), 20.0, 1e-13);
    // Through every vertex, from a fixed outside point: the chord of the convex polyhedron.
    const dvec3 s(-25, 7, 11);
    for (const auto& p : sphere.positions) {
        const dvec3 e = dvec3(p) + 2.0 * (dvec3(p) - s);
        const double truth = convexChord(sphere, s, e);
        ASSERT_NEAR(chord(*model, s, e), truth, 1e-9 * std::max(truth, 1e-3));
    }
}

TEST(MeshChord, UnroundedUvSphereAgreesWithinItsNonPlanarity) {
    // Float corners on the true sphere: the quads bend by ~1e-7 mm along their diagonal, and
    // the clipping truth (the half-spaces' intersection) differs by that over sin(grazing angle).
    const fm::Mesh sphere = fm::test::uvSphereMesh({1, 2, 3}, 10.f, 12, 24);
    const auto model = closedModel(sphere);
    RandomRays rays(19, {1, 2, 3}, 10.0);
    for (int i = 0; i < 2000; ++i) {
        const dvec3 s = rays.onSphere(), e = rays.inBox();
        const double truth = convexChord(sphere, s, e);
        ASSERT_NEAR(chord(*model, s, e), truth, truth > 20.0 / 3 ? 1e-5 : 1e-4) << i;
    }
}

TEST(MeshChord, NonConvexFrameAndTwoBoxes) {
    // The square frame (genus 1) = outer box minus the hole's box.
    const fm::Mesh frame = fm::test::squareFrameMesh(5.f, 2.f, -1.f, 3.f);
    const auto model = closedModel(frame);
    RandomRays rays(17, {0, 0, 1}, 5.0);
    int throughHole = 0;
    for (int i = 0; i < 3000; ++i) {
        const dvec3 s = rays.onSphere(), e = i % 2 ? rays.onSphere() : rays.inBox();
        const double hole = boxChord({-2, -2, -1}, {2, 2, 3}, s, e);
        const double truth = boxChord({-5, -5, -1}, {5, 5, 3}, s, e) - hole;
        ASSERT_NEAR(chord(*model, s, e), truth, 1e-9 * std::max(truth, 1e-3)) << i;
        throughHole += hole > 0;
    }
    EXPECT_GT(throughHole, 200);
    // Straight down through the hole: nothing; through the rim: the height.
    EXPECT_EQ(chord(*model, {0, 0, 10}, {0, 0, -10}), 0.0);
    EXPECT_DOUBLE_EQ(chord(*model, {3.5, 0, 10}, {3.5, 0, -10}), 4.0);
    // Across, in the hole's mid-plane: two walls of 3 mm each.
    EXPECT_DOUBLE_EQ(chord(*model, {-9, 0.25, 1}, {9, 0.25, 1}), 6.0);

    const fm::Mesh two = fm::test::mergeMeshes(fm::test::boxMesh({0, 0, 0}, {1, 1, 1}),
                                               fm::test::boxMesh({3, 0, 0}, {5, 1, 1}));
    EXPECT_DOUBLE_EQ(chord(*closedModel(two), {-1, 0.5, 0.5}, {9, 0.5, 0.5}), 3.0);
}

TEST(MeshChord, NestedShellsAddAndInwardShellsSubtract) {
    const fm::Mesh outer = fm::test::boxMesh({0, 0, 0}, {10, 10, 10});
    const fm::Mesh inner = fm::test::uvSphereMesh({5, 5, 5}, 3.f, 10, 20, true);
    const dvec3 s(-1, 5.3, 4.6), e(12, 5.1, 5.4);
    const double outerChord = boxChord({0, 0, 0}, {10, 10, 10}, s, e);
    const double innerChord = convexChord(inner, s, e);
    ASSERT_GT(innerChord, 5.0);
    // Both outward: the sphere's inside has winding 2 and counts twice.
    EXPECT_NEAR(chord(*closedModel(fm::test::mergeMeshes(outer, inner)), s, e), outerChord + innerChord, 1e-12);
    // The sphere inward: a hollow box (a shell of bone around a cavity).
    EXPECT_NEAR(chord(*closedModel(fm::test::mergeMeshes(outer, fm::test::flippedMesh(inner))), s, e),
                outerChord - innerChord, 1e-12);
}

TEST(MeshChord, RefusesOpenModelsAndEmptySegments) {
    fm::Mesh box = fm::test::boxMesh({0, 0, 0}, {1, 1, 1});
    box.triangles.pop_back();
    const auto open = fm::prepareMeshDrr(box, false);
    EXPECT_THROW(fm::meshChordMm(*open, {-1, 0.5, 0.5}, {2, 0.5, 0.5}), fm::Error);
    const auto closed = closedModel(fm::test::boxMesh({0, 0, 0}, {1, 1, 1}));
    EXPECT_THROW(fm::meshChordMm(*closed, {1, 2, 3}, {1, 2, 3}), fm::Error);
    EXPECT_THROW(fm::prepareMeshDrr(fm::Mesh{}, true), fm::Error);
}

}  // namespace

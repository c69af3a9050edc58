// Connected components of marching-cubes meshes (labelled while the triangles are generated,
// in parallel) against a plain breadth-first search written here, and against shapes whose
// components, Euler characteristics and volumes are known.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <queue>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "mesh/MarchingCubes.h"
#include "mesh/MeshCheck.h"
#include "mesh/MeshComponents.h"
#include "SampledField.h"

namespace {

using fm::Mesh;
using fm::Volume;

constexpr double kPiRad = std::numbers::pi;

// Reference: triangles sharing a vertex are neighbours; a breadth-first search from each
// unvisited triangle, in triangle order, finds the components in order of their first
// triangle; then the most triangles first, ties in that order.
std::vector<std::uint32_t> referenceRanks(const Mesh& mesh) {
    std::vector<std::vector<std::size_t>> trianglesOf(mesh.positions.size());
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k) trianglesOf[mesh.triangles[t][k]].push_back(t);
    std::vector<int> found(mesh.triangles.size(), -1);
    std::vector<std::size_t> sizes;
    for (std::size_t start = 0; start < mesh.triangles.size(); ++start) {
        if (found[start] >= 0) continue;
        const int id = static_cast<int>(sizes.size());
        sizes.push_back(0);
        std::queue<std::size_t> todo;
        todo.push(start);
        found[start] = id;
        while (!todo.empty()) {
            const std::size_t t = todo.front();
            todo.pop();
            ++sizes[id];
            for (int k = 0; k < 3; ++k)
                for (std::size_t n : trianglesOf[mesh.triangles[t][k]])
                    if (found[n] < 0) {
                        found[n] = id;
                        todo.push(n);
                    }
        }
    }
    std::vector<std::size_t> order(sizes.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return sizes[a] > sizes[b]; });
    std::vector<std::uint32_t> rank(sizes.size());
    for (std::size_t r = 0; r < order.size(); ++r) rank[order[r]] = static_cast<std::uint32_t>(r);
    std::vector<std::uint32_t> ranks(mesh.triangles.size());
    for (std::size_t t = 0; t < ranks.size(); ++t) ranks[t] = rank[found[t]];
    return ranks;
}

std::size_t distinct(const std::vector<std::uint32_t>& v) {
    return std::set<std::uint32_t>(v.begin(), v.end()).size();
}

using fm::test::sampleField;

fm::MarchingCubesOptions labelled(int threads) {
    fm::MarchingCubesOptions o;
    o.isoValue = 0.0;
    o.threads = threads;
    o.labelComponents = true;
    return o;
}

TEST(MeshComponents, LabelsMatchABreadthFirstSearchOnNoiseWithAnyThreadCount) {
    // Noise: from hundreds of components, many a single cube, to one that percolates; tall
    // volumes so that the generate pass's chunks (4 per thread) split the slices differently
    // at every thread count, and a flat one with fewer slices than chunks.
    std::mt19937 rng(99);
    std::uniform_real_distribution<float> value(-1.0f, 1.0f);
    for (const glm::ivec3 dims : {glm::ivec3(23, 17, 61), glm::ivec3(40, 33, 3),
                                  glm::ivec3(9, 70, 45)}) {
        for (const float iso : {0.7f, 0.5f, 0.0f}) {
            Volume v = Volume::allocate(dims);
            v.meta.source = "noise";
            for (float& x : v.values) x = value(rng);
            fm::MarchingCubesOptions o = labelled(1);
            o.isoValue = iso;
            const Mesh one = fm::marchingCubes(v, o);
            const std::vector<std::uint32_t> truth = referenceRanks(one);
            const std::string what = "noise " + std::to_string(dims.x) + "x" +
                                     std::to_string(dims.y) + "x" + std::to_string(dims.z) +
                                     " iso " + std::to_string(iso);
            ASSERT_GE(distinct(truth), 5u) << what;  // a test of several components
            EXPECT_TRUE(std::equal(one.component.begin(), one.component.end(), truth.begin(),
                                   truth.end()))
                << what;
            for (int threads : {2, 3, 4}) {
                o.threads = threads;
                const Mesh m = fm::marchingCubes(v, o);
                ASSERT_EQ(m.triangles.size(), one.triangles.size()) << what;
                EXPECT_TRUE(std::equal(m.component.begin(), m.component.end(), truth.begin(),
                                       truth.end()))
                    << what << ", " << threads << " threads";
            }
            // The stand-alone labelling (no forest from the generate pass) agrees too.
            for (int threads : {1, 3}) {
                Mesh m = one;
                m.component.clear();
                EXPECT_EQ(fm::labelComponents(m, threads), distinct(truth)) << what;
                EXPECT_TRUE(std::equal(m.component.begin(), m.component.end(), truth.begin(),
                                       truth.end()))
                    << what << ", labelComponents on " << threads << " threads";
            }
        }
    }
}

TEST(MeshComponents, LabelsMatchABreadthFirstSearchOnAMirroredGridAndARegionOfInterest) {
    // The labelling unites loop segments per cube from the case number alone: a left-handed
    // direction (winding flipped) and a region of interest (a border inside the volume, cut
    // surfaces closed by the padding) must not change which triangles are connected.
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> value(-1.0f, 1.0f);
    Volume v = Volume::allocate(glm::ivec3(27, 22, 41));
    v.meta.source = "noise";
    for (float& x : v.values) x = value(rng);
    v.direction = glm::dmat3(glm::dvec3(0, 1, 0), glm::dvec3(1, 0, 0), glm::dvec3(0, 0, 1));
    ASSERT_LT(glm::determinant(v.direction), 0.0);
    for (const bool roi : {false, true}) {
        fm::MarchingCubesOptions o = labelled(1);
        o.isoValue = 0.3;
        if (roi) {
            o.roiMin = glm::ivec3(3, 2, 5);
            o.roiMax = glm::ivec3(20, 19, 33);
        }
        for (int threads : {1, 2}) {
            o.threads = threads;
            const Mesh m = fm::marchingCubes(v, o);
            const std::vector<std::uint32_t> truth = referenceRanks(m);
            ASSERT_GE(distinct(truth), 5u);
            EXPECT_TRUE(std::equal(m.component.begin(), m.component.end(), truth.begin(),
                                   truth.end()))
                << (roi ? "region of interest, " : "whole volume, ") << threads << " threads";
        }
    }
}

TEST(MeshComponents, CountWithoutLabelsMatchesABreadthFirstSearchWithAnyThreadCount) {
    // What `fluoromatch mesh` reports: the count from the generate pass's forest, no triangle
    // labelled. Volumes: tall and flat noise, and noise in one slab of a constant volume, where
    // the work-balanced chunks of the generate pass are a slice or two each (all their segments
    // cross into the next chunk).
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> value(-1.0f, 1.0f);
    struct Case {
        glm::ivec3 dims;
        int slabFirst, slabLast;  // slices holding noise; the rest is -1 (outside)
    };
    for (const Case c : {Case{glm::ivec3(23, 17, 61), 0, 60}, Case{glm::ivec3(40, 33, 3), 0, 2},
                         Case{glm::ivec3(20, 22, 64), 40, 46}}) {
        Volume v = Volume::allocate(c.dims);
        v.meta.source = "noise";
        for (int z = 0; z < c.dims.z; ++z)
            for (int y = 0; y < c.dims.y; ++y)
                for (int x = 0; x < c.dims.x; ++x)
                    v.values[v.index(x, y, z)] =
                        z >= c.slabFirst && z <= c.slabLast ? value(rng) : -1.0f;
        for (const float iso : {0.6f, 0.0f}) {
            const std::string what = "noise " + std::to_string(c.dims.x) + "x" +
                                     std::to_string(c.dims.y) + "x" + std::to_string(c.dims.z) +
                                     " iso " + std::to_string(iso);
            fm::MarchingCubesOptions o;
            o.isoValue = iso;
            o.threads = 1;
            const Mesh plain = fm::marchingCubes(v, o);
            const std::size_t truth = distinct(referenceRanks(plain));
            ASSERT_GE(truth, 3u) << what;
            for (int threads : {1, 2, 3, 4}) {
                o.threads = threads;
                std::size_t count = 0;
                const Mesh m = fm::marchingCubes(v, o, &count);
                EXPECT_EQ(count, truth) << what << ", " << threads << " threads";
                EXPECT_TRUE(m.component.empty()) << what;  // counted, not labelled
                EXPECT_TRUE(std::equal(m.triangles.begin(), m.triangles.end(),
                                       plain.triangles.begin(), plain.triangles.end()))
                    << what << ", " << threads << " threads";
            }
            // With a component option the count is that of the mesh returned.
            o.threads = 2;
            std::size_t count = 0;
            o.keepLargestComponents = 2;
            const Mesh kept = fm::marchingCubes(v, o, &count);
            EXPECT_EQ(count, 2u) << what;
            EXPECT_EQ(distinct(referenceRanks(kept)), 2u) << what;
            o.keepLargestComponents = 0;
            o.onlyComponentRank = 1;
            count = 0;
            fm::marchingCubes(v, o, &count);
            EXPECT_EQ(count, 1u) << what;
            o.onlyComponentRank.reset();
            o.labelComponents = true;
            const Mesh labelled = fm::marchingCubes(v, o, &count);
            EXPECT_EQ(count, truth) << what << ", labelled";
            EXPECT_EQ(fm::componentSizes(labelled).size(), truth) << what;
        }
    }
}

TEST(MeshComponents, KeptComponentsAreTheSameTrianglesRenumbered) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> value(-1.0f, 1.0f);
    Volume v = Volume::allocate(glm::ivec3(30, 26, 48));
    v.meta.source = "noise";
    for (float& x : v.values) x = value(rng);
    fm::MarchingCubesOptions o = labelled(1);
    o.isoValue = 0.4;
    const Mesh all = fm::marchingCubes(v, o);
    const std::size_t count = distinct(std::vector<std::uint32_t>(all.component.begin(),
                                                                   all.component.end()));
    ASSERT_GT(count, 10u);
    // Each kept triangle, as world positions in order, with its rank.
    auto keptCorners = [](const Mesh& m, const std::function<bool(std::uint32_t)>& keep) {
        std::vector<std::pair<std::uint32_t, std::vector<float>>> out;
        for (std::size_t t = 0; t < m.triangles.size(); ++t) {
            if (!keep(m.component[t])) continue;
            std::vector<float> corners;
            for (int k = 0; k < 3; ++k)
                for (int a = 0; a < 3; ++a) corners.push_back(m.positions[m.triangles[t][k]][a]);
            out.emplace_back(m.component[t], corners);
        }
        return out;
    };
    for (int threads : {1, 2, 4}) {
        o.threads = threads;
        for (int keep : {1, 3, static_cast<int>(count) - 1, static_cast<int>(count) + 2}) {
            o.keepLargestComponents = keep;
            const Mesh kept = fm::marchingCubes(v, o);
            const auto expected = keptCorners(
                all, [&](std::uint32_t c) { return c < static_cast<std::uint32_t>(keep); });
            EXPECT_EQ(keptCorners(kept, [](std::uint32_t) { return true; }), expected)
                << "keep " << keep << ", " << threads << " threads";
            // Every vertex used, normals moved with their vertices.
            std::vector<bool> used(kept.positions.size(), false);
            for (const auto& t : kept.triangles)
                for (int k = 0; k < 3; ++k) used[t[k]] = true;
            EXPECT_TRUE(std::all_of(used.begin(), used.end(), [](bool u) { return u; }));
            ASSERT_EQ(kept.normals.size(), kept.positions.size());
            for (std::size_t t = 0; t < kept.triangles.size(); t += 97)
                for (int k = 0; k < 3; ++k) {
                    // Find the same vertex in the full mesh by position; its normal must match.
                    const glm::vec3 p = kept.positions[kept.triangles[t][k]];
                    const auto at = std::find(all.positions.begin(), all.positions.end(), p);
                    ASSERT_NE(at, all.positions.end());
                    EXPECT_EQ(all.normals[at - all.positions.begin()],
                              kept.normals[kept.triangles[t][k]]);
                }
        }
        o.keepLargestComponents = 0;
        o.onlyComponentRank = 2;
        const Mesh rank2 = fm::marchingCubes(v, o);
        EXPECT_EQ(keptCorners(rank2, [](std::uint32_t) { return true; }),
                  keptCorners(all, [](std::uint32_t c) { return c == 2; }));
        o.onlyComponentRank.reset();
    }
}

// Per component (by rank): Euler characteristic V - E + F from its own vertices and edges,
// signed volume (divergence theorem) and centroid of its vertices.
struct ComponentShape {
    long euler = 0;
    double volume = 0.0;
    glm::dvec3 centroid{0.0};
};

std::vector<ComponentShape> shapes(const Mesh& m) {
    const auto sizes = fm::componentSizes(m);
    std::vector<ComponentShape> out(sizes.size());
    std::vector<std::set<std::uint32_t>> vertices(sizes.size());
    std::vector<std::set<std::pair<std::uint32_t, std::uint32_t>>> edges(sizes.size());
    for (std::size_t t = 0; t < m.triangles.size(); ++t) {
        const std::uint32_t c = m.component[t];
        const glm::uvec3 tri = m.triangles[t];
        for (int k = 0; k < 3; ++k) {
            vertices[c].insert(tri[k]);
            const std::uint32_t a = tri[k], b = tri[(k + 1) % 3];
            edges[c].insert({std::min(a, b), std::max(a, b)});
        }
        const glm::dvec3 p0 = m.positions[tri.x], p1 = m.positions[tri.y], p2 = m.positions[tri.z];
        out[c].volume += glm::dot(p0, glm::cross(p1, p2)) / 6.0;
    }
    for (std::size_t c = 0; c < out.size(); ++c) {
        out[c].euler = static_cast<long>(vertices[c].size()) - static_cast<long>(edges[c].size()) +
                       static_cast<long>(sizes[c]);
        for (std::uint32_t v : vertices[c]) out[c].centroid += glm::dvec3(m.positions[v]);
        out[c].centroid /= static_cast<double>(vertices[c].size());
    }
    return out;
}

TEST(MeshComponents, KnownShapesGiveTheirComponentsEulerCharacteristicsAndVolumes) {
    // A ball (r 6), a torus (R 7, r 2.5, Euler 0), a hollow ball (outer 7, inner 4: two shells,
    // the inner one facing into the cavity, negative volume) and a small ball (r 3), at 0.5 mm.
    const glm::dvec3 ball(-12, -10, 0), torus(10, -10, 0), hollow(-10, 10, 0), small(10, 10, 0);
    auto field = [&](const glm::dvec3& p) {
        const double dBall = 6.0 - glm::length(p - ball);
        const glm::dvec3 q = p - torus;
        const double ring = std::sqrt(q.x * q.x + q.y * q.y) - 7.0;
        const double dTorus = 2.5 - std::sqrt(ring * ring + q.z * q.z);
        const double r = glm::length(p - hollow);
        const double dHollow = std::min(7.0 - r, r - 4.0);
        const double dSmall = 3.0 - glm::length(p - small);
        return std::max(std::max(dBall, dTorus), std::max(dHollow, dSmall));
    };
    const Volume v = sampleField(glm::ivec3(84, 84, 34), 0.5, field);
    struct Expected {
        glm::dvec3 centre;
        long euler;
        double volume;
        double radius;  // smallest curvature radius: the volume's tolerance 3 (h / radius)^2
    };
    const double ballVolume = 4.0 / 3.0 * kPiRad;
    const std::vector<Expected> expected = {
        {ball, 2, ballVolume * 216, 6},
        {torus, 0, 2.0 * kPiRad * kPiRad * 7.0 * 2.5 * 2.5, 2.5},
        {hollow, 2, ballVolume * 343, 7},  // outer shell
        {hollow, 2, -ballVolume * 64, 4},  // inner shell
        {small, 2, ballVolume * 27, 3},
    };
    for (int threads : {1, 2, 3}) {
        const Mesh m = fm::marchingCubes(v, labelled(threads));
        const auto found = shapes(m);
        ASSERT_EQ(found.size(), expected.size()) << threads << " threads";
        const auto sizes = fm::componentSizes(m);
        for (std::size_t c = 1; c < sizes.size(); ++c) EXPECT_GE(sizes[c - 1], sizes[c]);
        // Match each expected shape to the component with its centre and sign of volume.
        std::vector<bool> matched(found.size(), false);
        for (const Expected& e : expected) {
            bool hit = false;
            for (std::size_t c = 0; c < found.size() && !hit; ++c) {
                if (matched[c] || glm::length(found[c].centroid - e.centre) > 0.5 ||
                    (found[c].volume > 0) != (e.volume > 0))
                    continue;
                matched[c] = hit = true;
                EXPECT_EQ(found[c].euler, e.euler) << "component " << c;
                EXPECT_NEAR(found[c].volume, e.volume,
                            std::abs(e.volume) * 3.0 * std::pow(0.5 / e.radius, 2))
                    << "component " << c;
            }
            EXPECT_TRUE(hit) << "no component at (" << e.centre.x << ", " << e.centre.y << ")";
        }
        // Keeping the 4 largest drops the smallest by triangles: the small ball's (r 3) surface
        // or the inner shell (r 4): whichever, the rest stays watertight.
        fm::MarchingCubesOptions o = labelled(threads);
        o.keepLargestComponents = 4;
        const auto report = fm::checkMesh(fm::marchingCubes(v, o));
        EXPECT_TRUE(report.watertight()) << report.summary();
        EXPECT_EQ(report.components, 4u);
    }
}

}  // namespace

// The fast marching cubes (8 cubes per step, row trimming, running vertex ids, threads) against
// a plain one written here: one cube at a time over the padded grid, each crossed edge's vertex
// found through a map keyed by the edge. Both must give the same surface: the same vertex on
// every crossed edge, the same normals, and the same triangles with the same winding.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "mesh/MarchingCubes.h"
#include "mesh/MarchingCubesTable.h"

namespace {

using fm::MarchingCubesOptions;
using fm::Mesh;
using fm::Volume;

// Tolerances. Positions: our vertices are floats in world mm, mapped back to index space; the
// fractional part along the edge is at least kEdgeMargin = 1e-3 from a corner, so 1e-4 voxel
// tells edges apart and leaves room for float rounding at these coordinates (~1e-5 voxel).
constexpr double kIndexTolerance = 1e-4;
// Normals are unit vectors computed in float: directions agree to well within 1e-4.
constexpr double kNormalTolerance = 1e-4;
constexpr double kEdgeMargin = 1e-3;  // the documented clamp of the edge parameter

// A crossed edge: its lower point in padded local coordinates (ROI voxel lo + u - 1) and axis.
using EdgeKey = std::tuple<int, int, int, int>;
using TriangleKey = std::array<EdgeKey, 3>;

struct Reference {
    std::map<EdgeKey, glm::dvec3> index;   // vertex position, continuous voxel index
    std::map<EdgeKey, glm::dvec3> normal;  // unit, world
    std::vector<TriangleKey> triangles;
};

// Rotates a triangle so its smallest key comes first, keeping the winding.
TriangleKey canonical(TriangleKey t) {
    const auto smallest = std::min_element(t.begin(), t.end()) - t.begin();
    std::rotate(t.begin(), t.begin() + smallest, t.end());
    return t;
}

Reference referenceMarchingCubes(const Volume& v, const MarchingCubesOptions& o) {
    const glm::ivec3 lo = o.roiMin.value_or(glm::ivec3(0));
    const glm::ivec3 hi = o.roiMax.value_or(v.dims - 1);
    const glm::ivec3 m = hi - lo + 1;
    const double iso = o.isoValue;
    double pad = iso - 1.0;  // the documented default: the ROI minimum if that is below iso
    if (o.padValue) {
        pad = *o.padValue;
    } else {
        double lowest = std::numeric_limits<double>::infinity();
        for (int k = lo.z; k <= hi.z; ++k)
            for (int j = lo.y; j <= hi.y; ++j)
                for (int i = lo.x; i <= hi.x; ++i) lowest = std::min(lowest, double(v.at(i, j, k)));
        if (lowest < iso) pad = lowest;
    }
    const auto value = [&](glm::ivec3 u) -> double {
        for (int a = 0; a < 3; ++a)
            if (u[a] < 1 || u[a] > m[a]) return pad;
        const glm::ivec3 i = lo + u - 1;
        return v.at(i.x, i.y, i.z);
    };
    const auto gradient = [&](glm::ivec3 u) {
        glm::dvec3 g;
        for (int a = 0; a < 3; ++a) {
            glm::ivec3 up = u, down = u;
            up[a] += 1;
            down[a] -= 1;
            g[a] = value(up) - value(down);
        }
        return g;
    };
    glm::dmat3 gradToWorld = v.direction;
    for (int a = 0; a < 3; ++a) gradToWorld[a] /= v.spacing[a];
    const bool mirrored = glm::determinant(v.direction) < 0.0;

    Reference ref;
    const auto corner = [](int c) { return glm::ivec3(c & 1, (c >> 1) & 1, (c >> 2) & 1); };
    const auto& cases = fm::mc::cubeCases();
    for (int z = 0; z <= m.z; ++z)
        for (int y = 0; y <= m.y; ++y)
            for (int x = 0; x <= m.x; ++x) {
                const glm::ivec3 cube(x, y, z);
                int caseIndex = 0;
                for (int c = 0; c < 8; ++c)
                    if (value(cube + corner(c)) >= iso) caseIndex |= 1 << c;
                const auto& cc = cases[caseIndex];
                std::array<EdgeKey, 12> keys;
                for (int e = 0; e < 12; ++e) {
                    if (!((cc.edgeMask >> e) & 1)) continue;
                    const int axis = fm::mc::edgeAxis(e);
                    const glm::ivec3 a = cube + corner(fm::mc::edgeCorner(e, 0));
                    glm::ivec3 b = a;
                    b[axis] += 1;
                    keys[e] = {a.x, a.y, a.z, axis};
                    if (ref.index.count(keys[e])) continue;
                    const double v0 = value(a), v1 = value(b);
                    const double t =
                        std::clamp((iso - v0) / (v1 - v0), kEdgeMargin, 1.0 - kEdgeMargin);
                    glm::dvec3 idx = glm::dvec3(lo + a - 1);
                    idx[axis] += t;
                    ref.index[keys[e]] = idx;
                    glm::dvec3 n = -(gradToWorld * (gradient(a) + t * (gradient(b) - gradient(a))));
                    if (glm::length(n) < 1e-12) {  // plateau: from the inside corner outward
                        glm::dvec3 d(0.0);
                        d[axis] = v0 >= iso ? 1.0 : -1.0;
                        n = gradToWorld * d;
                    }
                    ref.normal[keys[e]] = glm::normalize(n);
                }
                for (int t = 0; t < cc.triangleCount; ++t) {
                    TriangleKey tri = {keys[cc.triangles[t][0]], keys[cc.triangles[t][1]],
                                       keys[cc.triangles[t][2]]};
                    if (mirrored) std::swap(tri[1], tri[2]);
                    ref.triangles.push_back(canonical(tri));
                }
            }
    return ref;
}

// Compares the fast mesh with the reference; `what` names the case in failure messages.
void expectSameSurface(const Volume& v, const MarchingCubesOptions& o, const std::string& what) {
    const Mesh mesh = fm::marchingCubes(v, o);
    const Reference ref = referenceMarchingCubes(v, o);
    ASSERT_EQ(mesh.positions.size(), ref.index.size()) << what;
    ASSERT_EQ(mesh.normals.size(), ref.index.size()) << what;
    ASSERT_EQ(mesh.triangles.size(), ref.triangles.size()) << what;
    const glm::ivec3 lo = o.roiMin.value_or(glm::ivec3(0));

    // Each vertex lies on one edge: two index coordinates are whole, the third is not.
    std::vector<EdgeKey> keyOf(mesh.positions.size());
    std::map<EdgeKey, int> seen;
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        const glm::dvec3 idx = v.worldToIndex(glm::dvec3(mesh.positions[i]));
        int axis = 0;
        double farthest = -1.0;
        for (int a = 0; a < 3; ++a) {
            const double off = std::abs(idx[a] - std::round(idx[a]));
            if (off > farthest) farthest = off, axis = a;
        }
        glm::ivec3 u;
        for (int a = 0; a < 3; ++a)
            u[a] =
                static_cast<int>(a == axis ? std::floor(idx[a]) : std::round(idx[a])) - lo[a] + 1;
        const EdgeKey key{u.x, u.y, u.z, axis};
        keyOf[i] = key;
        ASSERT_EQ(seen[key]++, 0) << what << ": two vertices on one edge, vertex " << i;
        const auto found = ref.index.find(key);
        ASSERT_NE(found, ref.index.end()) << what << ": vertex " << i << " on an uncrossed edge";
        EXPECT_LT(glm::length(idx - found->second), kIndexTolerance) << what << ": vertex " << i;
        const glm::dvec3 n = glm::dvec3(mesh.normals[i]);
        EXPECT_LT(glm::length(n - ref.normal.at(key)), kNormalTolerance)
            << what << ": normal of vertex " << i;
    }
    std::vector<TriangleKey> ours;
    ours.reserve(mesh.triangles.size());
    for (const auto& t : mesh.triangles) {
        ASSERT_LT(std::max({t.x, t.y, t.z}), mesh.positions.size()) << what;
        ours.push_back(canonical({keyOf[t.x], keyOf[t.y], keyOf[t.z]}));
    }
    std::vector<TriangleKey> theirs = ref.triangles;
    std::sort(ours.begin(), ours.end());
    std::sort(theirs.begin(), theirs.end());
    EXPECT_TRUE(ours == theirs) << what << ": triangles differ";
}

Volume noiseVolume(glm::ivec3 dims, std::mt19937& rng, bool integers) {
    Volume v = Volume::allocate(dims);
    v.meta.source = "noise";
    std::uniform_real_distribution<float> real(-1.0f, 1.0f);
    std::uniform_int_distribution<int> integer(-1, 1);  // many values equal to the iso (0)
    for (float& x : v.values) x = integers ? float(integer(rng)) : real(rng);
    return v;
}

MarchingCubesOptions options(double iso, int threads) {
    MarchingCubesOptions o;
    o.isoValue = iso;
    o.threads = threads;
    return o;
}

TEST(MarchingCubesReference, NoiseOfEveryRowLengthAroundTheEightCubeStep) {
    // Row lengths below, at and around multiples of 8 cubes, so that every lane position of
    // the first and last step of a row is exercised; thin and single-voxel volumes too.
    std::mt19937 rng(2024);
    const glm::ivec3 sizes[] = {{1, 1, 1},  {2, 2, 2},  {3, 5, 2},  {6, 4, 3},  {7, 3, 3},
                                {8, 2, 4},  {9, 8, 7},  {15, 4, 3}, {16, 3, 5}, {17, 9, 5},
                                {31, 2, 2}, {33, 6, 4}, {64, 3, 3}, {1, 12, 9}, {70, 1, 4}};
    int n = 0;
    for (const auto& dims : sizes)
        for (bool integers : {false, true}) {
            const Volume v = noiseVolume(dims, rng, integers);
            const int threads = 1 + n++ % 3;
            expectSameSurface(v, options(0.0, threads),
                              "noise " + std::to_string(dims.x) + "x" + std::to_string(dims.y) +
                                  "x" + std::to_string(dims.z) +
                                  (integers ? " integers" : " real") + ", " +
                                  std::to_string(threads) + " threads");
        }
}

TEST(MarchingCubesReference, SparseBlobsInALargerVolume) {
    // Mostly empty rows, long runs of skipped steps, blobs starting at odd x positions.
    Volume v = Volume::allocate(glm::ivec3(75, 23, 19));
    v.meta.source = "blobs";
    const glm::dvec3 centres[] = {{5, 5, 5}, {40.3, 11, 9}, {68.5, 18, 14}, {73, 2, 17}};
    for (int k = 0; k < v.dims.z; ++k)
        for (int j = 0; j < v.dims.y; ++j)
            for (int i = 0; i < v.dims.x; ++i) {
                float best = -1000.0f;
                for (const auto& c : centres)
                    best =
                        std::max(best, float(400.0 * (3.5 - glm::length(glm::dvec3(i, j, k) - c))));
                v.at(i, j, k) = best;
            }
    for (int threads : {1, 2, 4}) {
        expectSameSurface(v, options(300.0, threads),
                          "blobs, " + std::to_string(threads) + " threads");
        MarchingCubesOptions o = options(300.0, threads);
        o.padValue = -50.0;  // a pad close to the iso moves the caps of the cut blob
        expectSameSurface(v, o, "blobs with pad -50, " + std::to_string(threads) + " threads");
    }
}

TEST(MarchingCubesReference, RegionsOfInterest) {
    std::mt19937 rng(7);
    const Volume v = noiseVolume(glm::ivec3(21, 14, 11), rng, false);
    const std::pair<glm::ivec3, glm::ivec3> rois[] = {{{0, 0, 0}, {20, 13, 10}},
                                                      {{3, 2, 1}, {17, 9, 8}},
                                                      {{5, 5, 5}, {5, 5, 5}},
                                                      {{0, 7, 2}, {20, 7, 9}},
                                                      {{12, 0, 0}, {20, 13, 3}}};
    for (const auto& [lo, hi] : rois) {
        MarchingCubesOptions o = options(0.1, 2);
        o.roiMin = lo;
        o.roiMax = hi;
        expectSameSurface(v, o,
                          "ROI from x " + std::to_string(lo.x) + " to " + std::to_string(hi.x));
    }
}

TEST(MarchingCubesReference, RotatedMirroredAndAnisotropicGrids) {
    std::mt19937 rng(99);
    Volume v = noiseVolume(glm::ivec3(19, 10, 8), rng, false);
    v.spacing = glm::dvec3(0.5, 1.25, 2.0);
    v.origin = glm::dvec3(-30.0, 12.5, 100.0);
    const glm::dmat3 rotation =
        glm::dmat3(glm::rotate(glm::dmat4(1.0), 0.4, glm::normalize(glm::dvec3(1, 2, 3))));
    glm::dmat3 mirrored = rotation;
    mirrored[1] = -mirrored[1];  // a left-handed frame: the winding must flip
    for (const glm::dmat3& direction : {glm::dmat3(1.0), rotation, mirrored}) {
        v.direction = direction;
        expectSameSurface(v, options(0.0, 3),
                          glm::determinant(direction) < 0 ? "mirrored grid" : "rotated grid");
    }
}

}  // namespace

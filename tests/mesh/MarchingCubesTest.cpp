// Marching cubes against analytic shapes, checked independently by CGAL (fm::checkMesh):
// closed, manifold, no self-intersection, outward, Euler characteristic, volume and area.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <random>

#include <glm/glm.hpp>

#include "core/Error.h"
#include "mesh/MarchingCubes.h"
#include "mesh/MeshCheck.h"
#include "mesh/MeshComponents.h"
#include "SampledField.h"

namespace {

using fm::MarchingCubesOptions;
using fm::Mesh;
using fm::Volume;

constexpr double kPi = std::numbers::pi;

// Samples f(world position) on a grid. Inside = f >= iso (signed distances: positive inside).
using fm::test::sampleField;

// A grid of spacing h covering the cube [-halfWidth, halfWidth]^3 (plus a margin of 2 voxels).
Volume sampleCentered(double halfWidth, double h,
                      const std::function<double(const glm::dvec3&)>& f) {
    const int n = static_cast<int>(std::ceil(2.0 * halfWidth / h)) + 5;
    const glm::dvec3 origin(-0.5 * (n - 1) * h);
    return sampleField(glm::ivec3(n), glm::dvec3(h), origin, f);
}

double sphereDistance(const glm::dvec3& p, const glm::dvec3& c, double r) {
    return r - glm::length(p - c);
}

MarchingCubesOptions isoAt(double iso, int threads = 2) {
    MarchingCubesOptions o;
    o.isoValue = iso;
    o.threads = threads;
    return o;
}

void expectWatertight(const fm::MeshCheckReport& r, const std::string& what) {
    EXPECT_TRUE(r.isPolygonMesh) << what << ": " << r.summary();
    EXPECT_TRUE(r.closed) << what << ": " << r.summary();
    EXPECT_TRUE(r.manifold) << what << ": " << r.summary();
    EXPECT_FALSE(r.selfIntersecting) << what << ": " << r.summary();
    EXPECT_TRUE(r.outwardOriented) << what << ": " << r.summary();
    EXPECT_TRUE(r.boundsVolume) << what << ": " << r.summary();
    EXPECT_EQ(r.degenerateTriangles, 0u) << what << ": " << r.summary();
    EXPECT_EQ(r.duplicateVertices, 0u) << what << ": " << r.summary();
    EXPECT_EQ(r.unusedVertices, 0u) << what << ": " << r.summary();
}

// Relative volume/area error allowed for a surface of curvature radius R sampled at spacing
// h from its signed distance: linear interpolation along an edge misplaces a vertex by at most
// h^2 / (8R), and flat triangles (edges up to sqrt(3) h) sag by at most 3h^2 / (8R) between
// vertices; volume then errs by about 3 * (sum) / R relative: 1.5 (h/R)^2. Area alike, with
// a factor 2 margin for the facet-orientation (cosine) error MC surfaces carry.
double curvedSurfaceTolerance(double h, double radius) {
    return 3.0 * (h / radius) * (h / radius);
}

TEST(MarchingCubes, SphereIsClosedGenusZeroWithVolumeAndAreaConvergingWithVoxelSize) {
    constexpr double kRadius = 10.0;
    const double exactVolume = 4.0 / 3.0 * kPi * std::pow(kRadius, 3);
    const double exactArea = 4.0 * kPi * kRadius * kRadius;
    double previousVolumeError = 1e9;
    for (double h : {2.0, 1.0, 0.5}) {
        const Volume v = sampleCentered(kRadius, h, [&](const glm::dvec3& p) {
            return sphereDistance(p, glm::dvec3(0.3, -0.2, 0.1), kRadius);
        });
        const Mesh mesh = fm::marchingCubes(v, isoAt(0.0));
        const auto r = fm::checkMesh(mesh);
        const std::string what = "sphere h=" + std::to_string(h);
        expectWatertight(r, what);
        EXPECT_EQ(r.eulerCharacteristic, 2) << what;
        EXPECT_EQ(r.components, 1u) << what;
        const double volumeError = std::abs(r.volume - exactVolume) / exactVolume;
        EXPECT_LT(volumeError, curvedSurfaceTolerance(h, kRadius)) << what;
        EXPECT_LT(std::abs(r.area - exactArea) / exactArea, curvedSurfaceTolerance(h, kRadius))
            << what;
        EXPECT_LT(volumeError, previousVolumeError) << what << ": error must shrink with h";
        previousVolumeError = volumeError;
    }
}

TEST(MarchingCubes, VerticesAndNormalsLieOnTheSphereInWorldMillimetres) {
    // Anisotropic spacing, an offset origin and a left-handed (mirroring) direction matrix:
    // positions must come out in world mm and triangles must still face outward.
    constexpr double kRadius = 12.0;
    const glm::dvec3 center(100.0, -50.0, 300.0);
    const glm::dvec3 spacing(0.9, 1.1, 1.6);
    const glm::dmat3 direction(glm::dvec3(0, 1, 0), glm::dvec3(1, 0, 0), glm::dvec3(0, 0, 1));
    ASSERT_LT(glm::determinant(direction), 0.0);
    const glm::ivec3 dims(34, 30, 22);
    // Place the grid so that its centre is at the sphere centre.
    Volume probe = Volume::allocate(dims);
    probe.spacing = spacing;
    probe.direction = direction;
    const glm::dvec3 origin = center - (probe.center() - probe.origin);
    const Volume v = sampleField(
        dims, spacing, origin,
        [&](const glm::dvec3& p) { return sphereDistance(p, center, kRadius); }, direction);
    const Mesh mesh = fm::marchingCubes(v, isoAt(0.0));
    ASSERT_GT(mesh.triangleCount(), 100u);
    const auto r = fm::checkMesh(mesh);
    expectWatertight(r, "mirrored anisotropic sphere");
    EXPECT_EQ(r.eulerCharacteristic, 2);
    const double hMax = 1.6;
    // Edge vertices interpolate a signed distance: off the sphere by at most hMax^2 / (8R).
    // Centre vertices (means of a loop within one voxel, diagonal sqrt(3) hMax) sink below the
    // sphere by at most another 3 hMax^2 / (8R): hMax^2 / (2R) in all.
    const double kVertexTolerance = hMax * hMax / (2.0 * kRadius);
    // Central-difference normals of |p - c| are within a few degrees of radial at this
    // resolution (h/R ~ 0.13): allow 5 degrees.
    const double kNormalCosine = std::cos(5.0 * kPi / 180.0);
    for (std::size_t i = 0; i < mesh.vertexCount(); ++i) {
        const glm::dvec3 p(mesh.positions[i]);
        EXPECT_NEAR(glm::length(p - center), kRadius, kVertexTolerance);
        const glm::dvec3 radial = glm::normalize(p - center);
        EXPECT_GT(glm::dot(radial, glm::dvec3(mesh.normals[i])), kNormalCosine);
    }
    const double exactVolume = 4.0 / 3.0 * kPi * std::pow(kRadius, 3);
    EXPECT_LT(std::abs(r.volume - exactVolume) / exactVolume,
              curvedSurfaceTolerance(hMax, kRadius));
}

TEST(MarchingCubes, TorusHasEulerCharacteristicZero) {
    constexpr double kMajor = 12.0, kMinor = 4.0;
    const double exactVolume = 2.0 * kPi * kPi * kMajor * kMinor * kMinor;
    const double exactArea = 4.0 * kPi * kPi * kMajor * kMinor;
    for (double h : {1.0, 0.5}) {
        const Volume v = sampleCentered(kMajor + kMinor, h, [&](const glm::dvec3& p) {
            const double ring = std::hypot(p.x, p.y) - kMajor;
            return kMinor - std::hypot(ring, p.z);
        });
        const auto r = fm::checkMesh(fm::marchingCubes(v, isoAt(0.0)));
        const std::string what = "torus h=" + std::to_string(h);
        expectWatertight(r, what);
        EXPECT_EQ(r.eulerCharacteristic, 0) << what;
        EXPECT_EQ(r.components, 1u) << what;
        // The tube radius is the smallest curvature radius.
        EXPECT_LT(std::abs(r.volume - exactVolume) / exactVolume, curvedSurfaceTolerance(h, kMinor))
            << what;
        EXPECT_LT(std::abs(r.area - exactArea) / exactArea, curvedSurfaceTolerance(h, kMinor))
            << what;
    }
}

TEST(MarchingCubes, TwoTouchingSpheresStayManifold) {
    // Touching exactly at a grid point whose value equals the isovalue: the pinch point must
    // become either two separate closed surfaces or one joined by a small neck, never a
    // non-manifold vertex. Each closed genus-0 part contributes 2 to the Euler characteristic.
    constexpr double kRadius = 6.0;
    for (double offset : {0.0, 0.25, 0.5}) {
        const glm::dvec3 c1(-kRadius + offset, 0.0, 0.0), c2(kRadius + offset, 0.0, 0.0);
        const Volume v = sampleCentered(2.0 * kRadius + 1.0, 1.0, [&](const glm::dvec3& p) {
            return std::max(sphereDistance(p, c1, kRadius), sphereDistance(p, c2, kRadius));
        });
        const auto r = fm::checkMesh(fm::marchingCubes(v, isoAt(0.0)));
        const std::string what = "touching spheres offset " + std::to_string(offset);
        expectWatertight(r, what);
        EXPECT_TRUE(r.components == 1 || r.components == 2) << what;
        EXPECT_EQ(r.eulerCharacteristic, 2 * static_cast<long>(r.components)) << what;
        const double twoSpheres = 2.0 * 4.0 / 3.0 * kPi * std::pow(kRadius, 3);
        EXPECT_LT(std::abs(r.volume - twoSpheres) / twoSpheres,
                  curvedSurfaceTolerance(1.0, kRadius))
            << what;
    }
}

TEST(MarchingCubes, ShapeCutByTheVolumeBorderIsClosedByThePadding) {
    // A sphere whose centre lies 3 voxels inside the last slice: the scan cuts it, and the
    // virtual padding layer (below iso) caps it between the last voxel centre and one voxel
    // beyond.
    constexpr double kRadius = 10.0, kH = 1.0;
    const glm::ivec3 dims(30, 30, 14);
    const glm::dvec3 origin(-14.5, -14.5, -10.0);  // last slice (k = 13) at z = 3
    const double zLast = origin.z + (dims.z - 1) * kH;
    const Volume v = sampleField(dims, glm::dvec3(kH), origin, [&](const glm::dvec3& p) {
        return sphereDistance(p, glm::dvec3(0.0), kRadius);
    });
    const auto r = fm::checkMesh(fm::marchingCubes(v, isoAt(0.0)));
    expectWatertight(r, "cut sphere");
    EXPECT_EQ(r.eulerCharacteristic, 2);
    // Volume of the sphere below the plane z = a: pi (a + R)^2 (2R - a) / 3.
    auto capVolume = [&](double a) {
        return kPi * std::pow(a + kRadius, 2) * (2 * kRadius - a) / 3.0;
    };
    const double tol = curvedSurfaceTolerance(kH, kRadius);
    EXPECT_GT(r.volume, capVolume(zLast) * (1.0 - tol));
    EXPECT_LT(r.volume, capVolume(zLast + kH) * (1.0 + tol));
}

TEST(MarchingCubes, ValuesEqualToTheIsovalueDoNotCollapseTriangles) {
    // A box of voxels exactly at the isovalue in air: every vertex would fall on a corner
    // without the edge margin. The surface passes through the box's voxel centres.
    const glm::ivec3 dims(16, 14, 12);
    Volume v = Volume::allocate(dims, -1000.0f);
    v.meta.source = "iso box";
    const glm::ivec3 lo(3, 4, 2), hi(11, 9, 8);
    for (int k = lo.z; k <= hi.z; ++k)
        for (int j = lo.y; j <= hi.y; ++j)
            for (int i = lo.x; i <= hi.x; ++i) v.at(i, j, k) = 300.0f;
    const Mesh mesh = fm::marchingCubes(v, isoAt(300.0));
    const auto r = fm::checkMesh(mesh);
    expectWatertight(r, "iso box");
    EXPECT_EQ(r.eulerCharacteristic, 2);
    const glm::dvec3 size(hi - lo);
    const double boxVolume = size.x * size.y * size.z;
    // Vertices sit within the 1e-3 voxel edge margin of the box corners; the corner cut-offs
    // (triangles across the 8 corners and 12 edges) remove less than the corner and edge
    // tetrahedra, bounded here by the volume of the voxel shell one voxel thick / 2.
    const double shell = (size.x + 1) * (size.y + 1) * (size.z + 1) - boxVolume;
    EXPECT_LE(r.volume, boxVolume * (1.0 + 1e-3));
    EXPECT_GT(r.volume, boxVolume - 0.5 * shell);

    // Random fields of -1, 0, +1 at iso 0: many corners exactly on the isovalue and many
    // ambiguous faces.
    std::mt19937 rng(7);
    std::uniform_int_distribution<int> pick(-1, 1);
    for (int trial = 0; trial < 6; ++trial) {
        Volume noise = Volume::allocate(glm::ivec3(9, 8, 7));
        noise.meta.source = "noise";
        for (float& x : noise.values) x = static_cast<float>(pick(rng));
        const auto rn = fm::checkMesh(fm::marchingCubes(noise, isoAt(0.0)));
        expectWatertight(rn, "noise trial " + std::to_string(trial));
    }
}

TEST(MarchingCubes, RandomFieldsWithAmbiguousFacesAreWatertight) {
    // Uniform noise in [-1, 1]: about half of all faces are ambiguous; every surface must
    // still be closed, manifold, free of self-intersections and outward (CGAL decides).
    std::mt19937 rng(12345);
    std::uniform_real_distribution<float> value(-1.0f, 1.0f);
    for (int trial = 0; trial < 12; ++trial) {
        Volume noise = Volume::allocate(glm::ivec3(10, 9, 8));
        noise.meta.source = "noise";
        noise.spacing = glm::dvec3(1.0, 0.7, 1.3);
        for (float& x : noise.values) x = value(rng);
        const Mesh mesh = fm::marchingCubes(noise, isoAt(0.0, trial % 3 + 1));
        const auto r = fm::checkMesh(mesh);
        expectWatertight(r, "uniform noise trial " + std::to_string(trial));
        // Euler characteristic of a closed orientable surface is even.
        EXPECT_EQ(r.eulerCharacteristic % 2, 0) << r.summary();
    }
}

TEST(MarchingCubes, RegionOfInterestClosesAtItsBorder) {
    constexpr double kRadius = 8.0;
    const Volume v = sampleCentered(kRadius, 1.0, [&](const glm::dvec3& p) {
        return sphereDistance(p, glm::dvec3(0.0), kRadius);
    });
    MarchingCubesOptions o = isoAt(0.0);
    o.roiMin = glm::ivec3(0);
    o.roiMax = glm::ivec3(v.dims.x - 1, v.dims.y - 1, v.dims.z / 2);  // lower half (z <= ~0)
    const Mesh mesh = fm::marchingCubes(v, o);
    const auto r = fm::checkMesh(mesh);
    expectWatertight(r, "ROI half sphere");
    EXPECT_EQ(r.eulerCharacteristic, 2);
    const double zMax = v.indexToWorld(glm::dvec3(0, 0, v.dims.z / 2)).z;
    for (const auto& p : mesh.positions) EXPECT_LT(p.z, zMax + 1.0);  // at most the pad layer
    const double half = 2.0 / 3.0 * kPi * std::pow(kRadius, 3);
    EXPECT_NEAR(r.volume, half, half * 0.15);  // cap lies within one voxel of the mid-plane
}

TEST(MarchingCubes, ComponentsAreLabelledKeptAndPicked) {
    // Three separate spheres of radii 7, 5 and 3.
    const glm::dvec3 centers[3] = {{-12, 0, 0}, {4, 0, 0}, {14, 0, 0}};
    const double radii[3] = {7, 5, 3};
    const Volume v = sampleCentered(20.0, 1.0, [&](const glm::dvec3& p) {
        double d = -1e9;
        for (int s = 0; s < 3; ++s) d = std::max(d, sphereDistance(p, centers[s], radii[s]));
        return d;
    });
    MarchingCubesOptions o = isoAt(0.0);
    o.labelComponents = true;
    Mesh all = fm::marchingCubes(v, o);
    ASSERT_EQ(all.component.size(), all.triangleCount());
    EXPECT_EQ(fm::componentSizes(all).size(), 3u);
    const auto sizes = fm::componentSizes(all);
    EXPECT_GT(sizes[0], sizes[1]);
    EXPECT_GT(sizes[1], sizes[2]);
    auto sphereVolume = [](double r) { return 4.0 / 3.0 * kPi * r * r * r; };

    o.keepLargestComponents = 1;
    const auto largest = fm::checkMesh(fm::marchingCubes(v, o));
    expectWatertight(largest, "largest");
    EXPECT_EQ(largest.components, 1u);
    EXPECT_NEAR(largest.volume, sphereVolume(7), sphereVolume(7) * curvedSurfaceTolerance(1, 7));

    o.keepLargestComponents = 0;
    o.onlyComponentNear = centers[2];
    const auto smallest = fm::checkMesh(fm::marchingCubes(v, o));
    EXPECT_EQ(smallest.components, 1u);
    EXPECT_NEAR(smallest.volume, sphereVolume(3), sphereVolume(3) * curvedSurfaceTolerance(1, 3));

    // A point that is not one (NaN, or beyond kMaxWorldMm) is refused, not "nearest" to anything.
    o.onlyComponentNear = glm::dvec3(std::nan(""), 0.0, 0.0);
    EXPECT_THROW(fm::marchingCubes(v, o), fm::Error);
    o.onlyComponentNear = glm::dvec3(0.0, 1e308, 0.0);
    EXPECT_THROW(fm::marchingCubes(v, o), fm::Error);

    o.onlyComponentNear.reset();
    o.onlyComponentRank = 1;
    const auto middle = fm::checkMesh(fm::marchingCubes(v, o));
    EXPECT_EQ(middle.components, 1u);
    EXPECT_NEAR(middle.volume, sphereVolume(5), sphereVolume(5) * curvedSurfaceTolerance(1, 5));
}

TEST(MarchingCubes, OutputDoesNotDependOnTheThreadCount) {
    const Volume v = sampleCentered(12.0, 0.7, [&](const glm::dvec3& p) {
        const double ring = std::hypot(p.x, p.y) - 8.0;
        return 3.0 - std::hypot(ring, p.z) + 0.5 * std::sin(p.x);
    });
    const Mesh one = fm::marchingCubes(v, isoAt(0.0, 1));
    for (int threads : {2, 3, 5}) {
        const Mesh many = fm::marchingCubes(v, isoAt(0.0, threads));
        ASSERT_EQ(many.positions.size(), one.positions.size());
        ASSERT_EQ(many.triangles.size(), one.triangles.size());
        EXPECT_TRUE(many.positions == one.positions) << threads << " threads";
        EXPECT_TRUE(many.normals == one.normals) << threads << " threads";
        EXPECT_TRUE(many.triangles == one.triangles) << threads << " threads";
    }
}

TEST(MarchingCubes, NoSurfaceGivesAnEmptyMesh) {
    Volume v = Volume::allocate(glm::ivec3(5), -1000.0f);
    EXPECT_EQ(fm::marchingCubes(v, isoAt(300.0)).triangleCount(), 0u);
}

TEST(MarchingCubes, WholeVolumeAboveIsoBecomesItsBoundingBox) {
    Volume v = Volume::allocate(glm::ivec3(4, 5, 6), 1000.0f);
    const auto r = fm::checkMesh(fm::marchingCubes(v, isoAt(300.0)));
    expectWatertight(r, "full volume");
    EXPECT_EQ(r.eulerCharacteristic, 2);
    // Between the box through the outer voxel centres (3 x 4 x 5) and the padded box.
    EXPECT_GT(r.volume, 3.0 * 4.0 * 5.0);
    EXPECT_LT(r.volume, 5.0 * 6.0 * 7.0);
}

TEST(MarchingCubes, CavityInsideASolidBlockFacesInward) {
    // A block entirely above the isovalue (long all-inside runs, skipped in blocks) with a
    // spherical cavity below it, like a marrow cavity: two shells, the outer one closed by
    // the padding, the cavity's triangles facing into the cavity (away from the material).
    constexpr double kRadius = 8.0, kH = 1.0;
    const glm::ivec3 dims(40, 36, 32);
    const glm::dvec3 origin(-19.5, -17.5, -15.5);
    // Distance to the cavity, flat (5) from radius 13 on, so that the outer shell is the
    // same with and without the cavity.
    const Volume v = sampleField(dims, glm::dvec3(kH), origin, [&](const glm::dvec3& p) {
        return std::min(-sphereDistance(p, glm::dvec3(0.0), kRadius), 5.0);
    });
    Volume solid = v;
    std::fill(solid.values.begin(), solid.values.end(), 5.0f);
    MarchingCubesOptions o = isoAt(0.0);
    o.padValue = -1000.0;
    const auto outerOnly = fm::checkMesh(fm::marchingCubes(solid, o));
    expectWatertight(outerOnly, "solid block");
    EXPECT_EQ(outerOnly.components, 1u);
    const auto r = fm::checkMesh(fm::marchingCubes(v, o));
    expectWatertight(r, "block with cavity");
    EXPECT_EQ(r.components, 2u);
    EXPECT_EQ(r.eulerCharacteristic, 4);
    const double cavity = 4.0 / 3.0 * kPi * std::pow(kRadius, 3);
    EXPECT_NEAR(outerOnly.volume - r.volume, cavity, cavity * curvedSurfaceTolerance(kH, kRadius));
}

TEST(MarchingCubes, NonFiniteValuesGiveFiniteWatertightMeshes) {
    // NaN counts as outside (it is not >= iso); infinities are extreme values. Neither may
    // put a NaN position or normal into the mesh.
    Volume v = sampleCentered(
        6.0, 1.0, [](const glm::dvec3& p) { return sphereDistance(p, glm::dvec3(0.0), 6.0); });
    const float specials[3] = {std::numeric_limits<float>::quiet_NaN(),
                               std::numeric_limits<float>::infinity(),
                               -std::numeric_limits<float>::infinity()};
    for (std::size_t i = 0; i < v.values.size(); i += 37) v.values[i] = specials[i % 3];
    const Mesh mesh = fm::marchingCubes(v, isoAt(0.0));
    ASSERT_GT(mesh.triangleCount(), 0u);
    for (std::size_t i = 0; i < mesh.vertexCount(); ++i) {
        for (int a = 0; a < 3; ++a) {
            ASSERT_TRUE(std::isfinite(mesh.positions[i][a])) << i;
            ASSERT_TRUE(std::isfinite(mesh.normals[i][a])) << i;
        }
    }
    const auto r = fm::checkMesh(mesh);
    EXPECT_TRUE(r.closed && r.manifold && r.isPolygonMesh) << r.summary();
}

TEST(MarchingCubes, BadOptionsThrowErrorsNamingTheProblem) {
    Volume v = Volume::allocate(glm::ivec3(5), 0.0f);
    MarchingCubesOptions o;
    o.roiMin = glm::ivec3(2);
    o.roiMax = glm::ivec3(1);
    EXPECT_THROW(fm::marchingCubes(v, o), fm::Error);
    o.roiMin.reset();
    o.roiMax = glm::ivec3(5);
    EXPECT_THROW(fm::marchingCubes(v, o), fm::Error);
    o.roiMax.reset();
    o.isoValue = std::nan("");
    EXPECT_THROW(fm::marchingCubes(v, o), fm::Error);
    o.isoValue = 0.0;
    o.padValue = 1.0;
    EXPECT_THROW(fm::marchingCubes(v, o), fm::Error);
    o.padValue.reset();
    o.keepLargestComponents = -1;
    EXPECT_THROW(fm::marchingCubes(v, o), fm::Error);
    Volume bad = v;
    bad.spacing.x = 0.0;
    EXPECT_THROW(fm::marchingCubes(bad, MarchingCubesOptions{}), fm::Error);
}

}  // namespace

// Analytic objects against hand-computed truth: closed-form volumes and areas, an independent
// numeric surface integral for the ellipsoid, chord lengths from elementary geometry, and the
// voxelizer's total mass against the exact volume.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "core/Error.h"
#include "phantom/AnalyticObjects.h"

namespace {

using fm::AnalyticShape;
using fm::BoxShape;
using fm::CylinderShape;
using fm::EllipsoidShape;
using fm::SphereShape;

constexpr double kPi = std::numbers::pi;
// Closed forms and quadratic roots in double precision on numbers of order 1..1e5.
constexpr double kExactRel = 1e-12;
constexpr double kExactMm = 1e-9;

double relErr(double got, double want) {
    return std::abs(got - want) / std::abs(want);
}

// Independent check of the ellipsoid area: midpoint rule on the parametric surface
// x = a sin(t) cos(p), y = b sin(t) sin(p), z = c cos(t). The integrand is smooth, and
// periodic in p; with 2000 x 2000 cells the midpoint rule is accurate to ~1e-6 relative.
double numericEllipsoidArea(double a, double b, double c) {
    constexpr int kCells = 2000;
    const double dt = kPi / kCells, dp = 2.0 * kPi / kCells;
    double sum = 0.0;
    for (int i = 0; i < kCells; ++i) {
        const double t = (i + 0.5) * dt;
        const double st = std::sin(t), ct = std::cos(t);
        for (int j = 0; j < kCells; ++j) {
            const double p = (j + 0.5) * dp;
            const double sp = std::sin(p), cp = std::cos(p);
            sum += st * std::sqrt(b * b * c * c * st * st * cp * cp +
                                  a * a * c * c * st * st * sp * sp + a * a * b * b * ct * ct);
        }
    }
    return sum * dt * dp;
}
constexpr double kNumericAreaRel = 1e-5;  // midpoint rule error bound above, with margin

TEST(AnalyticObjects, VolumesMatchClosedForms) {
    EXPECT_NEAR(fm::exactVolume(BoxShape{{-1, -2, -3}, {3, 4, 5}}), 4.0 * 6.0 * 8.0, kExactMm);
    EXPECT_LT(relErr(fm::exactVolume(SphereShape{{1, 2, 3}, 10.0}), 4000.0 * kPi / 3.0), kExactRel);
    EXPECT_LT(relErr(fm::exactVolume(CylinderShape{{0, 0, 0}, 5.0, 10.0}), kPi * 25.0 * 20.0),
              kExactRel);
    EXPECT_LT(relErr(fm::exactVolume(EllipsoidShape{{0, 0, 0}, {3, 4, 5}}), 80.0 * kPi), kExactRel);
}

TEST(AnalyticObjects, AreasOfBoxSphereCylinder) {
    EXPECT_NEAR(fm::exactSurfaceArea(BoxShape{{0, 0, 0}, {2, 3, 4}}), 2.0 * (6 + 12 + 8), kExactMm);
    EXPECT_LT(relErr(fm::exactSurfaceArea(SphereShape{{0, 0, 0}, 7.0}), 4.0 * kPi * 49.0),
              kExactRel);
    // Two caps plus the side.
    EXPECT_LT(relErr(fm::exactSurfaceArea(CylinderShape{{0, 0, 0}, 3.0, 5.0}),
                     2.0 * kPi * 9.0 + 2.0 * kPi * 3.0 * 10.0),
              kExactRel);
}

TEST(AnalyticObjects, EllipsoidAreaMatchesSphereAndSpheroidClosedForms) {
    EXPECT_LT(relErr(fm::exactSurfaceArea(EllipsoidShape{{0, 0, 0}, {6, 6, 6}}), 4 * kPi * 36),
              kExactRel);
    // Prolate spheroid a > b = c: 2 pi b^2 (1 + a / (b e) asin e), e^2 = 1 - b^2 / a^2.
    {
        const double a = 10.0, b = 4.0, e = std::sqrt(1.0 - b * b / (a * a));
        const double want = 2.0 * kPi * b * b * (1.0 + a / (b * e) * std::asin(e));
        EXPECT_LT(relErr(fm::exactSurfaceArea(EllipsoidShape{{0, 0, 0}, {b, a, b}}), want), 1e-10);
    }
    // Oblate spheroid a = b > c: 2 pi a^2 + pi c^2 / e ln((1 + e) / (1 - e)), e^2 = 1 - c^2/a^2.
    {
        const double a = 10.0, c = 4.0, e = std::sqrt(1.0 - c * c / (a * a));
        const double want = 2.0 * kPi * a * a + kPi * c * c / e * std::log((1 + e) / (1 - e));
        EXPECT_LT(relErr(fm::exactSurfaceArea(EllipsoidShape{{0, 0, 0}, {a, c, a}}), want), 1e-10);
    }
}

TEST(AnalyticObjects, TriaxialEllipsoidAreaMatchesNumericIntegral) {
    for (const glm::dvec3 axes :
         {glm::dvec3(25, 18, 12), glm::dvec3(3, 10, 7), glm::dvec3(20, 20.5, 2)}) {
        const double want = numericEllipsoidArea(axes.x, axes.y, axes.z);
        EXPECT_LT(relErr(fm::exactSurfaceArea(EllipsoidShape{{1, 2, 3}, axes}), want),
                  kNumericAreaRel)
            << axes.x << " " << axes.y << " " << axes.z;
    }
}

TEST(AnalyticObjects, ContainsIsTheIndicator) {
    const SphereShape s{{1, 1, 1}, 2.0};
    EXPECT_TRUE(fm::contains(s, {1, 1, 1}));
    EXPECT_TRUE(fm::contains(s, {2.9, 1, 1}));
    EXPECT_FALSE(fm::contains(s, {3.1, 1, 1}));
    const CylinderShape c{{0, 0, 0}, 2.0, 5.0};
    EXPECT_TRUE(fm::contains(c, {1.9, 0, 4.9}));
    EXPECT_FALSE(fm::contains(c, {1.9, 0, 5.1}));  // beyond the cap
    EXPECT_FALSE(fm::contains(c, {1.5, 1.5, 0}));  // 2.12 from the axis
    const EllipsoidShape e{{0, 0, 0}, {4, 2, 1}};
    EXPECT_TRUE(fm::contains(e, {3.9, 0, 0}));
    EXPECT_FALSE(fm::contains(e, {0, 2.1, 0}));
    const BoxShape b{{0, 0, 0}, {1, 2, 3}};
    EXPECT_TRUE(fm::contains(b, {0.5, 1.9, 2.9}));
    EXPECT_FALSE(fm::contains(b, {0.5, 2.1, 1}));
}

TEST(AnalyticObjects, SphereChords) {
    const SphereShape s{{10, -5, 3}, 8.0};
    // Through the centre along each axis: the diameter.
    for (const glm::dvec3 d : {glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0), glm::dvec3(0, 0, 1)})
        EXPECT_NEAR(fm::chordLength(s, s.center - 100.0 * d, d, 0, 1e9), 16.0, kExactMm);
    // A line at distance h from the centre: 2 sqrt(r^2 - h^2).
    const double h = 5.0;
    EXPECT_NEAR(fm::chordLength(s, s.center + glm::dvec3(-50, h, 0), {1, 0, 0}, -1e9, 1e9),
                2.0 * std::sqrt(64.0 - 25.0), kExactMm);
    // A segment from the centre outwards: the radius, whatever the direction's length.
    EXPECT_NEAR(fm::chordLength(s, s.center, {0, 0, 0.25}, 0.0, 1e9), 8.0, kExactMm);
    // Segment ending inside: from 20 mm before the centre to the centre: r.
    EXPECT_NEAR(fm::chordLength(s, s.center - glm::dvec3(20, 0, 0), {20, 0, 0}, 0.0, 1.0), 8.0,
                kExactMm);
    // Misses and tangents.
    EXPECT_EQ(fm::chordLength(s, s.center + glm::dvec3(0, 9, 0), {1, 0, 0}, -1e9, 1e9), 0.0);
    EXPECT_NEAR(fm::chordLength(s, s.center + glm::dvec3(0, 8, 0), {1, 0, 0}, -1e9, 1e9), 0.0,
                1e-6);
    // Segment entirely before the sphere.
    EXPECT_EQ(fm::chordLength(s, s.center - glm::dvec3(50, 0, 0), {1, 0, 0}, 0.0, 10.0), 0.0);
    // Oblique through the centre: still the diameter.
    EXPECT_NEAR(fm::chordLength(s, s.center, glm::dvec3(1, 2, -3), -1e9, 1e9), 16.0, kExactMm);
}

TEST(AnalyticObjects, BoxChords) {
    const BoxShape b{{-10, -20, -30}, {10, 20, 30}};
    EXPECT_NEAR(fm::chordLength(b, {-100, 0, 0}, {1, 0, 0}, -1e9, 1e9), 20.0, kExactMm);
    EXPECT_NEAR(fm::chordLength(b, {0, 0, 0}, {0, 0, 1}, -1e9, 1e9), 60.0, kExactMm);
    // Face diagonal of the x-y face through the centre, and the space diagonal.
    EXPECT_NEAR(fm::chordLength(b, {0, 0, 0}, {10, 20, 0}, -1e9, 1e9), std::sqrt(400.0 + 1600.0),
                kExactMm);
    EXPECT_NEAR(fm::chordLength(b, {0, 0, 0}, {10, 20, 30}, -1e9, 1e9),
                std::sqrt(400.0 + 1600.0 + 3600.0), kExactMm);
    // Along a face plane (boundary counts as inside) and just outside it.
    EXPECT_NEAR(fm::chordLength(b, {10, 0, -100}, {0, 0, 1}, -1e9, 1e9), 60.0, kExactMm);
    EXPECT_EQ(fm::chordLength(b, {10.001, 0, -100}, {0, 0, 1}, -1e9, 1e9), 0.0);
    // A ray that enters through x = -10 and leaves through y = 20: from (-10,10) to (0,20).
    EXPECT_NEAR(fm::chordLength(b, {-20, 0, 5}, {1, 1, 0}, 0, 1e9), std::sqrt(200.0), kExactMm);
}

TEST(AnalyticObjects, CylinderChords) {
    const CylinderShape c{{1, 2, 3}, 5.0, 10.0};
    EXPECT_NEAR(fm::chordLength(c, {1, 2, -100}, {0, 0, 1}, -1e9, 1e9), 20.0, kExactMm);
    EXPECT_NEAR(fm::chordLength(c, {-100, 2, 3}, {1, 0, 0}, -1e9, 1e9), 10.0, kExactMm);
    // Parallel to the axis at 3 mm from it: the height; at 6 mm: nothing.
    EXPECT_NEAR(fm::chordLength(c, {4, 2, 0}, {0, 0, -1}, -1e9, 1e9), 20.0, kExactMm);
    EXPECT_EQ(fm::chordLength(c, {7, 2, 0}, {0, 0, -1}, -1e9, 1e9), 0.0);
    // Through the centre at 45 deg in x-z: leaves through the side at |x| = 5 (|z| = 5 < 10),
    // so the chord is 2 * 5 * sqrt(2).
    EXPECT_NEAR(fm::chordLength(c, c.center, {1, 0, 1}, -1e9, 1e9), 10.0 * std::sqrt(2.0),
                kExactMm);
    // Steep: direction (1, 0, 4) leaves through the caps at |z| = 10, |x| = 2.5 < 5.
    EXPECT_NEAR(fm::chordLength(c, c.center, {1, 0, 4}, -1e9, 1e9),
                2.0 * std::sqrt(2.5 * 2.5 + 100), kExactMm);
}

TEST(AnalyticObjects, EllipsoidChords) {
    const EllipsoidShape e{{0, 0, 0}, {10, 6, 3}};
    EXPECT_NEAR(fm::chordLength(e, {-50, 0, 0}, {1, 0, 0}, -1e9, 1e9), 20.0, kExactMm);
    EXPECT_NEAR(fm::chordLength(e, {0, -50, 0}, {0, 1, 0}, -1e9, 1e9), 12.0, kExactMm);
    EXPECT_NEAR(fm::chordLength(e, {0, 0, 50}, {0, 0, -2}, -1e9, 1e9), 6.0, kExactMm);
    // Through the centre along unit d: 2 / sqrt(sum d_i^2 / a_i^2).
    const glm::dvec3 d = glm::normalize(glm::dvec3(1, 1, 1));
    const double want = 2.0 / std::sqrt(d.x * d.x / 100 + d.y * d.y / 36 + d.z * d.z / 9);
    EXPECT_NEAR(fm::chordLength(e, {0, 0, 0}, d, -1e9, 1e9), want, kExactMm);
}

TEST(AnalyticObjects, ZeroDirectionIsAnError) {
    EXPECT_THROW(fm::chordLength(SphereShape{{0, 0, 0}, 1}, {0, 0, 0}, {0, 0, 0}, 0, 1), fm::Error);
}

TEST(AnalyticObjects, InvalidShapesAreRejected) {
    EXPECT_THROW(fm::validateShape(SphereShape{{0, 0, 0}, -1}, "s"), fm::Error);
    EXPECT_THROW(fm::validateShape(BoxShape{{0, 0, 0}, {1, 0, 1}}, "b"), fm::Error);
    EXPECT_THROW(fm::validateShape(CylinderShape{{0, 0, 0}, 1, 0}, "c"), fm::Error);
    EXPECT_THROW(fm::validateShape(EllipsoidShape{{0, 0, 0}, {1, std::nan(""), 1}}, "e"),
                 fm::Error);
    EXPECT_THROW(fm::voxelize(SphereShape{{0, 0, 0}, 1}, fm::VoxelGrid{}, 1, 0, 0), fm::Error);
}

double totalMass(const fm::Volume& v) {
    double sum = 0.0;
    for (float x : v.values) sum += x;
    return sum * v.spacing.x * v.spacing.y * v.spacing.z;
}

// The box voxelizer computes each voxel's overlap exactly, so the mass is the volume up to the
// float storage of the fractions (~1e-7 relative each).
constexpr double kBoxMassRel = 1e-6;

TEST(AnalyticObjects, VoxelizedBoxMassIsExactEvenOffGrid) {
    const BoxShape b{{-7.3, -5.1, -9.7}, {6.2, 8.9, 3.3}};
    for (double h : {2.0, 0.7}) {
        const fm::Volume v =
            fm::voxelize(b, fm::centeredGrid(glm::ivec3(int(40 / h)), glm::dvec3(h)));
        EXPECT_LT(relErr(totalMass(v), fm::exactVolume(b)), kBoxMassRel) << "h " << h;
    }
}

// Curved shapes: each boundary voxel's fraction is estimated from n^3 midpoint samples, an
// error of standard deviation about sigma1 = 1 / (n sqrt(12)) of the voxel (uniform rounding
// to 1/n), with signs that vary along the surface. Summed over the ~area / h^2 boundary voxels
// this is a random walk: sqrt(area) h^2 sigma1 in mm^3. For the cylinder (axis along z, caps
// on voxel faces or mid-planes, where midpoint sampling is exact) the side's error repeats
// identically in every z layer, so it is coherent along the axis: the walk runs over the
// perimeter / h columns only, giving sqrt(perimeter) h^1.5 sigma1 * height.
// We allow three standard deviations relative to the volume: the bound shrinks with h, and a
// voxelizer without partial volumes (n = 1) or with a bias would break it.
double massTolerance(const AnalyticShape& s, double h, int n) {
    const double sigma1 = 1.0 / (n * std::sqrt(12.0));
    double sigma;
    if (const auto* c = std::get_if<CylinderShape>(&s))
        sigma = std::sqrt(2.0 * kPi * c->radius) * std::pow(h, 1.5) * sigma1 * 2.0 * c->halfHeight;
    else
        sigma = std::sqrt(fm::exactSurfaceArea(s)) * h * h * sigma1;
    return 3.0 * sigma / fm::exactVolume(s);
}

TEST(AnalyticObjects, VoxelizedMassConvergesToVolume) {
    const glm::dvec3 c{0.3, -0.2, 0.1};  // off the grid's symmetry
    // The cylinder's caps at z = +-9 fall on voxel faces (h = 1, 0.5) or mid-planes (h = 2).
    const AnalyticShape shapes[] = {SphereShape{c, 10.0}, CylinderShape{{0.3, -0.2, 0.0}, 8.0, 9.0},
                                    EllipsoidShape{c, {12.0, 9.0, 6.0}}};
    constexpr int kSupersample = 4;
    for (const AnalyticShape& s : shapes)
        for (double h : {2.0, 1.0, 0.5}) {
            const int n = 2 * static_cast<int>(std::ceil(15.0 / h));  // even: faces at k * h
            const fm::Volume v = fm::voxelize(s, fm::centeredGrid(glm::ivec3(n), glm::dvec3(h)),
                                              1.0f, 0.0f, kSupersample);
            EXPECT_LT(relErr(totalMass(v), fm::exactVolume(s)), massTolerance(s, h, kSupersample))
                << fm::shapeName(s) << " h " << h;
        }
}

TEST(AnalyticObjects, VoxelValuesAreFractionsBetweenOutsideAndInside) {
    const SphereShape s{{0, 0, 0}, 6.0};
    const fm::Volume v =
        fm::voxelize(s, fm::centeredGrid(glm::ivec3(16), glm::dvec3(1.0)), 1000.0f, -1000.0f, 4);
    int partial = 0;
    for (float x : v.values) {
        EXPECT_GE(x, -1000.0f);
        EXPECT_LE(x, 1000.0f);
        if (x > -1000.0f && x < 1000.0f) ++partial;
    }
    EXPECT_GT(partial, 0);  // the boundary is anti-aliased
    // Centre voxel fully inside, corner voxel fully outside.
    EXPECT_EQ(v.at(8, 8, 8), 1000.0f);
    EXPECT_EQ(v.at(0, 0, 0), -1000.0f);
    // Mass from the +-1000 values: -1000 * total + 2000 * inside volume.
    double sum = 0.0;
    for (float x : v.values) sum += x;
    const double insideMm3 = (sum + 1000.0 * v.voxelCount()) / 2000.0;
    EXPECT_LT(relErr(insideMm3, fm::exactVolume(s)), massTolerance(s, 1.0, 4));
}

TEST(AnalyticObjects, VoxelizeIsThreadIndependent) {
    const EllipsoidShape e{{0.2, 0, 0}, {9, 7, 5}};
    const fm::VoxelGrid g = fm::centeredGrid(glm::ivec3(24), glm::dvec3(1.0));
    EXPECT_EQ(fm::voxelize(e, g, 1, 0, 3, 1).values, fm::voxelize(e, g, 1, 0, 3, 2).values);
}

}  // namespace

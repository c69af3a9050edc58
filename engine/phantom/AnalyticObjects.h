#pragma once
// Analytic test objects with exactly known answers: volume, surface area, the length of any
// line segment inside them (the exact line integral of a unit-density object) and a voxelizer
// whose partial-volume values converge to the exact mass. Used to check the DRR (line
// integrals) and marching cubes (volume, area, topology: every shape here is a topological
// sphere, Euler characteristic 2).
//
// All positions are world millimetres; the shapes are axis-aligned in the world frame.
#include <string>
#include <variant>

#include <glm/glm.hpp>

#include "volume/Volume.h"

namespace fm {

struct BoxShape {
    glm::dvec3 min{0.0};  // corner with the smallest coordinates
    glm::dvec3 max{0.0};  // opposite corner
};

struct SphereShape {
    glm::dvec3 center{0.0};
    double radius = 0.0;
};

// Finite circular cylinder with its axis along world z, flat caps.
struct CylinderShape {
    glm::dvec3 center{0.0};  // midpoint of the axis
    double radius = 0.0;
    double halfHeight = 0.0;  // caps at center.z +- halfHeight
};

struct EllipsoidShape {
    glm::dvec3 center{0.0};
    glm::dvec3 semiAxes{0.0};  // along world x, y, z
};

using AnalyticShape = std::variant<BoxShape, SphereShape, CylinderShape, EllipsoidShape>;

// "box", "sphere", "cylinder" or "ellipsoid".
std::string shapeName(const AnalyticShape& shape);

// Throws fm::Error naming `what` if a size is not positive or a number is not finite.
void validateShape(const AnalyticShape& shape, const std::string& what);

// True if p is inside or on the surface.
bool contains(const AnalyticShape& shape, const glm::dvec3& p);

// Exact volume (mm^3).
double exactVolume(const AnalyticShape& shape);

// Surface area (mm^2). Exact closed forms for box, sphere and cylinder. For a general
// ellipsoid, Legendre's formula with incomplete elliptic integrals of the first and second
// kind (std::ellint_1/ellint_2, accurate to ~1e-15 relative), with the spheroid and sphere
// limits handled by their closed forms.
double exactSurfaceArea(const AnalyticShape& shape);

// Axis-aligned bounding box of the shape.
BoxShape boundingBox(const AnalyticShape& shape);

// Where the infinite line origin + t * direction is inside the shape: t in [tEnter, tExit].
// `hit` is false if the line misses (or only grazes the surface in a single point).
struct LineInterval {
    bool hit = false;
    double tEnter = 0.0;
    double tExit = 0.0;
};
// `direction` must be non-zero (need not be unit); throws fm::Error otherwise.
LineInterval intersectLine(const AnalyticShape& shape, const glm::dvec3& origin,
                           const glm::dvec3& direction);

// Length in mm of the part of the segment {origin + t * direction : t in [tMin, tMax]} that is
// inside the shape: the exact line integral through a unit-density object.
// E.g. for a DRR ray from source s to pixel p: chordLength(shape, s, p - s, 0, 1).
double chordLength(const AnalyticShape& shape, const glm::dvec3& origin,
                   const glm::dvec3& direction, double tMin, double tMax);

// A regular axis-aligned grid (direction identity), ITK convention: voxel (i,j,k)'s centre is
// at origin + spacing * (i,j,k) and the voxel is the box of size `spacing` around it.
struct VoxelGrid {
    glm::ivec3 dims{64};
    glm::dvec3 spacing{1.0};
    glm::dvec3 origin{0.0};
};

// A grid of `dims` voxels of `spacing` whose centre (Volume::center()) is at `center`.
VoxelGrid centeredGrid(glm::ivec3 dims, glm::dvec3 spacing, glm::dvec3 center = glm::dvec3(0.0));

// Fills each voxel with outsideValue + f * (insideValue - outsideValue), f the fraction of the
// voxel's box inside the shape. f is exact for the box (overlap of intervals); for the other
// shapes, voxels whose 8 corners are all inside (shapes are convex: f = 1) or whose box misses
// the bounding box (f = 0) are exact, and the rest use supersample^3 midpoint samples.
// So the total mass converges to the exact volume as spacing shrinks or supersample grows.
// Units are left Unknown (raw values), source "phantom:<name>".
Volume voxelize(const AnalyticShape& shape, const VoxelGrid& grid, float insideValue = 1.0f,
                float outsideValue = 0.0f, int supersample = 4, int threads = 0);

}  // namespace fm

#include "phantom/AnalyticObjects.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

#include "core/Error.h"
#include "core/Parallel.h"

namespace fm {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kInf = std::numeric_limits<double>::infinity();

template <class... Ts>
struct Overloaded : Ts... {
    using Ts::operator()...;
};
template <class... Ts>
Overloaded(Ts...) -> Overloaded<Ts...>;

bool finite3(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Roots of a t^2 + b t + c = 0 as an interval, computed without cancellation.
LineInterval quadraticInterval(double a, double b, double c) {
    LineInterval out;
    const double disc = b * b - 4.0 * a * c;
    if (!(disc > 0.0) || a <= 0.0) return out;
    const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
    double t0 = q / a;
    double t1 = (q != 0.0) ? c / q : -t0;
    if (t0 > t1) std::swap(t0, t1);
    out.hit = t1 > t0;
    out.tEnter = t0;
    out.tExit = t1;
    return out;
}

// Slab [lo, hi] along one axis: the t-range where o + t d lies in it (all t if d == 0 and o is
// inside, none if outside).
bool clipSlab(double o, double d, double lo, double hi, double& tEnter, double& tExit) {
    if (d == 0.0) return o >= lo && o <= hi;
    double t0 = (lo - o) / d;
    double t1 = (hi - o) / d;
    if (t0 > t1) std::swap(t0, t1);
    tEnter = std::max(tEnter, t0);
    tExit = std::min(tExit, t1);
    return true;
}

// Squared distance from the point c to the axis-aligned box [lo, hi] (0 if inside).
double squaredDistanceToBox(const glm::dvec3& c, const glm::dvec3& lo, const glm::dvec3& hi) {
    const glm::dvec3 q = glm::clamp(c, lo, hi) - c;
    return glm::dot(q, q);
}

// True if the voxel box [lo, hi] has no point strictly inside the shape (exact tests).
bool boxOutside(const AnalyticShape& shape, const glm::dvec3& lo, const glm::dvec3& hi) {
    return std::visit(
        Overloaded{
            [&](const BoxShape& b) {
                return glm::any(glm::greaterThanEqual(lo, b.max)) ||
                       glm::any(glm::lessThanEqual(hi, b.min));
            },
            [&](const SphereShape& s) {
                return squaredDistanceToBox(s.center, lo, hi) >= s.radius * s.radius;
            },
            [&](const CylinderShape& c) {
                if (hi.z <= c.center.z - c.halfHeight || lo.z >= c.center.z + c.halfHeight)
                    return true;
                const glm::dvec2 q =
                    glm::clamp(glm::dvec2(c.center), glm::dvec2(lo), glm::dvec2(hi)) -
                    glm::dvec2(c.center);
                return glm::dot(q, q) >= c.radius * c.radius;
            },
            [&](const EllipsoidShape& e) {
                // Scaling by 1/semiAxes maps the ellipsoid to the unit ball and the voxel box to
                // another axis-aligned box.
                const glm::dvec3 l = (lo - e.center) / e.semiAxes;
                const glm::dvec3 h = (hi - e.center) / e.semiAxes;
                return squaredDistanceToBox(glm::dvec3(0.0), l, h) >= 1.0;
            },
        },
        shape);
}

double boxOverlapFraction(const BoxShape& b, const glm::dvec3& lo, const glm::dvec3& hi) {
    double f = 1.0;
    for (int a = 0; a < 3; ++a) {
        const double overlap = std::min(hi[a], b.max[a]) - std::max(lo[a], b.min[a]);
        if (overlap <= 0.0) return 0.0;
        f *= overlap / (hi[a] - lo[a]);
    }
    return f;
}

}  // namespace

std::string shapeName(const AnalyticShape& shape) {
    return std::visit(Overloaded{
                          [](const BoxShape&) { return std::string("box"); },
                          [](const SphereShape&) { return std::string("sphere"); },
                          [](const CylinderShape&) { return std::string("cylinder"); },
                          [](const EllipsoidShape&) { return std::string("ellipsoid"); },
                      },
                      shape);
}

void validateShape(const AnalyticShape& shape, const std::string& what) {
    auto fail = [&](const std::string& why) { throw Error(what + ": " + why); };
    auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
    std::visit(
        Overloaded{
            [&](const BoxShape& b) {
                if (!finite3(b.min) || !finite3(b.max)) fail("box corners must be finite");
                if (!glm::all(glm::lessThan(b.min, b.max)))
                    fail("box must have positive size along x, y and z");
            },
            [&](const SphereShape& s) {
                if (!finite3(s.center)) fail("sphere centre must be finite");
                if (!positive(s.radius)) fail("sphere radius must be positive");
            },
            [&](const CylinderShape& c) {
                if (!finite3(c.center)) fail("cylinder centre must be finite");
                if (!positive(c.radius)) fail("cylinder radius must be positive");
                if (!positive(c.halfHeight)) fail("cylinder height must be positive");
            },
            [&](const EllipsoidShape& e) {
                if (!finite3(e.center)) fail("ellipsoid centre must be finite");
                if (!positive(e.semiAxes.x) || !positive(e.semiAxes.y) || !positive(e.semiAxes.z))
                    fail("ellipsoid semi-axes must be positive");
            },
        },
        shape);
}

bool contains(const AnalyticShape& shape, const glm::dvec3& p) {
    return std::visit(Overloaded{
                          [&](const BoxShape& b) {
                              return glm::all(glm::greaterThanEqual(p, b.min)) &&
                                     glm::all(glm::lessThanEqual(p, b.max));
                          },
                          [&](const SphereShape& s) {
                              const glm::dvec3 d = p - s.center;
                              return glm::dot(d, d) <= s.radius * s.radius;
                          },
                          [&](const CylinderShape& c) {
                              const glm::dvec2 d = glm::dvec2(p) - glm::dvec2(c.center);
                              return std::abs(p.z - c.center.z) <= c.halfHeight &&
                                     glm::dot(d, d) <= c.radius * c.radius;
                          },
                          [&](const EllipsoidShape& e) {
                              const glm::dvec3 d = (p - e.center) / e.semiAxes;
                              return glm::dot(d, d) <= 1.0;
                          },
                      },
                      shape);
}

double exactVolume(const AnalyticShape& shape) {
    return std::visit(
        Overloaded{
            [](const BoxShape& b) {
                const glm::dvec3 s = b.max - b.min;
                return s.x * s.y * s.z;
            },
            [](const SphereShape& s) { return 4.0 / 3.0 * kPi * s.radius * s.radius * s.radius; },
            [](const CylinderShape& c) { return kPi * c.radius * c.radius * 2.0 * c.halfHeight; },
            [](const EllipsoidShape& e) {
                return 4.0 / 3.0 * kPi * e.semiAxes.x * e.semiAxes.y * e.semiAxes.z;
            },
        },
        shape);
}

namespace {

double ellipsoidArea(glm::dvec3 axes) {
    double s[3] = {axes.x, axes.y, axes.z};
    std::sort(s, s + 3, std::greater<double>());
    const double a = s[0], b = s[1], c = s[2];
    // Nearly a sphere: Legendre's formula divides by sin(phi) -> 0. The mean of the pairwise
    // products is then exact to second order in the axis differences (< 1e-18 relative here).
    constexpr double kSphereRelTol = 1e-9;
    if (a - c <= kSphereRelTol * a) return 4.0 * kPi * (a * b + a * c + b * c) / 3.0;
    const double phi = std::acos(c / a);
    const double sinPhi = std::sin(phi);
    const double cosPhi = c / a;
    if (a - b <= kSphereRelTol * a) {
        // Oblate spheroid (a = b > c): closed form, avoids modulus k = 1.
        const double e = std::sqrt(1.0 - (c * c) / (a * a));
        return 2.0 * kPi * a * a * (1.0 + (1.0 - e * e) / e * std::atanh(e));
    }
    const double k = std::sqrt((a * a * (b * b - c * c)) / (b * b * (a * a - c * c)));
    const double F = std::ellint_1(k, phi);
    const double E = std::ellint_2(k, phi);
    return 2.0 * kPi * c * c +
           2.0 * kPi * a * b / sinPhi * (E * sinPhi * sinPhi + F * cosPhi * cosPhi);
}

}  // namespace

double exactSurfaceArea(const AnalyticShape& shape) {
    return std::visit(Overloaded{
                          [](const BoxShape& b) {
                              const glm::dvec3 s = b.max - b.min;
                              return 2.0 * (s.x * s.y + s.y * s.z + s.z * s.x);
                          },
                          [](const SphereShape& s) { return 4.0 * kPi * s.radius * s.radius; },
                          [](const CylinderShape& c) {
                              return 2.0 * kPi * c.radius * c.radius +
                                     2.0 * kPi * c.radius * 2.0 * c.halfHeight;
                          },
                          [](const EllipsoidShape& e) { return ellipsoidArea(e.semiAxes); },
                      },
                      shape);
}

BoxShape boundingBox(const AnalyticShape& shape) {
    return std::visit(Overloaded{
                          [](const BoxShape& b) { return b; },
                          [](const SphereShape& s) {
                              return BoxShape{s.center - s.radius, s.center + s.radius};
                          },
                          [](const CylinderShape& c) {
                              const glm::dvec3 h{c.radius, c.radius, c.halfHeight};
                              return BoxShape{c.center - h, c.center + h};
                          },
                          [](const EllipsoidShape& e) {
                              return BoxShape{e.center - e.semiAxes, e.center + e.semiAxes};
                          },
                      },
                      shape);
}

LineInterval intersectLine(const AnalyticShape& shape, const glm::dvec3& origin,
                           const glm::dvec3& direction) {
    if (!finite3(origin) || !finite3(direction) || glm::dot(direction, direction) == 0.0)
        throw Error("line through " + shapeName(shape) +
                    ": the origin must be finite and the direction finite and non-zero");
    return std::visit(
        Overloaded{
            [&](const BoxShape& b) {
                LineInterval out;
                double t0 = -kInf, t1 = kInf;
                for (int a = 0; a < 3; ++a)
                    if (!clipSlab(origin[a], direction[a], b.min[a], b.max[a], t0, t1)) return out;
                out.hit = t1 > t0;
                out.tEnter = t0;
                out.tExit = t1;
                return out;
            },
            [&](const SphereShape& s) {
                const glm::dvec3 o = (origin - s.center) / s.radius;
                const glm::dvec3 d = direction / s.radius;
                return quadraticInterval(glm::dot(d, d), 2.0 * glm::dot(o, d),
                                         glm::dot(o, o) - 1.0);
            },
            [&](const CylinderShape& c) {
                LineInterval out;
                double t0 = -kInf, t1 = kInf;
                const glm::dvec2 o = (glm::dvec2(origin) - glm::dvec2(c.center)) / c.radius;
                const glm::dvec2 d = glm::dvec2(direction) / c.radius;
                if (glm::dot(d, d) == 0.0) {
                    if (glm::dot(o, o) > 1.0) return out;  // parallel to the axis, outside
                } else {
                    const LineInterval side = quadraticInterval(
                        glm::dot(d, d), 2.0 * glm::dot(o, d), glm::dot(o, o) - 1.0);
                    if (!side.hit) return out;
                    t0 = side.tEnter;
                    t1 = side.tExit;
                }
                if (!clipSlab(origin.z, direction.z, c.center.z - c.halfHeight,
                              c.center.z + c.halfHeight, t0, t1))
                    return out;
                out.hit = t1 > t0;
                out.tEnter = t0;
                out.tExit = t1;
                return out;
            },
            [&](const EllipsoidShape& e) {
                const glm::dvec3 o = (origin - e.center) / e.semiAxes;
                const glm::dvec3 d = direction / e.semiAxes;
                return quadraticInterval(glm::dot(d, d), 2.0 * glm::dot(o, d),
                                         glm::dot(o, o) - 1.0);
            },
        },
        shape);
}

double chordLength(const AnalyticShape& shape, const glm::dvec3& origin,
                   const glm::dvec3& direction, double tMin, double tMax) {
    const LineInterval in = intersectLine(shape, origin, direction);
    if (!in.hit) return 0.0;
    const double t0 = std::max(in.tEnter, tMin);
    const double t1 = std::min(in.tExit, tMax);
    if (!(t1 > t0)) return 0.0;
    return (t1 - t0) * glm::length(direction);
}

VoxelGrid centeredGrid(glm::ivec3 dims, glm::dvec3 spacing, glm::dvec3 center) {
    VoxelGrid g;
    g.dims = dims;
    g.spacing = spacing;
    g.origin = center - (glm::dvec3(dims) - 1.0) * 0.5 * spacing;
    return g;
}

Volume voxelize(const AnalyticShape& shape, const VoxelGrid& grid, float insideValue,
                float outsideValue, int supersample, int threads) {
    const std::string what = "voxelizing a " + shapeName(shape);
    validateShape(shape, what);
    constexpr int kMaxSupersample = 64;  // 262144 samples per boundary voxel is already absurd
    if (supersample < 1 || supersample > kMaxSupersample) {
        std::ostringstream msg;
        msg << what << ": supersampling must be 1.." << kMaxSupersample << ", got " << supersample;
        throw Error(msg.str());
    }
    if (!std::isfinite(insideValue) || !std::isfinite(outsideValue))
        throw Error(what + ": inside and outside values must be finite");

    Volume v = Volume::allocate(grid.dims, outsideValue);
    v.spacing = grid.spacing;
    v.origin = grid.origin;
    v.validate(what);
    v.meta.source = "phantom:" + shapeName(shape);
    v.meta.units = ValueUnit::Unknown;

    const BoxShape bounds = boundingBox(shape);
    const glm::dvec3 half = grid.spacing * 0.5;
    const int n = supersample;
    const double invSamples = 1.0 / (static_cast<double>(n) * n * n);
    const double range = static_cast<double>(insideValue) - outsideValue;

    parallelFor(grid.dims.z, threads, [&](int k0, int k1) {
        for (int k = k0; k < k1; ++k)
            for (int j = 0; j < grid.dims.y; ++j)
                for (int i = 0; i < grid.dims.x; ++i) {
                    const glm::dvec3 c = grid.origin + grid.spacing * glm::dvec3(i, j, k);
                    const glm::dvec3 lo = c - half, hi = c + half;
                    if (glm::any(glm::greaterThanEqual(lo, bounds.max)) ||
                        glm::any(glm::lessThanEqual(hi, bounds.min)) || boxOutside(shape, lo, hi))
                        continue;
                    double f;
                    if (const auto* box = std::get_if<BoxShape>(&shape)) {
                        f = boxOverlapFraction(*box, lo, hi);
                    } else {
                        bool allCornersInside = true;
                        for (int corner = 0; corner < 8 && allCornersInside; ++corner) {
                            const glm::dvec3 p{corner & 1 ? hi.x : lo.x, corner & 2 ? hi.y : lo.y,
                                               corner & 4 ? hi.z : lo.z};
                            allCornersInside = contains(shape, p);
                        }
                        if (allCornersInside) {
                            f = 1.0;  // convex shape: the whole voxel is inside
                        } else {
                            int inside = 0;
                            for (int c2 = 0; c2 < n; ++c2)
                                for (int b = 0; b < n; ++b)
                                    for (int a = 0; a < n; ++a) {
                                        const glm::dvec3 frac{(a + 0.5) / n, (b + 0.5) / n,
                                                              (c2 + 0.5) / n};
                                        if (contains(shape, lo + frac * grid.spacing)) ++inside;
                                    }
                            f = inside * invSamples;
                        }
                    }
                    v.at(i, j, k) = static_cast<float>(outsideValue + f * range);
                }
    });
    return v;
}

}  // namespace fm

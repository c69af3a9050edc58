#pragma once
// Helpers for the DRR tests: small volumes, an independent chord-length truth (slab method in
// long double) and simple orbit geometries built directly as ProjectionGeometry.
#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "drr/Drr.h"
#include "geometry/ProjectionGeometry.h"
#include "volume/Volume.h"

namespace fm::test {

// A rotation matrix (columns orthonormal) from an axis and an angle.
inline glm::dmat3 rotation(double degrees, glm::dvec3 axis) {
    return glm::dmat3(glm::rotate(glm::dmat4(1.0), glm::radians(degrees), glm::normalize(axis)));
}

inline Volume makeVolume(glm::ivec3 dims, glm::dvec3 spacing, float fill = 0.0f,
                         glm::dvec3 origin = glm::dvec3(0.0),
                         glm::dmat3 direction = glm::dmat3(1.0)) {
    Volume v = Volume::allocate(dims, fill);
    v.spacing = spacing;
    v.origin = origin;
    v.direction = direction;
    v.meta.source = "test";
    return v;
}

// Exact length (mm) of the part of segment source->target inside the box of voxels
// [lo, hi] (inclusive voxel indices) of `volume`: slab method in long double, on the world
// segment mapped to index space with the transposed direction (orthonormal in the tests).
inline long double slabChord(const Volume& volume, glm::dvec3 source, glm::dvec3 target,
                             glm::ivec3 lo, glm::ivec3 hi) {
    using R = long double;
    R p0[3], d[3];
    for (int a = 0; a < 3; ++a) {
        R s = 0, t = 0;
        for (int w = 0; w < 3; ++w) {
            s += R(volume.direction[a][w]) * (R(source[w]) - R(volume.origin[w]));
            t += R(volume.direction[a][w]) * (R(target[w]) - R(volume.origin[w]));
        }
        p0[a] = s;
        d[a] = t - s;
    }
    R tMin = 0, tMax = 1;
    for (int a = 0; a < 3; ++a) {
        const R boxLo = (R(lo[a]) - R(0.5)) * R(volume.spacing[a]);
        const R boxHi = (R(hi[a]) + R(0.5)) * R(volume.spacing[a]);
        if (d[a] == 0) {
            if (p0[a] < boxLo || p0[a] >= boxHi) return 0;
            continue;
        }
        R t0 = (boxLo - p0[a]) / d[a], t1 = (boxHi - p0[a]) / d[a];
        if (t0 > t1) std::swap(t0, t1);
        tMin = std::max(tMin, t0);
        tMax = std::min(tMax, t1);
    }
    if (tMax <= tMin) return 0;
    R length2 = 0;
    for (int a = 0; a < 3; ++a)
        length2 += (R(target[a]) - R(source[a])) * (R(target[a]) - R(source[a]));
    return (tMax - tMin) * std::sqrt(length2);
}

inline long double slabChord(const Volume& volume, glm::dvec3 source, glm::dvec3 target) {
    return slabChord(volume, source, target, glm::ivec3(0), volume.dims - 1);
}

// A source on a sphere around `center` (azimuth in the x-y plane from +x, elevation towards
// +z) and a square detector facing it on the other side, centred on the central ray.
inline ProjectionGeometry orbitGeometry(glm::dvec3 center, double azimuthDeg, double elevationDeg,
                                        double sourceToCenter, double centerToDetector, int pixels,
                                        double pixelMm) {
    const double az = glm::radians(azimuthDeg), el = glm::radians(elevationDeg);
    const glm::dvec3 s(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el));
    const glm::dvec3 eAz(-std::sin(az), std::cos(az), 0.0);
    const glm::dvec3 eEl = glm::cross(s, eAz);
    ProjectionGeometry g;
    g.source = center + sourceToCenter * s;
    g.detector.size = {pixels, pixels};
    g.detector.spacing = {pixelMm, pixelMm};
    g.detector.u = eAz;
    g.detector.v = eEl;
    const glm::dvec3 filmCenter = center - centerToDetector * s;
    g.detector.origin = filmCenter - 0.5 * (pixels - 1) * pixelMm * (eAz + eEl);
    return g;
}

inline double maxAbs(const Image& image) {
    double m = 0.0;
    for (float p : image.pixels) m = std::max(m, double(std::abs(p)));
    return m;
}

inline double maxAbsDifference(const Image& a, const Image& b) {
    double m = 0.0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i)
        m = std::max(m, std::abs(double(a.pixels[i]) - double(b.pixels[i])));
    return m;
}

inline bool allFinite(const Image& image) {
    return std::all_of(image.pixels.begin(), image.pixels.end(),
                       [](float p) { return std::isfinite(p); });
}

}  // namespace fm::test

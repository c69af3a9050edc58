// The slow reference DRR: Siddon's original algorithm (Siddon 1985) in long double, written
// independently of the fast renderer (no cropping, no bricks, no incremental state): for each
// ray, every crossing with the planes x = 0..nx, y = 0..ny, z = 0..nz (continuous index + 0.5,
// so voxel i spans [i, i+1)) inside the clipped range is listed and sorted, and each segment's
// voxel is found from its midpoint.
#include <algorithm>
#include <cmath>
#include <vector>

#include "core/Error.h"
#include "core/Parallel.h"
#include "drr/Drr.h"

namespace fm {
namespace {

using Real = long double;

struct Vec3L {
    Real x[3];
};

// Inverse of a 3x3 matrix (columns = axes) in long double, by cofactors.
void inverse3(const glm::dmat3& m, Real inv[3][3]) {
    Real a[3][3];
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) a[r][c] = m[c][r];  // a[row][col]
    const Real det = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
                     a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
                     a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
    inv[0][0] = (a[1][1] * a[2][2] - a[1][2] * a[2][1]) / det;
    inv[0][1] = (a[0][2] * a[2][1] - a[0][1] * a[2][2]) / det;
    inv[0][2] = (a[0][1] * a[1][2] - a[0][2] * a[1][1]) / det;
    inv[1][0] = (a[1][2] * a[2][0] - a[1][0] * a[2][2]) / det;
    inv[1][1] = (a[0][0] * a[2][2] - a[0][2] * a[2][0]) / det;
    inv[1][2] = (a[0][2] * a[1][0] - a[0][0] * a[1][2]) / det;
    inv[2][0] = (a[1][0] * a[2][1] - a[1][1] * a[2][0]) / det;
    inv[2][1] = (a[0][1] * a[2][0] - a[0][0] * a[2][1]) / det;
    inv[2][2] = (a[0][0] * a[1][1] - a[0][1] * a[1][0]) / det;
}

}  // namespace

namespace {

// The reference line integral of one ray, long double throughout.
Real referenceRay(const Volume& volume, const DrrValueOptions& valueOptions, const Real inv[3][3],
                  const Real source[3], const Real target[3], std::vector<Real>& alphas) {
    const int dims[3] = {volume.dims.x, volume.dims.y, volume.dims.z};
    // World -> continuous index + 0.5 (voxel i spans [i, i+1)).
    auto toGrid = [&](const Real w[3]) {
        Vec3L out;
        Real rel[3];
        for (int a = 0; a < 3; ++a) rel[a] = w[a] - Real(volume.origin[a]);
        for (int a = 0; a < 3; ++a) {
            const Real mm = inv[a][0] * rel[0] + inv[a][1] * rel[1] + inv[a][2] * rel[2];
            out.x[a] = mm / Real(volume.spacing[a]) + Real(0.5);
        }
        return out;
    };
    Real length2 = 0;
    for (int a = 0; a < 3; ++a) length2 += (target[a] - source[a]) * (target[a] - source[a]);
    const Vec3L p0 = toGrid(source), p1 = toGrid(target);
    Real d[3];
    Real aMin = 0, aMax = 1;
    for (int a = 0; a < 3; ++a) {
        d[a] = p1.x[a] - p0.x[a];
        if (d[a] == 0) {
            if (!(p0.x[a] >= 0 && p0.x[a] < dims[a])) return 0;
            continue;
        }
        Real t0 = (0 - p0.x[a]) / d[a], t1 = (dims[a] - p0.x[a]) / d[a];
        if (t0 > t1) std::swap(t0, t1);
        aMin = std::max(aMin, t0);
        aMax = std::min(aMax, t1);
    }
    if (!(aMax > aMin)) return 0;
    alphas.clear();
    alphas.push_back(aMin);
    alphas.push_back(aMax);
    for (int a = 0; a < 3; ++a) {
        if (d[a] == 0) continue;
        const Real x0 = p0.x[a] + aMin * d[a], x1 = p0.x[a] + aMax * d[a];
        const long long k0 = static_cast<long long>(std::ceil(std::min(x0, x1)));
        const long long k1 = static_cast<long long>(std::floor(std::max(x0, x1)));
        for (long long k = std::max(0LL, k0); k <= std::min<long long>(dims[a], k1); ++k) {
            const Real t = (Real(k) - p0.x[a]) / d[a];
            if (t > aMin && t < aMax) alphas.push_back(t);
        }
    }
    std::sort(alphas.begin(), alphas.end());
    Real integral = 0;
    for (std::size_t s = 0; s + 1 < alphas.size(); ++s) {
        const Real seg = alphas[s + 1] - alphas[s];
        if (!(seg > 0)) continue;
        const Real mid = (alphas[s] + alphas[s + 1]) / 2;
        int idx[3];
        bool inside = true;
        for (int a = 0; a < 3; ++a) {
            const Real x = p0.x[a] + mid * d[a];
            idx[a] = static_cast<int>(std::floor(x));
            if (idx[a] < 0 || idx[a] >= dims[a]) inside = false;
        }
        if (inside)
            integral +=
                seg * Real(drrVoxelValue(volume.values[volume.index(idx[0], idx[1], idx[2])],
                                         valueOptions));
    }
    return integral * std::sqrt(length2);
}

void checkVolume(const Volume& volume) {
    volume.validate("volume '" + volume.meta.source + "'");
    if (volume.values.size() != volume.voxelCount())
        throw Error("reference DRR: volume '" + volume.meta.source + "' has no values");
}

}  // namespace

double drrReferenceLineIntegral(const Volume& volume, const DrrValueOptions& values,
                                const glm::dvec3& source, const glm::dvec3& target) {
    checkVolume(volume);
    Real inv[3][3];
    inverse3(volume.direction, inv);
    const Real s[3] = {source.x, source.y, source.z}, t[3] = {target.x, target.y, target.z};
    std::vector<Real> alphas;
    return static_cast<double>(referenceRay(volume, values, inv, s, t, alphas));
}

Image renderDrrReference(const Volume& volume, const DrrValueOptions& valueOptions,
                         const ProjectionGeometry& g, DrrOutput output, int threads) {
    checkVolume(volume);
    const DetectorGeometry& det = g.detector;
    if (det.size.x <= 0 || det.size.y <= 0) throw Error("reference DRR: empty detector");
    const bool intensity = output == DrrOutput::Intensity;
    Image image(det.size.x, det.size.y, 0.0f);
    image.spacing = det.spacing;
    Real inv[3][3];
    inverse3(volume.direction, inv);
    auto body = [&](int rowBegin, int rowEnd) {
        std::vector<Real> alphas;
        for (int row = rowBegin; row < rowEnd; ++row)
            for (int col = 0; col < det.size.x; ++col) {
                Real source[3], pixel[3];
                for (int a = 0; a < 3; ++a) {
                    source[a] = g.source[a];
                    pixel[a] = Real(det.origin[a]) +
                               Real(col) * Real(det.spacing.x) * Real(det.u[a]) +
                               Real(row) * Real(det.spacing.y) * Real(det.v[a]);
                }
                const double integral = static_cast<double>(
                    referenceRay(volume, valueOptions, inv, source, pixel, alphas));
                image.at(col, row) = static_cast<float>(intensity ? std::exp(-integral) : integral);
            }
    };
    parallelFor(det.size.y, threads, body, 4);
    return image;
}

}  // namespace fm

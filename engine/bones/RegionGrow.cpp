#include "bones/RegionGrow.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "bones/ConnectedComponents.h"
#include "core/Error.h"

namespace fm {

Volume regionGrow(const Volume& ct, const glm::ivec3& seed, const RegionGrowOptions& options) {
    ct.validate("CT");
    if (!(options.lower <= options.upper))
        throw Error("region growing: the lower level must not exceed the upper level");
    if (glm::any(glm::lessThan(seed, glm::ivec3(0))) ||
        glm::any(glm::greaterThanEqual(seed, ct.dims))) {
        std::ostringstream msg;
        msg << "region growing: seed voxel (" << seed.x << ", " << seed.y << ", " << seed.z
            << ") lies outside the " << ct.dims.x << "x" << ct.dims.y << "x" << ct.dims.z
            << " volume";
        throw Error(msg.str());
    }
    const float seedValue = ct.at(seed.x, seed.y, seed.z);
    if (!(seedValue >= options.lower && seedValue <= options.upper)) {
        std::ostringstream msg;
        msg << "region growing: the seed voxel holds " << seedValue << ", outside "
            << options.lower << ".." << options.upper << " (not bone at this level)";
        throw Error(msg.str());
    }
    std::vector<std::uint8_t> inside(ct.voxelCount());
    for (std::size_t n = 0; n < inside.size(); ++n)
        inside[n] = ct.values[n] >= options.lower && ct.values[n] <= options.upper;
    std::vector<std::int32_t> component(ct.voxelCount(), 0);
    floodComponent(ct.dims, inside, ct.index(seed.x, seed.y, seed.z), 1, component);
    Volume out = ct;
    out.meta.description = "region grown from a seed in " + ct.meta.source;
    for (std::size_t n = 0; n < inside.size(); ++n) out.values[n] = component[n] ? 1.0f : 0.0f;
    return out;
}

glm::ivec3 nearestVoxel(const Volume& volume, const glm::dvec3& world) {
    const glm::dvec3 ijk = glm::floor(volume.worldToIndex(world) + 0.5);
    if (!std::isfinite(ijk.x) || !std::isfinite(ijk.y) || !std::isfinite(ijk.z) ||
        std::abs(ijk.x) > 1e9 || std::abs(ijk.y) > 1e9 || std::abs(ijk.z) > 1e9)
        throw Error("nearest voxel: the point is not finite or absurdly far");
    return glm::ivec3(ijk);
}

std::optional<glm::ivec3> firstVoxelAlong(const Volume& volume, const glm::dvec3& from,
                                          const glm::dvec3& to, double threshold) {
    volume.validate("volume");
    // In voxel index space (an affine map of the world), clipped to the voxels' box.
    const glm::dvec3 a = volume.worldToIndex(from), b = volume.worldToIndex(to);
    for (int k = 0; k < 3; ++k)
        if (!std::isfinite(a[k]) || !std::isfinite(b[k]))
            throw Error("first voxel along a ray: the points are not finite");
    double t0 = 0.0, t1 = 1.0;
    for (int k = 0; k < 3; ++k) {
        const double lo = -0.5, hi = volume.dims[k] - 0.5, d = b[k] - a[k];
        if (d == 0.0) {
            if (a[k] < lo || a[k] > hi) return std::nullopt;
            continue;
        }
        double e0 = (lo - a[k]) / d, e1 = (hi - a[k]) / d;
        if (e0 > e1) std::swap(e0, e1);
        t0 = std::max(t0, e0);
        t1 = std::min(t1, e1);
    }
    if (t0 > t1) return std::nullopt;
    // A quarter of a voxel per step through the box (at most a few times its size in voxels).
    const double voxels = glm::length(b - a) * (t1 - t0);
    const long steps = long(std::ceil(std::min(4.0 * voxels, 8.0 * (volume.dims.x + volume.dims.y +
                                                                    volume.dims.z))));
    for (long n = 0; n <= steps; ++n) {
        const double t = t0 + (t1 - t0) * (steps > 0 ? double(n) / double(steps) : 0.0);
        const glm::dvec3 ijk = glm::floor(a + (b - a) * t + 0.5);
        if (glm::any(glm::lessThan(ijk, glm::dvec3(0.0))) ||
            glm::any(glm::greaterThanEqual(ijk, glm::dvec3(volume.dims))))
            continue;
        const glm::ivec3 v(ijk);
        if (volume.at(v.x, v.y, v.z) >= threshold) return v;
    }
    return std::nullopt;
}

}  // namespace fm

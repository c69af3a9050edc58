#include "bones/RegionGrow.h"

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

}  // namespace fm

#pragma once
// Seeded region growing: the bone the user clicks on. From a seed voxel, every voxel
// 6-connected to it whose value lies in [lower, upper] (HU), as a label map with label 1.
#include <optional>

#include <glm/glm.hpp>

#include "volume/Volume.h"

namespace fm {

struct RegionGrowOptions {
    double lower = 300.0;     // HU
    double upper = 1e30;      // HU (no upper limit by default)
};

// Throws fm::Error if the seed lies outside the volume or its own value is outside the range
// (a click on soft tissue: nothing to grow).
Volume regionGrow(const Volume& ct, const glm::ivec3& seed, const RegionGrowOptions& options = {});

// The voxel whose centre is nearest to a world point (mm), for a click in the 3D view.
glm::ivec3 nearestVoxel(const Volume& volume, const glm::dvec3& world);

// The first voxel at or above `threshold` met along the segment from `from` to `to` (world mm),
// clipped to the volume's box and stepped by a quarter of a voxel: where a ray through a
// clicked X-ray pixel enters bone (the seed of regionGrow). nullopt when it meets none.
std::optional<glm::ivec3> firstVoxelAlong(const Volume& volume, const glm::dvec3& from,
                                          const glm::dvec3& to, double threshold);

}  // namespace fm

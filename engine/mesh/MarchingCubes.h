#pragma once
// Isosurfaces of a volume: our own marching cubes, watertight and manifold by construction.
#include <optional>

#include <glm/glm.hpp>

#include "mesh/Mesh.h"
#include "volume/Volume.h"

namespace fm {

struct MarchingCubesOptions {
    double isoValue = 300.0;                // HU for CTs: a bone level by default
    std::optional<glm::ivec3> roiMin;       // optional region of interest, voxel indices
    std::optional<glm::ivec3> roiMax;       //   (inclusive)
    int keepLargestComponents = 0;          // 0 = all; N = the N largest by triangle count
    int threads = 0;                        // 0 = all cores; output identical per thread count
};

// The surface where the volume crosses isoValue, outside = below isoValue. The border is
// treated as below the isovalue so surfaces cut by the scan close.
Mesh marchingCubes(const Volume& volume, const MarchingCubesOptions& options);

}  // namespace fm

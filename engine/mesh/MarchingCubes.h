#pragma once
// Isosurfaces of a volume: our own marching cubes, watertight and manifold by construction.
// How it stays manifold and how it runs fast: docs/marching-cubes.md.
#include <cstddef>
#include <optional>

#include <glm/glm.hpp>

#include "mesh/Mesh.h"
#include "volume/Volume.h"

namespace fm {

struct MarchingCubesOptions {
    double isoValue = 300.0;           // HU for CTs: a bone level by default
    std::optional<glm::ivec3> roiMin;  // optional region of interest, voxel indices
    std::optional<glm::ivec3> roiMax;  //   (inclusive)
    int keepLargestComponents = 0;     // 0 = all; N = the N largest by triangle count
    int threads = 0;                   // 0 = all cores; output identical per thread count

    // Added by the mesh helper (backward compatible):
    // Value assumed beyond the volume (or ROI) border so cut bones close. Must be below
    // isoValue. Default: the smallest value in the ROI, or isoValue - 1 if none is below.
    std::optional<double> padValue;
    // Label connected components (Mesh::component, 0 = largest). Implied by the options below.
    bool labelComponents = false;
    // Keep only the component of this rank (0 = largest), e.g. "femur only".
    std::optional<int> onlyComponentRank;
    // Keep only the component with a vertex nearest to this world point (mm).
    std::optional<glm::dvec3> onlyComponentNear;
};

// The surface where the volume crosses isoValue, outside = below isoValue. The border is
// treated as below the isovalue so surfaces cut by the scan close. A value equal to isoValue
// counts as inside. Throws fm::Error for an unusable volume or option.
// `componentCount`, when given, receives the number of connected components of the returned
// mesh. Without labelComponents (or an option that implies it) they are counted from the
// union-find the generate pass builds, and no triangle is labelled: what `fluoromatch mesh`
// reports, for a fraction of the labelling's time.
Mesh marchingCubes(const Volume& volume, const MarchingCubesOptions& options,
                   std::size_t* componentCount = nullptr);

}  // namespace fm

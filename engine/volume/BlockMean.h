#pragma once
// A coarser copy of a volume: each voxel the mean of a factor^3 block of the original (blocks
// cut by the far faces average the voxels they hold), placed at the centre of its block. For
// things shown rather than measured, e.g. the display surface of a 1.4 M-triangle MRI head
// (app/scene/DisplaySurface.h).
#include "volume/Volume.h"

namespace fm {

// factor >= 1 (1: a copy). Spacing times factor; direction and metadata kept; the voxel of a
// full block is at the mean of its voxel centres (a block cut by a far face stays on the
// regular grid, up to half a coarse voxel from its voxels' mean). Deterministic for any thread
// count. Throws fm::Error for a factor below 1 or an empty volume.
Volume blockMean(const Volume& volume, int factor, int threads = 0);

}  // namespace fm

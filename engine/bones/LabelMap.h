#pragma once
// A label map: one integer label per voxel of a CT's grid (0 = background), e.g. a
// TotalSegmentator segmentation or the connected components of a thresholded CT. Stored as a
// Volume whose values are whole numbers 0..kMaxLabel (exact in float), on the CT's grid, so
// label voxel (i, j, k) is CT voxel (i, j, k).
#include <cstddef>
#include <map>
#include <string>

#include "volume/Volume.h"

namespace fm {

inline constexpr int kMaxLabel = 65535;

// True when a and b have the same dims and their voxel centres coincide to `toleranceMm`
// (origin, spacing and direction compared through the grid's far corner).
bool sameGrid(const Volume& a, const Volume& b, double toleranceMm = 1e-3);

// Puts `labels` on `ct`'s grid: kept as is (with the CT's geometry copied, exactly) when the
// grids agree, otherwise resampled by nearest neighbour in the world frame (each CT voxel
// centre takes the label of the label voxel containing it; outside the label map: 0).
// Throws fm::Error naming `what` when a value is not a whole number in 0..kMaxLabel, or when
// the label map covers no CT voxel centre at all (another scan: nothing to resample).
Volume labelsOnGrid(Volume labels, const Volume& ct, const std::string& what);

// Reads a label map from any volume file readVolume knows and puts it on `ct`'s grid.
Volume loadLabelMap(const std::string& path, const Volume& ct);

// Voxels per label (0 included).
std::map<int, std::size_t> labelVoxelCounts(const Volume& labels);

}  // namespace fm

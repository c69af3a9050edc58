#pragma once
// Value statistics of a volume (what `fluoromatch info` prints and windowing uses). NaN and
// infinite voxels are counted apart and left out of every figure: one NaN must not make the
// maximum (or a percentile) meaningless.
#include <cstddef>
#include <vector>

#include "volume/Volume.h"

namespace fm {

struct VolumeStats {
    float min = 0.0f, max = 0.0f;     // of the finite values
    double mean = 0.0;                // of the finite values
    std::vector<double> percentiles;  // of the finite values, at the requested percentiles
    std::size_t nanCount = 0;         // voxels that are NaN
    std::size_t infiniteCount = 0;    // voxels that are +inf or -inf
};

// Exact percentiles (nearest rank on the sorted finite values). Percentile p is in [0, 100].
// fm::Error for an empty volume or one without a single finite value.
VolumeStats computeStats(const Volume& volume, const std::vector<double>& percentiles = {1, 50, 99});

}  // namespace fm

#pragma once
// Value statistics of a volume (what `fluoromatch info` prints and windowing uses).
#include <vector>

#include "volume/Volume.h"

namespace fm {

struct VolumeStats {
    float min = 0.0f, max = 0.0f;
    double mean = 0.0;
    std::vector<double> percentiles;  // values at the requested percentiles, same order
};

// Exact percentiles (nearest rank on the sorted values). Percentile p is in [0, 100].
VolumeStats computeStats(const Volume& volume, const std::vector<double>& percentiles = {1, 50, 99});

}  // namespace fm

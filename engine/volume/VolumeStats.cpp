#include "volume/VolumeStats.h"

#include <algorithm>
#include <cmath>

#include "core/Error.h"

namespace fm {

VolumeStats computeStats(const Volume& volume, const std::vector<double>& percentiles) {
    VolumeStats s;
    if (volume.values.empty()) throw Error("cannot compute statistics of an empty volume");
    const auto [lo, hi] = std::minmax_element(volume.values.begin(), volume.values.end());
    s.min = *lo;
    s.max = *hi;
    double sum = 0.0;
    for (float v : volume.values) sum += v;
    s.mean = sum / static_cast<double>(volume.values.size());
    if (percentiles.empty()) return s;
    std::vector<float> sorted(volume.values);
    std::sort(sorted.begin(), sorted.end());
    for (double p : percentiles) {
        if (!(p >= 0.0 && p <= 100.0)) throw Error("percentile must be in [0, 100]");
        const double rank = p / 100.0 * static_cast<double>(sorted.size() - 1);
        s.percentiles.push_back(sorted[static_cast<std::size_t>(std::llround(rank))]);
    }
    return s;
}

}  // namespace fm

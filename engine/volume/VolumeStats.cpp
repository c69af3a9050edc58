#include "volume/VolumeStats.h"

#include <algorithm>
#include <cmath>

#include "core/Error.h"

namespace fm {

VolumeStats computeStats(const Volume& volume, const std::vector<double>& percentiles) {
    VolumeStats s;
    if (volume.values.empty()) throw Error("cannot compute statistics of an empty volume");
    for (double p : percentiles)
        if (!(p >= 0.0 && p <= 100.0)) throw Error("percentile must be in [0, 100]");
    std::vector<float> finite;
    finite.reserve(volume.values.size());
    for (float v : volume.values) {
        if (std::isnan(v))
            ++s.nanCount;
        else if (std::isinf(v))
            ++s.infiniteCount;
        else
            finite.push_back(v);
    }
    if (finite.empty())
        throw Error("cannot compute statistics: none of the " +
                    std::to_string(volume.values.size()) + " voxels is a finite number");
    const auto [lo, hi] = std::minmax_element(finite.begin(), finite.end());
    s.min = *lo;
    s.max = *hi;
    double sum = 0.0;
    for (float v : finite) sum += v;
    s.mean = sum / static_cast<double>(finite.size());
    if (percentiles.empty()) return s;
    std::sort(finite.begin(), finite.end());
    for (double p : percentiles) {
        const double rank = p / 100.0 * static_cast<double>(finite.size() - 1);
        s.percentiles.push_back(finite[static_cast<std::size_t>(std::llround(rank))]);
    }
    return s;
}

}  // namespace fm

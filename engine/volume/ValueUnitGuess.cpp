#include "volume/ValueUnitGuess.h"

#include <sstream>

#include "volume/VolumeStats.h"

namespace fm {

UnitGuess guessHounsfield(const Volume& volume) {
    if (volume.meta.units == ValueUnit::HounsfieldUnits) return {true, "the file says HU"};
    if (volume.meta.units != ValueUnit::Unknown)
        return {false, std::string("the file says ") + toString(volume.meta.units)};
    const double p1 = computeStats(volume, {1}).percentiles[0];
    std::ostringstream reason;
    reason << "no units in the file; 1st percentile " << p1
           << (p1 <= kAirPercentileHU ? " <= " : " > ") << kAirPercentileHU
           << (p1 <= kAirPercentileHU ? " (air)" : " (no air)");
    return {p1 <= kAirPercentileHU, reason.str()};
}

}  // namespace fm

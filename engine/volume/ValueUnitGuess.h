#pragma once
// Are a volume's values Hounsfield units? One rule for the app and the CLI (drr, register):
// HU when the file says so; not HU when it names other units; when it says nothing (NIfTI
// without scl_slope, VTK, raw stacks), HU when its 1st percentile is air (at most -900): no
// other common CT scale goes that far below zero. A bone crop with background 0 (Autoscoper's
// volumes) is therefore not HU, and is integrated as stored.
#include <string>

#include "volume/Volume.h"

namespace fm {

inline constexpr double kAirPercentileHU = -900.0;

struct UnitGuess {
    bool hounsfield = false;
    std::string reason;  // "the file says HU", "no units in the file; 1st percentile 0 > -900"
};

UnitGuess guessHounsfield(const Volume& volume);

}  // namespace fm

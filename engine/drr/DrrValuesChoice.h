#pragma once
// Which values a DRR integrates, decided as the app and every command decide it (`--values
// auto|mu|raw`, Python's `values=`): the unit detection of volume/ValueUnitGuess, said in words,
// and overridable with a warning when the override contradicts it.
#include <string>

#include "drr/Drr.h"
#include "volume/Volume.h"

namespace fm {

struct DrrValuesChoice {
    DrrValues values = DrrValues::Mu;
    std::string line;     // what was decided and why
    std::string warning;  // non-empty when an explicit choice contradicts the detection
};

// `option`: "auto" (HU -> mu, anything else -> raw), "mu" or "raw". Throws fm::Error otherwise.
DrrValuesChoice chooseDrrValues(const Volume& volume, const std::string& option);

}  // namespace fm

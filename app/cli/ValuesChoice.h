#pragma once
// --values auto|mu|raw for the commands that render DRRs (drr, register, evaluate): the same
// unit detection as the app (engine/volume/ValueUnitGuess), said out loud, and overridable.
#include <string>

#include <CLI/CLI.hpp>

#include "drr/Drr.h"
#include "volume/Volume.h"

namespace fm::cli {

struct ValuesChoice {
    DrrValues values = DrrValues::Mu;
    std::string line;     // for the console: what was decided and why
    std::string warning;  // non-empty when an explicit choice contradicts the detection
};

// `option`: "auto" (HU -> mu, anything else -> raw), "mu" or "raw". Throws fm::Error otherwise.
ValuesChoice chooseValues(const Volume& volume, const std::string& option);

// Prints the choice (stdout) and its warning (stderr); returns the values to prepare with.
DrrValues reportValues(const Volume& volume, const std::string& option);

// Adds --values with the help text and the check.
void addValuesOption(CLI::App* cmd, std::string& values);

}  // namespace fm::cli

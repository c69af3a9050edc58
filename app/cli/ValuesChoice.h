#pragma once
// --values auto|mu|raw for the commands that render DRRs (drr, register, evaluate): the choice
// of drr/DrrValuesChoice (the app's and Python's too), said out loud.
#include <string>

#include <CLI/CLI.hpp>

#include "drr/Drr.h"
#include "volume/Volume.h"

namespace fm::cli {

// Prints the choice (stdout) and its warning (stderr); returns the values to prepare with.
DrrValues reportValues(const Volume& volume, const std::string& option);

// Adds --values with the help text and the check.
void addValuesOption(CLI::App* cmd, std::string& values);

}  // namespace fm::cli

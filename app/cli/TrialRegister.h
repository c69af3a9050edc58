#pragma once
// `fluoromatch register --trial T --bone NAME --frame K`: one frame of a trial registered in all
// its cameras at once (or in a subset, --cameras 1, to compare single-view answers).
#include <string>

#include <CLI/CLI.hpp>

#include "cli/RadiographOptions.h"
#include "search/ConfirmedSearch.h"

namespace fm::cli {

struct TrialRegisterArgs {
    std::string trial;
    std::string bone;
    int frame = -1;
    std::string cameras;  // "1" or "1,2"; empty = all
    std::string start;    // .tra holding the start pose at --frame (else the trial's keyframes)
    std::string out;      // .tra with the result at --frame
    std::string findSpace;  // --find-space: where a bone with no start is looked for
    std::uint64_t seed = 1;
    int threads = 0;
    ConfirmationSettings confirmation;  // register's --runs, --max-runs
    RadiographOptions prep;  // over the trial's preparation of every camera (register's flags)
};

void addTrialRegisterOptions(CLI::App* cmd, TrialRegisterArgs& args);
void runTrialRegister(const TrialRegisterArgs& args);

}  // namespace fm::cli

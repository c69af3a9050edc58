#pragma once
// `fluoromatch register --reference IMG --camera CALIB --model MODEL ...`: the pose of implant
// or bone models in a real radiograph (engine/xray). Kept apart from the 2011 register flow.
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "search/ConfirmedSearch.h"

#include "cli/RadiographOptions.h"
#include "cli/SearchCli.h"

namespace fm::cli {

struct XrayRegisterArgs {
    std::string camera;
    std::vector<std::string> models;
    std::vector<std::string> starts;  // one per model, or one .tra for all
    std::vector<std::string> outs;    // one per model, or one .tra for all
    std::vector<std::string> masks;   // one per model (silhouette IoU reported)
    int frame = 0;  // --frame (the trial mode's option, shared): set by the command
    int page = -1;
    double mu = 0.0;  // 0 = the default attenuation of the model kind
    std::string traForm;  // --tra-form: "" (from the counts), matrix or xyzypr
    int runs = 2;         // --runs: searches from independent starts per model (1 = unconfirmed)
    int maxRuns = 4;      // --max-runs: the re-search's budget while no two agree
    std::string findSpace;  // --find-space: where models with no start are looked for
    RadiographOptions prep;
};

// --runs and --max-runs as a confirmation (search/ConfirmedSearch.h); fm::Error when --max-runs
// is below --runs. register's every mode that searches uses it.
ConfirmationSettings confirmationFrom(const XrayRegisterArgs& args);

// --camera, --model, --out, --mask, --mu, --page and the preparation flags (--start,
// --reference and --frame are the register command's own).
void addXrayRegisterOptions(CLI::App* cmd, XrayRegisterArgs& args);

// Throws fm::Error naming the file and the field for bad input.
// The similarity is edge distance unless --similarity was given (`similarityGiven`). Models
// with no start (no --start at all, or `find` in its place) are found (engine/find).
void runXrayRegister(const std::string& reference, const XrayRegisterArgs& args,
                     const std::vector<std::string>& starts, const SearchArgs& search,
                     bool similarityGiven);

}  // namespace fm::cli

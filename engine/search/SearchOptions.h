#pragma once
// What a user may say about a search (the CLI's --method, --similarity, --seed, --budget,
// --polish-budget, --levels, --radius, --threads, --polish; the Python module's keywords of the
// same names), applied to a mode's default settings. One place for the rules, so that the CLI and
// Python make the same search of the same words.
#include <cstdint>
#include <string>
#include <vector>

#include "search/Registration.h"

namespace fm {

struct SearchOptions {
    std::string method = "cmaes";
    std::string similarity = "gncc";
    std::string polish = "nm";
    std::uint64_t seed = 1;
    int budget = 0;             // global search evaluations (0: the mode's default)
    int polishBudget = -1;      // per polish level (-1: the mode's default)
    std::vector<int> levels;    // coarse to fine (empty: the mode's default)
    std::vector<double> radius;  // one number or six (empty: the mode's default)
    int threads = 0;
    // How messages name the options: "--" (the CLI: "--levels: ...") or "" (Python: "levels: ...").
    std::string prefix = "--";
};

// `base` with what the options set: method, similarity, polish, seed and threads always,
// budgets, levels and radius when given. Throws fm::Error naming the option on a bad value.
RegistrationSettings applySearchOptions(const SearchOptions& options, RegistrationSettings base);

}  // namespace fm

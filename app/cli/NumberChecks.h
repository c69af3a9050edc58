#pragma once
// Validators for numeric options whose values CLI11 would otherwise take silently: a negative
// --seed wraps to a huge unsigned number, a NaN passes every comparison. One wording for all.
#include <cmath>
#include <cstdint>
#include <string>

#include <CLI/CLI.hpp>

namespace fm::cli {

// A whole number 0..2^64-1 written in decimal digits ("-1", "1e3", "0x10" are refused).
inline const CLI::Validator kSeedNumber(
    [](std::string& text) -> std::string {
        if (text.empty() || text.size() > 20 ||
            text.find_first_not_of("0123456789") != std::string::npos)
            return "must be a whole number 0.." + std::to_string(UINT64_MAX) + ", got \"" + text +
                   "\"";
        if (text.size() == 20 && text > std::to_string(UINT64_MAX))
            return "must be at most " + std::to_string(UINT64_MAX);
        return {};
    },
    "UINT64");

// A finite number (nan and inf are refused).
inline const CLI::Validator kFiniteNumber(
    [](std::string& text) -> std::string {
        double value = 0.0;
        if (!CLI::detail::lexical_cast(text, value) || !std::isfinite(value))
            return "must be a finite number, got \"" + text + "\"";
        return {};
    },
    "FINITE");

// Evaluation budgets: enough for any real search, far below what would run for days.
inline constexpr int kMaxEvaluations = 1000000;

}  // namespace fm::cli

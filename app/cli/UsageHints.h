#pragma once
// What to tell a user whose command line did not parse: for a misspelt subcommand or option,
// "unknown command \"drrr\"; did you mean \"drr\"?" (core/Suggest), one line per unknown word.
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace fm::cli {

// `args`: the whole command line (args[0] the program). Empty when nothing looks misspelt.
std::vector<std::string> usageHints(CLI::App& app, const std::vector<std::string>& args);

// The exit codes of fluoromatch (README "Exit codes").
inline constexpr int kExitOk = 0;
inline constexpr int kExitError = 1;     // bad input or a failed step (fm::Error)
inline constexpr int kExitUsage = 2;     // the command line did not parse
inline constexpr int kExitInternal = 3;  // a bug (any other exception)

}  // namespace fm::cli

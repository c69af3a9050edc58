#pragma once
// One subcommand, several modes (register: a 2011 pose, an MRI slice, one bone, models in a
// radiograph, a trial's frame): each mode names the options it takes, and any other option the
// user gave is refused before any work, naming the mode and what it does take. An option that
// does not apply is never silently ignored (README "Conventions").
#include <functional>
#include <initializer_list>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace fm::cli {

struct CommandMode {
    std::string name;                // how it is called, e.g. "register --trial"
    std::string what;                // e.g. "one bone in one frame of a trial"
    std::vector<std::string> takes;  // long option names without dashes
};

// The long names of the options `add` adds to a command (e.g. addSearchOptions on scratch
// arguments), so a mode's list follows the options as they are, plus `more`, less `less`.
std::vector<std::string> optionNames(const std::function<void(CLI::App*)>& add,
                                     std::initializer_list<const char*> more = {},
                                     std::initializer_list<const char*> less = {});

// Throws CLI::ValidationError (exit 2, "the command line did not parse") naming every given
// option outside `mode.takes`, and which of the `other` modes take it.
void refuseOptionsOutside(const CLI::App& cmd, const CommandMode& mode,
                          const std::vector<CommandMode>& other = {});

}  // namespace fm::cli

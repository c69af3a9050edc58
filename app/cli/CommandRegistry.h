#pragma once
// Each subcommand lives in its own file under app/cli/ and registers itself with a static
// FM_REGISTER_COMMAND(...) so adding a command touches no shared file. The app sources are
// compiled straight into the executable, so the registrations are never dropped by the linker.
#include <functional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace fm::cli {

struct Command {
    std::string name;
    int order;  // position in --help
    // Adds the subcommand to `app` and returns it; the callback that runs it is set by the
    // command itself and reports failure by throwing (fm::Error for user errors).
    std::function<CLI::App*(CLI::App& app)> install;
};

std::vector<Command>& commandRegistry();

struct CommandRegistration {
    CommandRegistration(std::string name, int order, std::function<CLI::App*(CLI::App&)> install) {
        commandRegistry().push_back({std::move(name), order, std::move(install)});
    }
};

}  // namespace fm::cli

#define FM_CLI_CONCAT2(a, b) a##b
#define FM_CLI_CONCAT(a, b) FM_CLI_CONCAT2(a, b)
#define FM_REGISTER_COMMAND(name, order, install) \
    static ::fm::cli::CommandRegistration FM_CLI_CONCAT(fmCommand_, __COUNTER__)(name, order, install)

// fluoromatch: one executable, subcommands registered from app/cli/.
// With no arguments it runs the "app" subcommand (the matching window) when it is built in.
#include <algorithm>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/CommandRegistry.h"
#include "cli/UsageHints.h"
#include "core/Error.h"
#include "core/HeapReuse.h"
#include "distributed/ProcessTransport.h"

int main(int argc, char** argv) {
    fm::keepFreedMemoryForReuse();  // core/HeapReuse.h
    CLI::App app{"fluoromatch: match X-ray images to CT with digitally reconstructed radiographs"};
    app.set_version_flag("--version", "fluoromatch 0.1.0");
    app.require_subcommand(1, 1);

    auto& commands = fm::cli::commandRegistry();
    std::sort(commands.begin(), commands.end(),
              [](const auto& a, const auto& b) { return a.order < b.order; });
    bool hasApp = false;
    for (auto& command : commands) {
        command.install(app);
        hasApp = hasApp || command.name == "app";
    }

    std::vector<std::string> args(argv, argv + argc);
    if (argc == 1 && hasApp) args.push_back("app");
    std::vector<char*> argvOut;
    for (auto& a : args) argvOut.push_back(a.data());

    // Exit codes (README): 0 done, 1 bad input or a failed step, 2 the command line did not
    // parse, 3 internal error.
    try {
        app.parse(static_cast<int>(argvOut.size()), argvOut.data());
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        const std::vector<std::string> hints = fm::cli::usageHints(app, args);
        if (hints.empty()) {
            app.exit(e);  // CLI11's message and "Run with --help"
        } else {
            for (const std::string& h : hints) std::cerr << "fluoromatch: " << h << "\n";
            std::cerr << "Run with --help for more information.\n";
        }
        return fm::cli::kExitUsage;
    } catch (const fm::distributed::JobsFailed& e) {
        std::cerr << "fluoromatch: error: " << e.what() << "\n";
        return fm::cli::kExitError;  // every rank has finished: end normally
    } catch (const fm::Error& e) {
        std::cerr << "fluoromatch: error: " << e.what() << "\n";
        fm::distributed::endRunAfterError(fm::cli::kExitError);
        return fm::cli::kExitError;
    } catch (const std::exception& e) {
        std::cerr << "fluoromatch: internal error: " << e.what() << "\n";
        fm::distributed::endRunAfterError(fm::cli::kExitInternal);
        return fm::cli::kExitInternal;
    }
    return fm::cli::kExitOk;
}

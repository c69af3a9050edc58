#include "cli/UsageHints.h"

#include "core/Suggest.h"

namespace fm::cli {

std::vector<std::string> usageHints(CLI::App& app, const std::vector<std::string>& args) {
    std::vector<std::string> hints;
    if (args.size() < 2) return hints;
    std::vector<std::string> commands;
    CLI::App* chosen = nullptr;
    for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) {
        commands.push_back(sub->get_name());
        if (sub->get_name() == args[1]) chosen = sub;
    }
    if (!chosen) {
        if (args[1].rfind("-", 0) == 0) return hints;  // --help, --version: CLI11's own
        std::string line = "unknown command \"" + args[1] + "\"";
        if (const auto near = closestMatch(args[1], commands)) line += "; did you mean \"" + *near + "\"?";
        else line += " (commands: " + [&] {
            std::string all;
            for (const auto& c : commands) all += (all.empty() ? "" : ", ") + c;
            return all;
        }() + ")";
        hints.push_back(line);
        return hints;
    }
    std::vector<std::string> options;
    for (const CLI::Option* o : chosen->get_options()) {
        for (const std::string& n : o->get_lnames()) options.push_back("--" + n);
        for (const std::string& n : o->get_snames()) options.push_back("-" + n);
    }
    for (std::size_t i = 2; i < args.size(); ++i) {
        if (args[i].size() < 2 || args[i][0] != '-' || args[i] == "--") continue;
        const std::string name = args[i].substr(0, args[i].find('='));
        if (std::find(options.begin(), options.end(), name) != options.end()) continue;
        if (name.size() > 1 && name[1] != '-' && std::isdigit(static_cast<unsigned char>(name[1])))
            continue;  // a negative number, the value of an option
        std::string line = "unknown option " + name + " for " + chosen->get_name();
        if (const auto near = closestMatch(name, options)) line += "; did you mean " + *near + "?";
        hints.push_back(line);
    }
    return hints;
}

}  // namespace fm::cli

#include "cli/ModeOptions.h"

#include <algorithm>

namespace fm::cli {

std::vector<std::string> optionNames(const std::function<void(CLI::App*)>& add,
                                     std::initializer_list<const char*> more,
                                     std::initializer_list<const char*> less) {
    CLI::App scratch;
    add(&scratch);
    std::vector<std::string> names(more.begin(), more.end());
    for (const CLI::Option* o : scratch.get_options()) {
        if (o->get_lnames().empty()) continue;
        const std::string& name = o->get_lnames().front();
        if (name != "help" && std::find(less.begin(), less.end(), name) == less.end())
            names.push_back(name);
    }
    return names;
}

namespace {

bool takes(const CommandMode& mode, const std::string& name) {
    return std::find(mode.takes.begin(), mode.takes.end(), name) != mode.takes.end();
}

}  // namespace

void refuseOptionsOutside(const CLI::App& cmd, const CommandMode& mode,
                          const std::vector<CommandMode>& other) {
    std::vector<std::string> refused;
    for (const CLI::Option* o : cmd.get_options()) {
        if (o->count() == 0 || o->get_lnames().empty()) continue;
        const std::string& name = o->get_lnames().front();
        if (name == "help") continue;
        if (!takes(mode, name)) refused.push_back(name);
    }
    if (refused.empty()) return;
    std::string given, elsewhere, taken;
    for (const std::string& r : refused) {
        given += (given.empty() ? "--" : ", --") + r;
        std::string modes;
        for (const CommandMode& m : other)
            if (m.name != mode.name && takes(m, r)) modes += (modes.empty() ? "" : ", ") + m.name;
        if (!modes.empty()) elsewhere += "; --" + r + " is for " + modes;
    }
    for (const std::string& t : mode.takes) taken += (taken.empty() ? "--" : ", --") + t;
    throw CLI::ValidationError(given + (refused.size() == 1 ? " does" : " do") + " not apply to " +
                               mode.name + " (" + mode.what + ")" + elsewhere + "; it takes " +
                               taken);
}

}  // namespace fm::cli

#include "cli/ValuesChoice.h"

#include <cstdio>

#include "core/Error.h"
#include "drr/DrrValuesChoice.h"

namespace fm::cli {

DrrValues reportValues(const Volume& volume, const std::string& option) {
    const DrrValuesChoice c = chooseDrrValues(volume, option);
    std::printf("values    %s\n", c.line.c_str());
    if (!c.warning.empty()) std::fprintf(stderr, "fluoromatch: warning: %s\n", c.warning.c_str());
    return c.values;
}

void addValuesOption(CLI::App* cmd, std::string& values) {
    cmd->add_option("--values", values,
                    "auto: HU volumes converted to attenuation (mu), others integrated as stored "
                    "(raw), as the app decides; mu or raw to override")
        ->check(CLI::IsMember({"auto", "mu", "raw"}))
        ->capture_default_str();
}

}  // namespace fm::cli

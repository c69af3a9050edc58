#include "cli/ValuesChoice.h"

#include <cstdio>

#include "core/Error.h"
#include "volume/ValueUnitGuess.h"

namespace fm::cli {

ValuesChoice chooseValues(const Volume& volume, const std::string& option) {
    if (option != "auto" && option != "mu" && option != "raw")
        throw Error("--values must be auto, mu or raw, got \"" + option + "\"");
    const UnitGuess guess = guessHounsfield(volume);
    ValuesChoice c;
    if (option == "auto") {
        c.values = guess.hounsfield ? DrrValues::Mu : DrrValues::Raw;
        c.line = guess.hounsfield
                     ? "auto: HU (" + guess.reason + ") -> mu (HU converted to 1/mm)"
                     : "auto: not HU (" + guess.reason +
                           ") -> raw (value * mm, as stored); --values mu to convert them as HU";
        return c;
    }
    c.values = option == "mu" ? DrrValues::Mu : DrrValues::Raw;
    c.line = option == "mu" ? "mu (HU -> 1/mm), as asked" : "raw (value * mm), as asked";
    if (option == "mu" && !guess.hounsfield)
        c.warning = "--values mu converts the values as HU, but they do not look like HU (" +
                    guess.reason + "): the background becomes attenuation";
    if (option == "raw" && guess.hounsfield)
        c.warning = "--values raw integrates HU as stored (" + guess.reason +
                    "): air counts as -1000";
    return c;
}

DrrValues reportValues(const Volume& volume, const std::string& option) {
    const ValuesChoice c = chooseValues(volume, option);
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

#include "drr/DrrValuesChoice.h"

#include "core/Error.h"
#include "volume/ValueUnitGuess.h"

namespace fm {

DrrValuesChoice chooseDrrValues(const Volume& volume, const std::string& option) {
    if (option != "auto" && option != "mu" && option != "raw")
        throw Error("values must be auto, mu or raw, got \"" + option + "\"");
    const UnitGuess guess = guessHounsfield(volume);
    DrrValuesChoice c;
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

}  // namespace fm

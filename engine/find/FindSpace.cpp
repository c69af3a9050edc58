#include "find/FindSpace.h"

#include <cstdio>

#include "core/Error.h"
#include "io/HeaderText.h"

namespace fm {

void forEachKeyValue(const std::string& text, const std::string& option, const std::string& keysHelp,
                     const std::function<void(const std::string& key, const std::string& value)>& each) {
    std::size_t start = 0;
    while (start < text.size()) {
        const std::size_t comma = text.find(',', start);
        const std::string part = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        const std::size_t eq = part.find('=');
        if (eq == std::string::npos) throw Error(option + " \"" + text + "\": expected key=value" + keysHelp);
        each(part.substr(0, eq), part.substr(eq + 1));
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
}

FindSpace parseFindSpace(const std::string& text, const std::string& option, const FindSpace& base) {
    FindSpace space = base;
    const std::string keys = " (tilt=DEG, roll=DEG, depth=NEAR:FAR as fractions of the source-to-detector distance)";
    forEachKeyValue(text, option, keys, [&](const std::string& key, const std::string& value) {
        if (key == "tilt") {
            space.tiltDeg = io::parseFinite(value, option + " tilt");
            if (!(space.tiltDeg >= 0.0 && space.tiltDeg <= 90.0)) throw Error(option + ": tilt must be 0 to 90 deg");
        } else if (key == "roll") {
            space.rollDeg = io::parseFinite(value, option + " roll");
            if (!(space.rollDeg >= 0.0 && space.rollDeg <= 180.0)) throw Error(option + ": roll must be 0 to 180 deg");
        } else if (key == "depth") {
            const std::size_t colon = value.find(':');
            if (colon == std::string::npos)
                throw Error(option + ": depth must be NEAR:FAR, e.g. depth=0.25:0.92 or depth=600mm:1400mm");
            std::string nearText = value.substr(0, colon), farText = value.substr(colon + 1);
            const auto inMm = [](std::string& t) {
                const bool mm = t.size() > 2 && t.compare(t.size() - 2, 2, "mm") == 0;
                if (mm) t.resize(t.size() - 2);
                return mm;
            };
            const bool nearMm = inMm(nearText), farMm = inMm(farText);
            if (nearMm != farMm) throw Error(option + ": depth NEAR and FAR must both be fractions or both in mm");
            const double near = io::parseFinite(nearText, option + " depth (near)");
            const double far = io::parseFinite(farText, option + " depth (far)");
            if (nearMm) {
                if (!(near > 0.0 && near < far && far <= 1e5))
                    throw Error(option + ": depth NEARmm:FARmm must satisfy 0 < NEAR < FAR (mm from the source)");
                space.nearMm = near, space.farMm = far;
            } else {
                if (!(near > 0.0 && near < far && far < 1.0))
                    throw Error(option + ": depth NEAR:FAR must satisfy 0 < NEAR < FAR < 1 (fractions of the "
                                         "source-to-detector distance)");
                space.nearFraction = near, space.farFraction = far;
                space.nearMm = space.farMm = 0.0;
            }
        } else {
            throw Error(option + ": unknown \"" + key + "\"" + keys);
        }
    });
    return space;
}

std::string describeFindSpace(const FindSpace& space) {
    char buf[160];
    if (space.nearMm > 0.0)
        std::snprintf(buf, sizeof buf, "tilt +-%.0f deg, roll +-%.0f deg, depth %.0f-%.0f mm from the source",
                      space.tiltDeg, space.rollDeg, space.nearMm, space.farMm);
    else
        std::snprintf(buf, sizeof buf, "tilt +-%.0f deg, roll +-%.0f deg, depth %.2f-%.2f of the source-to-detector distance",
                      space.tiltDeg, space.rollDeg, space.nearFraction, space.farFraction);
    return buf;
}

}  // namespace fm

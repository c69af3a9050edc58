#include "find/ViewSpace.h"

#include <cstdio>

#include "core/Error.h"
#include "find/FindSpace.h"
#include "io/HeaderText.h"

namespace fm {

ViewSpace parseViewSpace(const std::string& text, const std::string& option) {
    ViewSpace space;
    const std::string keys = " (elevation=DEG, rotation=DEG, offset=MM: the 2011 scene's search space)";
    forEachKeyValue(text, option, keys, [&](const std::string& key, const std::string& value) {
        if (key == "elevation" || key == "rotation") {
            const double v = io::parseFinite(value, option + " " + key);
            if (!(v >= 0.0 && v <= 90.0)) throw Error(option + ": " + key + " must be 0 to 90 deg");
            (key == "elevation" ? space.elevationDeg : space.rotationDeg) = v;
        } else if (key == "offset") {
            space.offsetMm = io::parseFinite(value, option + " offset");
            if (!(space.offsetMm > 0.0 && space.offsetMm <= 500.0))
                throw Error(option + ": offset must be above 0 and at most 500 mm");
        } else {
            throw Error(option + ": unknown \"" + key + "\"" + keys);
        }
    });
    return space;
}

std::string describeViewSpace(const ViewSpace& space) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "azimuth any, elevation +-%.0f deg, rotation +-%.0f deg, offsets +-%.0f mm",
                  space.elevationDeg, space.rotationDeg, space.offsetMm);
    return buf;
}

}  // namespace fm

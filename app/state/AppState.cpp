#include "state/AppState.h"

#include <sstream>

#include "core/Error.h"

namespace fm::app {

std::array<ParameterSpec, kParameterCount> parameterSpecs(double translationRangeMm) {
    const double t = translationRangeMm;
    return {{{"x offset", "mm", -t, t},
             {"y offset", "mm", -t, t},
             {"z offset", "mm", -t, t},
             {"azimuth", "deg", -180.0, 180.0},
             {"elevation", "deg", -90.0, 90.0},
             {"rotation", "deg", -90.0, 90.0}}};
}

std::array<ParameterSpec, kParameterCount> boneMotionSpecs() {
    return {{{"x shift", "mm", -50.0, 50.0},
             {"y shift", "mm", -50.0, 50.0},
             {"z shift", "mm", -50.0, 50.0},
             {"turn x", "deg", -120.0, 120.0},
             {"turn y", "deg", -90.0, 90.0},
             {"turn z", "deg", -90.0, 90.0}}};
}

void checkPoseWithinSliders(const Pose& pose, double translationRangeMm, const std::string& what) {
    const auto specs = parameterSpecs(translationRangeMm);
    const auto values = pose.toArray();
    for (int p = 0; p < kParameterCount; ++p) {
        if (values[p] >= specs[p].min && values[p] <= specs[p].max) continue;
        std::ostringstream msg;
        msg << what << ": " << specs[p].name << " " << values[p] << " " << specs[p].unit
            << " is outside the slider range " << specs[p].min << " .. " << specs[p].max << " "
            << specs[p].unit << " for this volume";
        throw Error(msg.str());
    }
}

}  // namespace fm::app

#include "state/AppState.h"

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

}  // namespace fm::app

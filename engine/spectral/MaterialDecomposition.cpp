#include "spectral/MaterialDecomposition.h"

#include <algorithm>
#include <cmath>

#include "core/Error.h"

namespace fm {

double densityFromHU(double hu) { return std::max(std::min(0.001029 * hu + 1.030, 0.0005886 * hu + 1.030), 0.0); }

Volume signedMaterialDensity(const Volume& ct, const Volume* mask, double threshold) {
    if (mask && mask->dims != ct.dims) throw Error("the bone mask's grid differs from the CT's");
    Volume out = Volume::allocate(ct.dims, 0.0f);
    out.spacing = ct.spacing;
    out.origin = ct.origin;
    out.direction = ct.direction;
    out.meta.source = ct.meta.source;
    out.meta.description = "density, mg/cm^3: soft tissue > 0, bone < 0";
    for (std::size_t i = 0; i < ct.values.size(); ++i) {
        const double hu = ct.values[i];
        if (std::isnan(hu) || hu < kAirBelowHU) continue;
        const float mgPerCm3 = static_cast<float>(std::round(1000.0 * densityFromHU(hu)));
        const bool bone = mask ? mask->values[i] > 0.0f : hu > threshold;
        out.values[i] = bone ? -mgPerCm3 : mgPerCm3;
    }
    return out;
}

}  // namespace fm

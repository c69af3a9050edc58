#include "spectral/MaterialDecomposition.h"

#include <algorithm>
#include <cmath>

#include "core/Error.h"

namespace fm {

double densityFromHU(double hu) { return std::max(std::min(0.001029 * hu + 1.030, 0.0005886 * hu + 1.030), 0.0); }

MaterialVolumes decomposeMaterials(const Volume& ct, const Volume* mask, double threshold) {
    if (mask && mask->dims != ct.dims) throw Error("the bone mask's grid differs from the CT's");
    MaterialVolumes m;
    m.softTissue = Volume::allocate(ct.dims, 0.0f);
    m.bone = Volume::allocate(ct.dims, 0.0f);
    for (Volume* v : {&m.softTissue, &m.bone}) {
        v->spacing = ct.spacing;
        v->origin = ct.origin;
        v->direction = ct.direction;
        v->meta.source = ct.meta.source;
        v->meta.description = "density, mg/cm^3";
    }
    for (std::size_t i = 0; i < ct.values.size(); ++i) {
        const double hu = ct.values[i];
        if (std::isnan(hu) || hu < kAirBelowHU) continue;
        const float mgPerCm3 = static_cast<float>(std::round(1000.0 * densityFromHU(hu)));
        const bool bone = mask ? mask->values[i] > 0.0f : hu > threshold;
        (bone ? m.bone : m.softTissue).values[i] = mgPerCm3;
    }
    return m;
}

}  // namespace fm

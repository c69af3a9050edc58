#include "workspace/RawImageHint.h"

namespace fm::app {

double footprintContrast(const Image& image, const Mask& valid, const Mask& footprint, double range) {
    if (footprint.inside.size() != image.pixels.size() || !(range > 0.0)) return 0.0;
    double inside = 0.0, outside = 0.0;
    std::size_t nInside = 0, nOutside = 0;
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
        if (!valid.inside.empty() && !valid.inside[i]) continue;
        if (footprint.inside[i]) {
            inside += image.pixels[i];
            ++nInside;
        } else {
            outside += image.pixels[i];
            ++nOutside;
        }
    }
    if (nInside == 0 || nOutside == 0) return 0.0;
    return (inside / double(nInside) - outside / double(nOutside)) / range;
}

}  // namespace fm::app

#include "workspace/RawImageHint.h"

#include <algorithm>
#include <vector>

namespace fm::app {

double footprintContrast(const Image& image, const Mask& valid, const Mask& footprint) {
    if (footprint.inside.size() != image.pixels.size()) return 0.0;
    double inside = 0.0, outside = 0.0;
    std::size_t nInside = 0, nOutside = 0;
    std::vector<float> values;
    values.reserve(image.pixels.size());
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
        if (!valid.inside.empty() && !valid.inside[i]) continue;
        const float v = image.pixels[i];
        values.push_back(v);
        if (footprint.inside[i]) {
            inside += v;
            ++nInside;
        } else {
            outside += v;
            ++nOutside;
        }
    }
    if (nInside == 0 || nOutside == 0) return 0.0;
    const auto at = [&](double q) {
        const auto k = static_cast<std::ptrdiff_t>(q * double(values.size() - 1));
        std::nth_element(values.begin(), values.begin() + k, values.end());
        return double(values[static_cast<std::size_t>(k)]);
    };
    const double range = at(0.99) - at(0.01);
    if (!(range > 0.0)) return 0.0;
    return (inside / double(nInside) - outside / double(nOutside)) / range;
}

}  // namespace fm::app

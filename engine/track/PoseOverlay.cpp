#include "track/PoseOverlay.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/Error.h"

namespace fm {

Mask outlineOf(const Mask& m) {
    Mask out(m.width, m.height, false);
    for (int r = 0; r < m.height; ++r)
        for (int c = 0; c < m.width; ++c) {
            if (!m.at(c, r)) continue;
            const bool edge = c == 0 || r == 0 || c == m.width - 1 || r == m.height - 1 ||
                              !m.at(c - 1, r) || !m.at(c + 1, r) || !m.at(c, r - 1) || !m.at(c, r + 1);
            if (edge) out.inside[static_cast<std::size_t>(r) * m.width + c] = 1;
        }
    return out;
}

std::pair<float, float> validPercentileRange(const Image& image, const std::optional<Mask>& valid) {
    std::vector<float> values;
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        if ((!valid || valid->inside[i] != 0) && std::isfinite(image.pixels[i])) values.push_back(image.pixels[i]);
    float low = 0.0f, high = 1.0f;
    if (!values.empty()) {
        const auto at = [&](double q) {
            const auto k = static_cast<std::size_t>(q * static_cast<double>(values.size() - 1));
            std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k), values.end());
            return values[k];
        };
        low = at(0.01);
        high = at(0.99);
        if (!(high > low)) high = low + 1.0f;
    }
    return {low, high};
}

std::vector<std::uint8_t> overlayRgb(const Image& image, const std::optional<Mask>& valid,
                                     const std::vector<OverlayOutline>& outlines) {
    const auto sameSize = [&](const Mask& m, const char* what) {
        if (m.width != image.width || m.height != image.height)
            throw Error(std::string("overlay: the ") + what + " is " + std::to_string(m.width) + "x" +
                        std::to_string(m.height) + ", the image " + std::to_string(image.width) + "x" +
                        std::to_string(image.height));
    };
    if (valid) sameSize(*valid, "valid mask");
    for (const OverlayOutline& o : outlines) sameSize(o.silhouette, "silhouette");
    const std::size_t n = image.pixels.size();
    auto isValid = [&](std::size_t i) {
        return (!valid || valid->inside[i] != 0) && std::isfinite(image.pixels[i]);
    };
    const auto [low, high] = validPercentileRange(image, valid);
    std::vector<std::uint8_t> rgb(3 * n, 0);
    for (std::size_t i = 0; i < n; ++i) {
        if (!isValid(i)) continue;
        const float t = std::clamp((image.pixels[i] - low) / (high - low), 0.0f, 1.0f);
        const auto g = static_cast<std::uint8_t>(std::lround(255.0f * t));
        rgb[3 * i] = rgb[3 * i + 1] = rgb[3 * i + 2] = g;
    }
    for (const OverlayOutline& o : outlines) {
        const Mask line = outlineOf(o.silhouette);
        for (std::size_t i = 0; i < n; ++i)
            if (line.inside[i]) std::copy(o.colour.begin(), o.colour.end(), rgb.begin() + static_cast<std::ptrdiff_t>(3 * i));
    }
    return rgb;
}

Rgb overlayColour(std::size_t index) {
    static constexpr Rgb kColours[] = {{255, 40, 40}, {40, 220, 40}, {60, 120, 255},
                                       {255, 220, 0}, {255, 0, 255}, {0, 230, 230}};
    return kColours[index % (sizeof kColours / sizeof *kColours)];
}

}  // namespace fm

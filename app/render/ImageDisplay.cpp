#include "render/ImageDisplay.h"

#include <algorithm>
#include <cmath>

namespace fm::render {
namespace {

// 0..1 through the window; NaN shows black.
float windowed(float value, const WindowLevel& wl) {
    const float width = std::max(wl.window, 1e-12f);
    const float t = (value - (wl.level - 0.5f * width)) / width;
    return std::isfinite(t) ? std::clamp(t, 0.0f, 1.0f) : 0.0f;
}

std::uint8_t toByte(float t) {
    return static_cast<std::uint8_t>(std::lround(t * 255.0f));
}

}  // namespace

WindowLevel fullRange(const Image& image) {
    float lo = 0.0f, hi = 0.0f;
    bool any = false;
    for (float v : image.pixels) {
        if (!std::isfinite(v)) continue;
        lo = any ? std::min(lo, v) : v;
        hi = any ? std::max(hi, v) : v;
        any = true;
    }
    if (!any || hi <= lo) return {1.0f, lo + 0.5f};
    return {hi - lo, 0.5f * (hi + lo)};
}

std::vector<std::uint8_t> windowedRgba(const Image& image, const WindowLevel& wl) {
    std::vector<std::uint8_t> rgba(image.pixels.size() * 4);
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
        const std::uint8_t g = toByte(windowed(image.pixels[i], wl));
        rgba[4 * i] = rgba[4 * i + 1] = rgba[4 * i + 2] = g;
        rgba[4 * i + 3] = 255;
    }
    return rgba;
}

std::vector<std::uint8_t> differenceRgba(const Image& reference, const Image& user,
                                         const WindowLevel& wl) {
    if (reference.width != user.width || reference.height != user.height) return {};
    std::vector<std::uint8_t> rgba(user.pixels.size() * 4);
    // Half the window maps to full colour: small misalignments stay visible.
    const float scale = 2.0f / std::max(wl.window, 1e-12f);
    for (std::size_t i = 0; i < user.pixels.size(); ++i) {
        float d = (user.pixels[i] - reference.pixels[i]) * scale;
        if (!std::isfinite(d)) d = 0.0f;
        d = std::clamp(d, -1.0f, 1.0f);
        rgba[4 * i] = toByte(std::max(d, 0.0f));
        rgba[4 * i + 1] = toByte(0.25f * std::abs(d));
        rgba[4 * i + 2] = toByte(std::max(-d, 0.0f));
        rgba[4 * i + 3] = 255;
    }
    return rgba;
}

std::vector<std::uint8_t> overlayRgba(const Image& reference, const Image& user,
                                      const WindowLevel& wl) {
    if (reference.width != user.width || reference.height != user.height) return {};
    std::vector<std::uint8_t> rgba(user.pixels.size() * 4);
    for (std::size_t i = 0; i < user.pixels.size(); ++i) {
        const std::uint8_t r = toByte(windowed(reference.pixels[i], wl));
        const std::uint8_t u = toByte(windowed(user.pixels[i], wl));
        rgba[4 * i] = r;
        rgba[4 * i + 1] = u;
        rgba[4 * i + 2] = r;
        rgba[4 * i + 3] = 255;
    }
    return rgba;
}

std::vector<std::uint8_t> checkerboardRgba(const Image& reference, const Image& user,
                                           const WindowLevel& wl, int tile) {
    if (reference.width != user.width || reference.height != user.height) return {};
    tile = std::max(tile, 1);
    std::vector<std::uint8_t> rgba(user.pixels.size() * 4);
    for (int row = 0; row < user.height; ++row)
        for (int col = 0; col < user.width; ++col) {
            const bool fromUser = ((col / tile) + (row / tile)) % 2 == 1;
            const float v = fromUser ? user.at(col, row) : reference.at(col, row);
            const std::size_t i = std::size_t(row) * user.width + col;
            const std::uint8_t g = toByte(windowed(v, wl));
            rgba[4 * i] = rgba[4 * i + 1] = rgba[4 * i + 2] = g;
            rgba[4 * i + 3] = 255;
        }
    return rgba;
}

}  // namespace fm::render

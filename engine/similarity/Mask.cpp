#include "similarity/Mask.h"

#include <algorithm>
#include <string>

#include "core/Error.h"

namespace fm {

std::size_t Mask::count() const {
    return static_cast<std::size_t>(std::count(inside.begin(), inside.end(), std::uint8_t{1}));
}

Mask footprintMask(const Image& drr, float threshold, int dilatePixels) {
    Mask m(drr.width, drr.height, false);
    for (std::size_t i = 0; i < drr.pixels.size(); ++i) m.inside[i] = drr.pixels[i] > threshold;
    return dilatePixels > 0 ? dilate(m, dilatePixels) : m;
}

Mask dilate(const Mask& mask, int pixels) {
    if (pixels <= 0) return mask;
    const int w = mask.width, h = mask.height;
    if (w == 0 || h == 0) return mask;
    // A square structuring element is separable: rows first, then columns, each pass a running
    // count of the inside pixels in the window, so the cost does not grow with `pixels` (this
    // runs on every candidate's footprint and on every 1760 x 1760 radiograph's border).
    std::vector<std::uint8_t> rowPass(mask.inside.size());
    for (int r = 0; r < h; ++r) {
        const std::uint8_t* in = mask.inside.data() + static_cast<std::size_t>(r) * w;
        std::uint8_t* out = rowPass.data() + static_cast<std::size_t>(r) * w;
        int count = 0;  // inside pixels in [c - pixels, c + pixels]
        for (int k = 0; k <= std::min(pixels, w - 1); ++k) count += in[k] != 0;
        for (int c = 0; c < w; ++c) {
            out[c] = count > 0 ? 1 : 0;
            if (c + pixels + 1 < w) count += in[c + pixels + 1] != 0;
            if (c - pixels >= 0) count -= in[c - pixels] != 0;
        }
    }
    Mask out(w, h, false);
    std::vector<int> count(static_cast<std::size_t>(w), 0);  // per column, rows [r - p, r + p]
    auto addRow = [&](int r, int sign) {
        const std::uint8_t* row = rowPass.data() + static_cast<std::size_t>(r) * w;
        for (int c = 0; c < w; ++c) count[static_cast<std::size_t>(c)] += sign * row[c];
    };
    for (int k = 0; k <= std::min(pixels, h - 1); ++k) addRow(k, 1);
    for (int r = 0; r < h; ++r) {
        std::uint8_t* row = out.inside.data() + static_cast<std::size_t>(r) * w;
        for (int c = 0; c < w; ++c) row[c] = count[static_cast<std::size_t>(c)] > 0 ? 1 : 0;
        if (r + pixels + 1 < h) addRow(r + pixels + 1, 1);
        if (r - pixels >= 0) addRow(r - pixels, -1);
    }
    return out;
}

Mask intersect(const Mask& a, const Mask& b) {
    if (a.width != b.width || a.height != b.height)
        throw Error("mask sizes differ: " + std::to_string(a.width) + "x" +
                    std::to_string(a.height) + " and " + std::to_string(b.width) + "x" +
                    std::to_string(b.height));
    Mask out(a.width, a.height, false);
    for (std::size_t i = 0; i < a.inside.size(); ++i) out.inside[i] = a.inside[i] && b.inside[i];
    return out;
}

PixelRect boundingRect(const Mask& mask) {
    int c0 = mask.width, r0 = mask.height, c1 = -1, r1 = -1;
    for (int r = 0; r < mask.height; ++r)
        for (int c = 0; c < mask.width; ++c)
            if (mask.at(c, r)) {
                c0 = std::min(c0, c);
                c1 = std::max(c1, c);
                r0 = std::min(r0, r);
                r1 = std::max(r1, r);
            }
    if (c1 < 0) return {};
    return {c0, r0, c1 - c0 + 1, r1 - r0 + 1};
}

Mask cropMask(const Mask& mask, const PixelRect& r) {
    if (r.col0 < 0 || r.row0 < 0 || r.cols < 0 || r.rows < 0 || r.col0 + r.cols > mask.width ||
        r.row0 + r.rows > mask.height)
        throw Error("mask crop leaves the " + std::to_string(mask.width) + "x" +
                    std::to_string(mask.height) + " mask");
    Mask out(r.cols, r.rows, false);
    for (int row = 0; row < r.rows; ++row)  // whole rows: this runs on every candidate
        std::copy_n(mask.inside.begin() + (static_cast<std::ptrdiff_t>(r.row0 + row) * mask.width + r.col0),
                    r.cols, out.inside.begin() + static_cast<std::ptrdiff_t>(row) * r.cols);
    return out;
}

Mask downsampleMaskBy(const Mask& mask, int factor) {
    if (factor < 1) throw Error("mask downsampling factor must be >= 1");
    const int w = mask.width / factor, h = mask.height / factor;
    Mask out(w, h, false);
    for (int row = 0; row < h; ++row)
        for (int col = 0; col < w; ++col) {
            bool all = true;
            for (int r = 0; r < factor && all; ++r)
                for (int c = 0; c < factor && all; ++c)
                    all = mask.at(col * factor + c, row * factor + r);
            out.inside[static_cast<std::size_t>(row) * w + col] = all;
        }
    return out;
}

}  // namespace fm

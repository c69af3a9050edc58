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
    // Rows first, then columns: a square structuring element is separable.
    Mask rowPass(w, h, false);
    for (int r = 0; r < h; ++r) {
        for (int c = 0; c < w; ++c) {
            const int lo = std::max(0, c - pixels), hi = std::min(w - 1, c + pixels);
            bool any = false;
            for (int k = lo; k <= hi && !any; ++k) any = mask.at(k, r);
            rowPass.inside[static_cast<std::size_t>(r) * w + c] = any;
        }
    }
    Mask out(w, h, false);
    for (int r = 0; r < h; ++r) {
        const int lo = std::max(0, r - pixels), hi = std::min(h - 1, r + pixels);
        for (int c = 0; c < w; ++c) {
            bool any = false;
            for (int k = lo; k <= hi && !any; ++k) any = rowPass.at(c, k);
            out.inside[static_cast<std::size_t>(r) * w + c] = any;
        }
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
    for (int row = 0; row < r.rows; ++row)
        for (int col = 0; col < r.cols; ++col)
            out.inside[static_cast<std::size_t>(row) * r.cols + col] =
                mask.at(r.col0 + col, r.row0 + row);
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

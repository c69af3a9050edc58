#include "radiograph/RadiographPreparation.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/Error.h"

namespace fm {

namespace {

Mask complement(const Mask& m) {
    Mask out = m;
    for (auto& v : out.inside) v = v ? 0 : 1;
    return out;
}

// NaN and infinite pixels (a float TIFF's holes) carry no image. They and their 8 neighbours
// (whose Sobel gradients read them) leave the mask, and their values become the mean of the
// finite pixels, so no later sum (a gradient, a pyramid level's average, the log) meets them.
// Returns how many there were.
std::size_t dropNonFinite(Image& image, Mask& valid) {
    Mask bad(image.width, image.height, false);
    std::size_t count = 0;
    double sum = 0.0;
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
        if (std::isfinite(image.pixels[i])) sum += image.pixels[i];
        else bad.inside[i] = 1, ++count;
    }
    if (count == 0) return 0;
    const std::size_t finite = image.pixels.size() - count;
    const float fill = finite ? static_cast<float>(sum / double(finite)) : 0.0f;
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        if (bad.inside[i]) image.pixels[i] = fill;
    const Mask grown = dilate(bad, 1);
    for (std::size_t i = 0; i < valid.inside.size(); ++i)
        if (grown.inside[i]) valid.inside[i] = 0;
    return count;
}

}  // namespace

double radiographFullScale(int bitsPerSample) {
    return bitsPerSample >= 32 ? 1.0 : std::pow(2.0, bitsPerSample) - 1.0;
}

PreparedRadiograph prepareRadiograph(const Image& radiograph, const RadiographPreparation& o) {
    if (radiograph.empty()) throw Error("radiograph preparation: the image is empty");
    if (o.invert && o.logTransform)
        throw Error("--invert with --log: the log transform already makes dense matter bright");
    if (!(std::isfinite(o.fullScale) && o.fullScale > 0.0))
        throw Error("radiograph preparation: full scale must be positive");
    const double i0 = o.i0 > 0.0 ? o.i0 : o.fullScale;
    if (!std::isfinite(i0) || o.i0 < 0.0) throw Error("--i0 must be positive (the unattenuated intensity)");
    if (o.erodePixels < 0 || o.erodePixels > 1000) throw Error("--erode must be between 0 and 1000 pixels");
    if (o.excludeBelow && !std::isfinite(*o.excludeBelow)) throw Error("--exclude-below must be finite");

    const int w = radiograph.width, h = radiograph.height;
    PreparedRadiograph out;
    out.valid = Mask(w, h, true);
    if (o.excludeBelow) {
        Mask excluded(w, h, false);
        for (std::size_t i = 0; i < radiograph.pixels.size(); ++i)
            excluded.inside[i] = radiograph.pixels[i] <= *o.excludeBelow;
        out.valid = complement(dilate(excluded, o.erodePixels));
    }
    if (o.roi) {
        const PixelRect& r = *o.roi;
        if (r.cols < 1 || r.rows < 1 || r.col0 < 0 || r.row0 < 0 || r.col0 + r.cols > w || r.row0 + r.rows > h)
            throw Error("--roi " + std::to_string(r.col0) + "," + std::to_string(r.row0) + "," +
                        std::to_string(r.cols) + "," + std::to_string(r.rows) + " must lie inside the " +
                        std::to_string(w) + " x " + std::to_string(h) + " image");
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                if (x < r.col0 || y < r.row0 || x >= r.col0 + r.cols || y >= r.row0 + r.rows)
                    out.valid.inside[static_cast<std::size_t>(y) * w + x] = 0;
    }
    out.image = radiograph;
    dropNonFinite(out.image, out.valid);
    if (o.logTransform)
        for (float& v : out.image.pixels)
            v = static_cast<float>(-std::log(std::clamp(static_cast<double>(v), 1.0, i0) / i0));
    if (o.invert)
        for (float& v : out.image.pixels) v = static_cast<float>(o.fullScale - v);
    return out;
}

}  // namespace fm

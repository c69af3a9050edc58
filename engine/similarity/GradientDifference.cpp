#include "similarity/GradientDifference.h"

#include <string>

#include "core/Error.h"

namespace fm {

namespace {

double variance(const Image& g, const Mask& m, std::size_t n) {
    double s = 0.0;
    for (std::size_t i = 0; i < g.pixels.size(); ++i)
        if (m.inside[i]) s += g.pixels[i];
    const double mean = s / double(n);
    double v = 0.0;
    for (std::size_t i = 0; i < g.pixels.size(); ++i)
        if (m.inside[i]) v += (g.pixels[i] - mean) * (g.pixels[i] - mean);
    return v / double(n);
}

}  // namespace

double gradientDifference(const GradientImages& ref, const GradientImages& drr,
                          const Mask& interior) {
    const std::size_t size = ref.gx.pixels.size();
    if (drr.gx.pixels.size() != size || interior.inside.size() != size)
        throw Error("gradient difference needs images and mask of one size");
    const std::size_t n = interior.count();
    if (n < 2) return 0.0;
    const double ax = variance(ref.gx, interior, n), ay = variance(ref.gy, interior, n);
    if (!(ax > 0.0) && !(ay > 0.0)) return 0.0;
    double rd = 0.0, dd = 0.0;
    for (std::size_t i = 0; i < size; ++i) {
        if (!interior.inside[i]) continue;
        rd += double(ref.gx.pixels[i]) * drr.gx.pixels[i] +
              double(ref.gy.pixels[i]) * drr.gy.pixels[i];
        dd += double(drr.gx.pixels[i]) * drr.gx.pixels[i] +
              double(drr.gy.pixels[i]) * drr.gy.pixels[i];
    }
    const double s = dd > 0.0 ? rd / dd : 0.0;
    double sum = 0.0;
    for (std::size_t i = 0; i < size; ++i) {
        if (!interior.inside[i]) continue;
        const double dx = ref.gx.pixels[i] - s * drr.gx.pixels[i];
        const double dy = ref.gy.pixels[i] - s * drr.gy.pixels[i];
        // A zero-variance component carries no information: count it as a perfect match.
        sum += (ax > 0.0 ? ax / (ax + dx * dx) : 1.0) + (ay > 0.0 ? ay / (ay + dy * dy) : 1.0);
    }
    return sum / (2.0 * double(n));
}

double gradientDifference(const Image& reference, const Image& drr, const Mask* mask) {
    if (reference.width != drr.width || reference.height != drr.height)
        throw Error("gradient difference needs images of one size, got " +
                    std::to_string(reference.width) + "x" + std::to_string(reference.height) +
                    " and " + std::to_string(drr.width) + "x" + std::to_string(drr.height));
    if (mask && (mask->width != drr.width || mask->height != drr.height))
        throw Error("gradient difference mask size differs from the image size");
    return gradientDifference(sobel(reference), sobel(drr),
                              interiorMask(drr.width, drr.height, mask));
}

}  // namespace fm

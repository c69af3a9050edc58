#include "similarity/GradientNcc.h"

#include <string>

#include "core/Error.h"
#include "similarity/Ncc.h"

namespace fm {

double gradientNcc(const GradientImages& a, const GradientImages& b, const Mask& interior) {
    const std::size_t n = a.gx.pixels.size();
    if (b.gx.pixels.size() != n || interior.inside.size() != n)
        throw Error("gradient NCC needs images and mask of one size");
    const double cx = nccValues(a.gx.pixels.data(), b.gx.pixels.data(), interior.inside.data(), n);
    const double cy = nccValues(a.gy.pixels.data(), b.gy.pixels.data(), interior.inside.data(), n);
    return 0.5 * (cx + cy);
}

double gradientNcc(const Image& a, const Image& b, const Mask* mask) {
    if (a.width != b.width || a.height != b.height)
        throw Error("gradient NCC needs images of one size, got " + std::to_string(a.width) + "x" +
                    std::to_string(a.height) + " and " + std::to_string(b.width) + "x" +
                    std::to_string(b.height));
    if (mask && (mask->width != a.width || mask->height != a.height))
        throw Error("gradient NCC mask size differs from the image size");
    return gradientNcc(sobel(a), sobel(b), interiorMask(a.width, a.height, mask));
}

}  // namespace fm

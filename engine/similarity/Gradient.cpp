#include "similarity/Gradient.h"

namespace fm {

GradientImages sobel(const Image& image) {
    const int w = image.width, h = image.height;
    GradientImages g{Image(w, h), Image(w, h)};
    g.gx.spacing = g.gy.spacing = image.spacing;
    for (int r = 1; r + 1 < h; ++r)
        for (int c = 1; c + 1 < w; ++c) {
            const float a = image.at(c - 1, r - 1), b = image.at(c, r - 1),
                        d = image.at(c + 1, r - 1);
            const float e = image.at(c - 1, r), f = image.at(c + 1, r);
            const float p = image.at(c - 1, r + 1), q = image.at(c, r + 1),
                        s = image.at(c + 1, r + 1);
            g.gx.at(c, r) = ((d + 2.0f * f + s) - (a + 2.0f * e + p)) * 0.125f;
            g.gy.at(c, r) = ((p + 2.0f * q + s) - (a + 2.0f * b + d)) * 0.125f;
        }
    return g;
}

Mask interiorMask(int width, int height, const Mask* mask) {
    Mask m(width, height, false);
    for (int r = 1; r + 1 < height; ++r)
        for (int c = 1; c + 1 < width; ++c)
            m.inside[static_cast<std::size_t>(r) * width + c] = mask ? mask->at(c, r) : true;
    return m;
}

}  // namespace fm

#include "similarity/ImagePyramid.h"

#include <string>

#include "core/Error.h"

namespace fm {

Image downsample2x2(const Image& image) {
    if (image.width < 2 || image.height < 2)
        throw Error("cannot downsample a " + std::to_string(image.width) + "x" +
                    std::to_string(image.height) + " image by 2: it needs at least 2x2 pixels");
    Image out(image.width / 2, image.height / 2);
    out.spacing = image.spacing * 2.0;
    for (int r = 0; r < out.height; ++r)
        for (int c = 0; c < out.width; ++c) {
            // Sum in double: the mean of four floats is then exact up to one final rounding.
            const double sum = double(image.at(2 * c, 2 * r)) + image.at(2 * c + 1, 2 * r) +
                               image.at(2 * c, 2 * r + 1) + image.at(2 * c + 1, 2 * r + 1);
            out.at(c, r) = static_cast<float>(sum * 0.25);
        }
    return out;
}

Image downsampleBy(const Image& image, int factor) {
    if (factor < 1 || (factor & (factor - 1)) != 0)
        throw Error("downsampling factor must be a power of two, got " + std::to_string(factor));
    Image out = image;
    for (int f = factor; f > 1; f /= 2) out = downsample2x2(out);
    return out;
}

ImagePyramid buildPyramid(const Image& image, int levelCount) {
    if (levelCount < 1)
        throw Error("pyramid level count must be at least 1, got " + std::to_string(levelCount));
    ImagePyramid p;
    p.levels.push_back(image);
    for (int k = 1; k < levelCount; ++k) p.levels.push_back(downsample2x2(p.levels.back()));
    return p;
}

}  // namespace fm

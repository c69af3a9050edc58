#include "similarity/AreaResample.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/Error.h"

namespace fm {

namespace {

// Shares below this (of one input pixel) are rounding in the interval ends, not overlap.
constexpr double kMinShare = 1e-9;

struct Tap {
    int index;
    double weight;  // share of the output pixel's interval, summing to 1
};

// Per output pixel along one axis, the input pixels its interval [j s, (j + 1) s) covers.
std::vector<std::vector<Tap>> taps(int input, int output) {
    const double s = double(input) / output;
    std::vector<std::vector<Tap>> out(static_cast<std::size_t>(output));
    for (int j = 0; j < output; ++j) {
        const double lo = j * s, hi = std::min(double(input), (j + 1) * s);
        for (int i = std::max(0, int(std::floor(lo))); i < input && i < hi; ++i) {
            const double share = std::min(hi, i + 1.0) - std::max(lo, double(i));
            if (share > kMinShare) out[static_cast<std::size_t>(j)].push_back({i, share / s});
        }
    }
    return out;
}

void checkSizes(int width, int height, glm::ivec2 size, const char* what) {
    if (width < 1 || height < 1) throw Error(std::string("cannot resample an empty ") + what);
    if (size.x < 1 || size.y < 1)
        throw Error(std::string("cannot resample ") + what + " to " + std::to_string(size.x) + "x" +
                    std::to_string(size.y) + " pixels");
}

}  // namespace

Image resampleByArea(const Image& image, glm::ivec2 size) {
    checkSizes(image.width, image.height, size, "image");
    if (size == glm::ivec2(image.width, image.height)) return image;
    const auto cols = taps(image.width, size.x), rows = taps(image.height, size.y);
    // Along the rows first (into doubles), then down the columns.
    std::vector<double> across(static_cast<std::size_t>(size.x) * image.height, 0.0);
    for (int r = 0; r < image.height; ++r)
        for (int c = 0; c < size.x; ++c) {
            double sum = 0.0;
            for (const Tap& t : cols[static_cast<std::size_t>(c)]) sum += t.weight * image.at(t.index, r);
            across[static_cast<std::size_t>(r) * size.x + c] = sum;
        }
    Image out(size.x, size.y);
    out.spacing = image.spacing * glm::dvec2(double(image.width) / size.x, double(image.height) / size.y);
    for (int r = 0; r < size.y; ++r)
        for (int c = 0; c < size.x; ++c) {
            double sum = 0.0;
            for (const Tap& t : rows[static_cast<std::size_t>(r)])
                sum += t.weight * across[static_cast<std::size_t>(t.index) * size.x + c];
            out.at(c, r) = static_cast<float>(sum);
        }
    return out;
}

Mask resampleMaskByArea(const Mask& mask, glm::ivec2 size) {
    checkSizes(mask.width, mask.height, size, "mask");
    if (size == glm::ivec2(mask.width, mask.height)) return mask;
    const auto cols = taps(mask.width, size.x), rows = taps(mask.height, size.y);
    // "Every input pixel it takes a share of" is separable: along the rows first (is every
    // tapped pixel of this input row valid?), then down the columns.
    std::vector<std::uint8_t> across(static_cast<std::size_t>(size.x) * mask.height, 0);
    for (int r = 0; r < mask.height; ++r) {
        const std::uint8_t* in = mask.inside.data() + static_cast<std::size_t>(r) * mask.width;
        std::uint8_t* out = across.data() + static_cast<std::size_t>(r) * size.x;
        for (int c = 0; c < size.x; ++c) {
            bool all = true;
            for (const Tap& t : cols[static_cast<std::size_t>(c)]) all = all && in[t.index] != 0;
            out[c] = all ? 1 : 0;
        }
    }
    Mask out(size.x, size.y, true);
    for (int r = 0; r < size.y; ++r) {
        std::uint8_t* row = out.inside.data() + static_cast<std::size_t>(r) * size.x;
        for (const Tap& t : rows[static_cast<std::size_t>(r)]) {
            const std::uint8_t* in = across.data() + static_cast<std::size_t>(t.index) * size.x;
            for (int c = 0; c < size.x; ++c) row[c] &= in[c];
        }
    }
    return out;
}

}  // namespace fm

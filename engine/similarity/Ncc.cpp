#include "similarity/Ncc.h"

#include <cmath>
#include <string>

#include "core/Error.h"

namespace fm {

double nccValues(const float* a, const float* b, const std::uint8_t* mask, std::size_t count) {
    // Two passes (means first) rather than raw sums of squares: DRR values are large and
    // nearly constant over flat regions, where the one-pass formula loses all digits.
    double sa = 0.0, sb = 0.0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < count; ++i) {
        if (mask && !mask[i]) continue;
        sa += a[i];
        sb += b[i];
        ++n;
    }
    if (n < 2) return 0.0;
    const double ma = sa / double(n), mb = sb / double(n);
    double sab = 0.0, saa = 0.0, sbb = 0.0;
    for (std::size_t i = 0; i < count; ++i) {
        if (mask && !mask[i]) continue;
        const double da = a[i] - ma, db = b[i] - mb;
        sab += da * db;
        saa += da * da;
        sbb += db * db;
    }
    if (!(saa > 0.0) || !(sbb > 0.0)) return 0.0;
    return sab / std::sqrt(saa * sbb);
}

double ncc(const Image& a, const Image& b, const Mask* mask) {
    if (a.width != b.width || a.height != b.height)
        throw Error("NCC needs images of one size, got " + std::to_string(a.width) + "x" +
                    std::to_string(a.height) + " and " + std::to_string(b.width) + "x" +
                    std::to_string(b.height));
    if (mask && (mask->width != a.width || mask->height != a.height))
        throw Error("NCC mask is " + std::to_string(mask->width) + "x" +
                    std::to_string(mask->height) + " but the images are " +
                    std::to_string(a.width) + "x" + std::to_string(a.height));
    return nccValues(a.pixels.data(), b.pixels.data(), mask ? mask->inside.data() : nullptr,
                     a.pixels.size());
}

}  // namespace fm

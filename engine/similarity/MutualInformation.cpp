#include "similarity/MutualInformation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "core/Error.h"

namespace fm {

double mutualInformation(const Image& a, const Image& b, const Mask* mask, int bins) {
    if (a.width != b.width || a.height != b.height)
        throw Error("mutual information needs images of one size, got " +
                    std::to_string(a.width) + "x" + std::to_string(a.height) + " and " +
                    std::to_string(b.width) + "x" + std::to_string(b.height));
    if (mask && (mask->width != a.width || mask->height != a.height))
        throw Error("mutual information: the mask size differs from the image size");
    if (bins < 2 || bins > 1024)
        throw Error("mutual information: bins must be 2..1024, got " + std::to_string(bins));
    const std::size_t n = a.pixels.size();
    auto use = [&](std::size_t i) { return !mask || mask->inside[i]; };
    float amin = std::numeric_limits<float>::infinity(), amax = -amin;
    float bmin = amin, bmax = -amin;
    std::size_t count = 0;
    for (std::size_t i = 0; i < n; ++i) {
        if (!use(i)) continue;
        amin = std::min(amin, a.pixels[i]);
        amax = std::max(amax, a.pixels[i]);
        bmin = std::min(bmin, b.pixels[i]);
        bmax = std::max(bmax, b.pixels[i]);
        ++count;
    }
    if (count < 2 || !(amax > amin) || !(bmax > bmin)) return 0.0;
    const double as = (bins - 1) / (double(amax) - amin), bs = (bins - 1) / (double(bmax) - bmin);
    std::vector<double> joint(static_cast<std::size_t>(bins) * bins, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
        if (!use(i)) continue;
        const double pa = (a.pixels[i] - double(amin)) * as, pb = (b.pixels[i] - double(bmin)) * bs;
        const int ia = std::min(static_cast<int>(pa), bins - 2);
        const int ib = std::min(static_cast<int>(pb), bins - 2);
        const double fa = pa - ia, fb = pb - ib;
        double* r0 = &joint[static_cast<std::size_t>(ia) * bins + ib];
        double* r1 = r0 + bins;
        r0[0] += (1 - fa) * (1 - fb);
        r0[1] += (1 - fa) * fb;
        r1[0] += fa * (1 - fb);
        r1[1] += fa * fb;
    }
    std::vector<double> pa(bins, 0.0), pb(bins, 0.0);
    for (int i = 0; i < bins; ++i)
        for (int j = 0; j < bins; ++j) {
            pa[i] += joint[static_cast<std::size_t>(i) * bins + j];
            pb[j] += joint[static_cast<std::size_t>(i) * bins + j];
        }
    // MI = sum p(a,b) log(p(a,b) / (p(a) p(b))), with p = counts / N.
    const double total = double(count);
    double mi = 0.0;
    for (int i = 0; i < bins; ++i)
        for (int j = 0; j < bins; ++j) {
            const double pij = joint[static_cast<std::size_t>(i) * bins + j];
            if (pij <= 0.0) continue;
            mi += pij * std::log(pij * total / (pa[i] * pb[j]));
        }
    return std::max(0.0, mi / total);
}

}  // namespace fm

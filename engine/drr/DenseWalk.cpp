// The scalar plain walk and the dispatch to the AVX-512 form (DenseWalkAvx512.cpp).
#include "drr/DenseWalk.h"

#include <algorithm>

namespace fm {

namespace detail {
void walkDense16Avx512(const float* values, std::int64_t last, const DenseRay* rays, int count,
                      double* sums);
}

double walkDense(const float* values, std::int64_t last, const DenseRay& r) {
    double next[3] = {r.next[0], r.next[1], r.next[2]};
    std::int64_t linear = r.linear, steps = r.steps;
    double alpha = r.aBegin, acc = 0.0;
    for (;;) {
        // The smallest next crossing; on ties the later axis (the vector form does the same).
        const int a = next[0] < next[1] ? (next[0] < next[2] ? 0 : 2) : (next[1] < next[2] ? 1 : 2);
        const double aNext = std::min(next[a], r.aEnd);
        if (aNext > alpha) {
            acc += (aNext - alpha) * static_cast<double>(values[std::clamp<std::int64_t>(linear, 0, last)]);
            alpha = aNext;
        }
        if (next[a] >= r.aEnd || steps == 0) break;
        --steps;
        linear += r.offset[a];
        next[a] += r.delta[a];
    }
    return acc;
}

bool denseWalkSimdAvailable() {
#if defined(__x86_64__) && defined(__GNUC__)
    static const bool available =
        __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq");
    return available;
#else
    return false;
#endif
}

void walkDense16(const float* values, std::int64_t last, const DenseRay* rays, int count,
                double* sums) {
#if defined(__x86_64__) && defined(__GNUC__)
    if (denseWalkSimdAvailable()) {
        detail::walkDense16Avx512(values, last, rays, count, sums);
        return;
    }
#endif
    for (int i = 0; i < count; ++i) sums[i] = walkDense(values, last, rays[i]);
}

}  // namespace fm

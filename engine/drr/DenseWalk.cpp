// The scalar plain walk and the dispatch to the AVX-512 form (DenseWalkAvx512.cpp).
#include "drr/DenseWalk.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fm {

namespace detail {
template <class T, bool Prefetch, bool WithAbs>
void walkDense16Avx512(const T* values, std::int64_t last, const DenseRay* rays, int count,
                       WalkSums* sums);
}

template <class T, bool WithAbs>
WalkSums walkDense(const T* values, std::int64_t last, const DenseRay& r) {
    double next[3] = {r.next[0], r.next[1], r.next[2]};
    std::int64_t linear = r.linear, steps = r.steps;
    double alpha = r.aBegin;
    WalkSums acc;
    for (;;) {
        // The smallest next crossing; on ties the later axis (the vector form does the same).
        const double nextMin = std::min(next[0], std::min(next[1], next[2]));
        const int a = next[2] == nextMin ? 2 : (next[1] == nextMin ? 1 : 0);
        // Never negative: alpha is the last crossing, every next crossing is at or after it
        // (DenseRay's next >= aBegin, increments >= 0), and aEnd >= aBegin.
        const double aNext = std::min(nextMin, r.aEnd);
        // |length * value| = length * |value| exactly: lengths are >= 0 and a sign flip is exact.
        const double segment =
            (aNext - alpha) * static_cast<double>(values[std::clamp<std::int64_t>(linear, 0, last)]);
        acc.sum += segment;
        if constexpr (WithAbs) acc.absSum += std::abs(segment);
        alpha = aNext;
        if (nextMin >= r.aEnd || steps == 0) break;
        --steps;
        linear += r.offset[a];
        next[a] += r.delta[a];
    }
    return acc;
}

bool denseWalkSimdAvailable() {
#if defined(__x86_64__) && defined(__GNUC__)
    static const bool available =
        __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") &&
        __builtin_cpu_supports("avx512vl");
    return available;
#else
    return false;
#endif
}

template <class T, bool WithAbs>
void walkDense16(const T* values, std::int64_t last, const DenseRay* rays, int count,
                 WalkSums* sums) {
#if defined(__x86_64__) && defined(__GNUC__)
    // The vector form indexes in 32 bits; a volume past that (2^31 voxels) walks
    // one ray at a time, with the same sums.
    if (denseWalkSimdAvailable() && last <= std::numeric_limits<std::int32_t>::max()) {
        if (denseWalkPrefetches(std::uint64_t(last + 1) * sizeof(T)))
            detail::walkDense16Avx512<T, true, WithAbs>(values, last, rays, count, sums);
        else
            detail::walkDense16Avx512<T, false, WithAbs>(values, last, rays, count, sums);
        return;
    }
#endif
    for (int i = 0; i < count; ++i) sums[i] = walkDense<T, WithAbs>(values, last, rays[i]);
}

template WalkSums walkDense<float, false>(const float*, std::int64_t, const DenseRay&);
template WalkSums walkDense<float, true>(const float*, std::int64_t, const DenseRay&);
template WalkSums walkDense<std::int16_t, false>(const std::int16_t*, std::int64_t, const DenseRay&);
template WalkSums walkDense<std::int16_t, true>(const std::int16_t*, std::int64_t, const DenseRay&);
template void walkDense16<float, false>(const float*, std::int64_t, const DenseRay*, int, WalkSums*);
template void walkDense16<float, true>(const float*, std::int64_t, const DenseRay*, int, WalkSums*);
template void walkDense16<std::int16_t, false>(const std::int16_t*, std::int64_t, const DenseRay*, int,
                                                WalkSums*);
template void walkDense16<std::int16_t, true>(const std::int16_t*, std::int64_t, const DenseRay*, int,
                                               WalkSums*);

}  // namespace fm

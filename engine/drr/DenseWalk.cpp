// The scalar plain walk and the dispatch to the vector forms (DenseWalkAvx512.cpp,
// DenseWalkAvx2.cpp).
#include "drr/DenseWalk.h"

#include "core/Error.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

namespace fm {

namespace detail {
template <class T, bool Prefetch, bool WithAbs>
void walkDense16Avx512(const T* values, std::int64_t last, const DenseRay* rays, int count,
                       WalkSums* sums);
template <class T, bool WithAbs>
void walkDense16Avx2(const T* values, std::int64_t last, const DenseRay* rays, int count, WalkSums* sums);
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

DenseWalkSimd denseWalkSimdSupported() {
#if defined(__x86_64__) && defined(__GNUC__)
    static const DenseWalkSimd supported = [] {
        if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") &&
            __builtin_cpu_supports("avx512vl"))
            return DenseWalkSimd::Avx512;
        return __builtin_cpu_supports("avx2") ? DenseWalkSimd::Avx2 : DenseWalkSimd::None;
    }();
    return supported;
#else
    return DenseWalkSimd::None;
#endif
}

namespace {
// The form a test chose (ScopedDenseWalkSimd); none chosen: the widest supported.
std::atomic<int> chosenForm{-1};
}  // namespace

DenseWalkSimd denseWalkSimd() {
    const int chosen = chosenForm.load(std::memory_order_relaxed);
    return chosen < 0 ? denseWalkSimdSupported() : static_cast<DenseWalkSimd>(chosen);
}

ScopedDenseWalkSimd::ScopedDenseWalkSimd(DenseWalkSimd form) : previous_(denseWalkSimd()) {
    if (static_cast<int>(form) > static_cast<int>(denseWalkSimdSupported()))
        throw Error("ScopedDenseWalkSimd: this CPU does not run that form");
    chosenForm.store(static_cast<int>(form), std::memory_order_relaxed);
}
ScopedDenseWalkSimd::~ScopedDenseWalkSimd() {
    chosenForm.store(static_cast<int>(previous_), std::memory_order_relaxed);
}

template <class T, bool WithAbs>
void walkDense16(const T* values, std::int64_t last, const DenseRay* rays, int count,
                 WalkSums* sums) {
#if defined(__x86_64__) && defined(__GNUC__)
    switch (denseWalkSimd()) {
        case DenseWalkSimd::Avx512:
            // This form indexes in 32 bits; a volume past that (2^31 voxels) walks in AVX2's
            // 64-bit lanes, with the same sums.
            if (last <= std::numeric_limits<std::int32_t>::max()) {
                if (denseWalkPrefetches(std::uint64_t(last + 1) * sizeof(T)))
                    detail::walkDense16Avx512<T, true, WithAbs>(values, last, rays, count, sums);
                else
                    detail::walkDense16Avx512<T, false, WithAbs>(values, last, rays, count, sums);
                return;
            }
            [[fallthrough]];
        case DenseWalkSimd::Avx2:
            detail::walkDense16Avx2<T, WithAbs>(values, last, rays, count, sums);
            return;
        case DenseWalkSimd::None: break;
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

// Plain walks in the lanes of AVX-512 vectors (see DenseWalk.h): two groups of eight rays
// stepped in turn, so that one group's compare -> mask -> masked-add chain runs while the
// other's waits. Lane i does what walkDense does for ray i, operation for operation; a lane
// that is done is masked off and a group runs until all its lanes are done (neighbouring
// pixels' rays are about equally long). The step bound and the read clamp are off the chain.
// The eight values of a step are read with eight scalar loads, not the AVX-512 gather
// instruction: on this machine's AMD EPYC the gather was half of the walk's time, and scalar
// loads made whole renders 1.24-1.42x faster (docs/drr.md, "The dense walk").
//
// On a volume larger than the caches the walk waits on memory: every lane's next voxel is a
// cache miss whenever the lane crosses into another row or slice, and neither the hardware
// prefetcher nor a prefetch "16 voxels further along the main axis" foresees those crossings.
// The prefetching form (walkDense16's choice by volume size, DenseWalk.h) therefore runs a
// shadow of each group: the same index walk kShadowSteps steps ahead, without values or sums,
// prefetching the voxel every lane will read then. The shadow only hints; sums are unchanged.
#include "drr/DenseWalk.h"

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>

// GCC 12 flags the undefined source vector inside _mm512_min_pd / _mm512_cvtps_pd.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#pragma GCC diagnostic ignored "-Wuninitialized"
// The vector arguments of the inline helpers below never cross a non-AVX-512 call.
#pragma GCC diagnostic ignored "-Wpsabi"

#define FM_AVX512 __attribute__((target("avx512f,avx512dq,avx512vl")))

namespace fm::detail {
namespace {

struct Lanes {
    __m512d nx, ny, nz, dx, dy, dz, alpha, aEnd, acc, absAcc, value;
    // Indices in 32 bits (the caller checks that the padded values fit): half-width integer
    // work (measured 4-6 % faster than 64-bit lanes).
    __m256i linear, ox, oy, oz, steps;
    __mmask8 active;
    // Without the shadow: prefetch distance of lanes 0 and 7, 16 voxels along each one's main
    // axis (without it the 12 MB DICOM series' lateral and oblique views were 5-15 % slower;
    // the shadow costs more than it saves there).
    std::int32_t ahead0, ahead7;
    // The shadow (prefetching form only): next crossings and linear index kShadowSteps ahead.
    __m512d snx, sny, snz;
    __m256i slinear;
};

// How far the shadow runs ahead. A step of both groups takes ~5-10 ns when its voxels are in
// the cache, so 12 steps cover a memory latency of ~100 ns; on the GE head (173 MB) 6 and 24
// steps were 10-20 % slower than 12 (docs/drr.md, "Prefetching on large volumes").
constexpr int kShadowSteps = 12;

// Eight values widened to doubles, zero in the lanes not asked for: float -> double and
// int16 -> int32 -> double are exact.
FM_AVX512 inline __m512d widen(const float* values, const std::int32_t* idx, __mmask8 lanes) {
    const __m128 lo = _mm_setr_ps(values[idx[0]], values[idx[1]], values[idx[2]], values[idx[3]]);
    const __m128 hi = _mm_setr_ps(values[idx[4]], values[idx[5]], values[idx[6]], values[idx[7]]);
    return _mm512_cvtps_pd(_mm256_maskz_mov_ps(lanes, _mm256_set_m128(hi, lo)));
}
FM_AVX512 inline __m512d widen(const std::int16_t* values, const std::int32_t* idx,
                               __mmask8 lanes) {
    const __m256i v = _mm256_setr_epi32(values[idx[0]], values[idx[1]], values[idx[2]],
                                        values[idx[3]], values[idx[4]], values[idx[5]],
                                        values[idx[6]], values[idx[7]]);
    return _mm512_cvtepi32_pd(_mm256_maskz_mov_epi32(lanes, v));
}

// A hint to fetch values[index]. The index may lie outside the array (the shadow runs past a
// ray's end, or wraps in 32 bits), so the address is formed as an integer: a prefetch never
// faults.
template <class T>
inline void prefetch(const T* values, std::int64_t index) {
    _mm_prefetch(reinterpret_cast<const char*>(reinterpret_cast<std::uintptr_t>(values) +
                                               static_cast<std::uintptr_t>(index * sizeof(T))),
                 _MM_HINT_T0);
}

// The values at the lanes' indices, each clamped to [0, last]; zero in the lanes not asked for
// (those read a valid voxel too, then masked). Without the shadow, also a prefetch for the
// outer lanes some steps on.
template <class T, bool Prefetch>
FM_AVX512 inline __m512d gather(const T* values, __m256i linear, __m256i lastIndex,
                                __mmask8 lanes, std::int32_t ahead0, std::int32_t ahead7) {
    const __m256i at =
        _mm256_min_epi32(_mm256_max_epi32(linear, _mm256_setzero_si256()), lastIndex);
    alignas(32) std::int32_t idx[8];
    _mm256_store_si256(reinterpret_cast<__m256i*>(idx), at);
    if constexpr (!Prefetch) {
        prefetch(values, std::int64_t(idx[0]) + ahead0);
        prefetch(values, std::int64_t(idx[7]) + ahead7);
    }
    return widen(values, idx, lanes);
}

// A hint to fetch the eight lanes' voxels at the shadow's indices.
template <class T>
FM_AVX512 inline void prefetchLanes(const T* values, __m256i linear) {
    alignas(32) std::int32_t idx[8];
    _mm256_store_si256(reinterpret_cast<__m256i*>(idx), linear);
    for (int i = 0; i < 8; ++i) prefetch(values, idx[i]);
}

// The smallest of the next crossings and the lanes whose smallest is on y or z; ties go to
// the later axis (as walkDense).
struct Crossing {
    __m512d nextMin;
    __mmask8 onY, onZ;
};
FM_AVX512 inline Crossing nextCrossing(__m512d nx, __m512d ny, __m512d nz) {
    Crossing c;
    c.nextMin = _mm512_min_pd(nx, _mm512_min_pd(ny, nz));
    c.onZ = _mm512_cmp_pd_mask(nz, c.nextMin, _CMP_EQ_OQ);
    c.onY = _mm512_mask_cmp_pd_mask(static_cast<__mmask8>(~c.onZ), ny, c.nextMin, _CMP_EQ_OQ);
    return c;
}

// The lanes in `move` cross the plane of their next crossing: the linear index steps along
// that axis and the axis's next crossing moves one increment on.
FM_AVX512 inline void cross(const Lanes& l, const Crossing& c, __mmask8 move, __m512d& nx,
                            __m512d& ny, __m512d& nz, __m256i& linear) {
    const __mmask8 sz = move & c.onZ, sy = move & c.onY,
                   sx = move & static_cast<__mmask8>(~(c.onZ | c.onY));
    linear = _mm256_mask_add_epi32(linear, sx, linear, l.ox);
    linear = _mm256_mask_add_epi32(linear, sy, linear, l.oy);
    linear = _mm256_mask_add_epi32(linear, sz, linear, l.oz);
    nx = _mm512_mask_add_pd(nx, sx, nx, l.dx);
    ny = _mm512_mask_add_pd(ny, sy, ny, l.dy);
    nz = _mm512_mask_add_pd(nz, sz, nz, l.dz);
}

// One step of the shadow: step()'s crossing for every lane (a lane past its end walks on
// harmlessly).
FM_AVX512 inline void shadowStep(Lanes& l) {
    cross(l, nextCrossing(l.snx, l.sny, l.snz), 0xff, l.snx, l.sny, l.snz, l.slinear);
}

template <class T, bool Prefetch>
FM_AVX512 inline void load(Lanes& l, const T* values, __m256i lastIndex,
                           const DenseRay* rays, int count) {
    alignas(64) double lane[8][8];
    alignas(64) std::int32_t ilane[5][8];
    for (int i = 0; i < 8; ++i) {
        // Unused lanes get an empty ray; they are masked off from the start.
        const DenseRay r = i < count ? rays[i] : DenseRay{};
        for (int a = 0; a < 3; ++a) {
            lane[a][i] = r.next[a];
            lane[3 + a][i] = r.delta[a];
            ilane[1 + a][i] = static_cast<std::int32_t>(r.offset[a]);
        }
        lane[6][i] = r.aBegin;
        lane[7][i] = r.aEnd;
        ilane[0][i] = static_cast<std::int32_t>(r.linear);
        ilane[4][i] = static_cast<std::int32_t>(r.steps);
    }
    l.nx = _mm512_load_pd(lane[0]);
    l.ny = _mm512_load_pd(lane[1]);
    l.nz = _mm512_load_pd(lane[2]);
    l.dx = _mm512_load_pd(lane[3]);
    l.dy = _mm512_load_pd(lane[4]);
    l.dz = _mm512_load_pd(lane[5]);
    l.alpha = _mm512_load_pd(lane[6]);
    l.aEnd = _mm512_load_pd(lane[7]);
    l.linear = _mm256_load_si256(reinterpret_cast<const __m256i*>(ilane[0]));
    l.ox = _mm256_load_si256(reinterpret_cast<const __m256i*>(ilane[1]));
    l.oy = _mm256_load_si256(reinterpret_cast<const __m256i*>(ilane[2]));
    l.oz = _mm256_load_si256(reinterpret_cast<const __m256i*>(ilane[3]));
    l.steps = _mm256_load_si256(reinterpret_cast<const __m256i*>(ilane[4]));
    l.active = static_cast<__mmask8>(count >= 8 ? 0xffu : (1u << count) - 1u);
    auto ahead = [&](int i) {
        if (Prefetch || i < 0 || i >= count) return std::int32_t(0);
        const DenseRay& r = rays[i];
        int a = 0;
        for (int b = 1; b < 3; ++b)
            if (r.delta[b] > 0.0 && (r.delta[a] <= 0.0 || r.delta[b] < r.delta[a])) a = b;
        return static_cast<std::int32_t>(16 * r.offset[a]);
    };
    l.ahead0 = ahead(0);
    l.ahead7 = ahead(count >= 8 ? 7 : count - 1);
    if constexpr (Prefetch) {
        // The first kShadowSteps voxels of every lane at once, then one step ahead per step.
        l.snx = l.nx;
        l.sny = l.ny;
        l.snz = l.nz;
        l.slinear = l.linear;
        for (int i = 0; i < kShadowSteps; ++i) {
            shadowStep(l);
            prefetchLanes(values, l.slinear);
        }
    }
    l.acc = _mm512_setzero_pd();
    l.absAcc = _mm512_setzero_pd();
    l.value = gather<T, Prefetch>(values, l.linear, lastIndex, l.active, l.ahead0, l.ahead7);
}

// One step of every active lane: walkDense's loop body.
template <class T, bool Prefetch, bool WithAbs>
FM_AVX512 inline void step(Lanes& l, const T* values, __m256i lastIndex) {
    const Crossing c = nextCrossing(l.nx, l.ny, l.nz);
    const __m512d aNext = _mm512_min_pd(c.nextMin, l.aEnd);
    // Segments never run backwards (walkDense), so no test for a positive length.
    const __m512d segment = _mm512_mul_pd(_mm512_sub_pd(aNext, l.alpha), l.value);
    l.acc = _mm512_mask_add_pd(l.acc, l.active, l.acc, segment);
    if constexpr (WithAbs)
        l.absAcc = _mm512_mask_add_pd(l.absAcc, l.active, l.absAcc, _mm512_abs_pd(segment));
    l.alpha = aNext;
    // Done: the next crossing is at or beyond the end, or no step is left.
    l.active = _mm512_mask_cmp_pd_mask(l.active, c.nextMin, l.aEnd, _CMP_LT_OQ) &
               _mm256_test_epi32_mask(l.steps, l.steps);
    l.steps = _mm256_mask_sub_epi32(l.steps, l.active, l.steps, _mm256_set1_epi32(1));
    cross(l, c, l.active, l.nx, l.ny, l.nz, l.linear);
    if constexpr (Prefetch) {
        shadowStep(l);
        prefetchLanes(values, l.slinear);
    }
    l.value = gather<T, Prefetch>(values, l.linear, lastIndex, l.active, l.ahead0, l.ahead7);
}

FM_AVX512 inline void store(const Lanes& l, int count, WalkSums* sums) {
    alignas(64) double out[8], outAbs[8];
    _mm512_store_pd(out, l.acc);
    _mm512_store_pd(outAbs, l.absAcc);
    for (int i = 0; i < count; ++i) sums[i] = {out[i], outAbs[i]};
}

}  // namespace

template <class T, bool Prefetch, bool WithAbs>
FM_AVX512 void walkDense16Avx512(const T* values, std::int64_t last, const DenseRay* rays,
                                 int count, WalkSums* sums) {
    const __m256i lastIndex = _mm256_set1_epi32(static_cast<std::int32_t>(last));
    const int countA = count < 8 ? count : 8, countB = count - countA;
    Lanes a, b;
    load<T, Prefetch>(a, values, lastIndex, rays, countA);
    load<T, Prefetch>(b, values, lastIndex, rays + countA, countB);
    while (a.active && b.active) {
        step<T, Prefetch, WithAbs>(a, values, lastIndex);
        step<T, Prefetch, WithAbs>(b, values, lastIndex);
    }
    while (a.active) step<T, Prefetch, WithAbs>(a, values, lastIndex);
    while (b.active) step<T, Prefetch, WithAbs>(b, values, lastIndex);
    store(a, countA, sums);
    store(b, countB, sums + countA);
}

#define FM_WALK_DENSE16(T, PREFETCH, WITH_ABS)                                                  \
    template void walkDense16Avx512<T, PREFETCH, WITH_ABS>(const T*, std::int64_t, const DenseRay*, int, \
                                                           WalkSums*);
FM_WALK_DENSE16(float, false, false)
FM_WALK_DENSE16(float, true, false)
FM_WALK_DENSE16(float, false, true)
FM_WALK_DENSE16(float, true, true)
FM_WALK_DENSE16(std::int16_t, false, false)
FM_WALK_DENSE16(std::int16_t, true, false)
FM_WALK_DENSE16(std::int16_t, false, true)
FM_WALK_DENSE16(std::int16_t, true, true)
#undef FM_WALK_DENSE16

}  // namespace fm::detail
#endif

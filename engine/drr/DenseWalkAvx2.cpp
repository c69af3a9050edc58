// Plain walks in the lanes of AVX2 vectors (see DenseWalk.h), for CPUs without AVX-512: two
// groups of four rays stepped in turn, so that one group's compare -> blend -> add chain runs
// while the other's waits (eight rays at a time; four groups kept in an array were slower:
// the lanes lived in memory). Lane i does what walkDense does for ray i, operation for operation (the
// same minima, compares, products and sums; a blend where the scalar walk branches or the
// AVX-512 form masks), so the sums are bit-identical to both. AVX2 has no mask registers: a
// lane's "active" is an all-ones double lane, and every update is blended under it.
// Indices are 64-bit lanes (AVX2 adds them natively), so no volume is too large for this form.
#include "drr/DenseWalk.h"

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>

#include <algorithm>

// The vector arguments of the inline helpers below never cross a non-AVX2 call.
#pragma GCC diagnostic ignored "-Wpsabi"

#define FM_AVX2 __attribute__((target("avx2")))

namespace fm::detail {
namespace {

struct Lanes4 {
    __m256d nx, ny, nz, dx, dy, dz, alpha, aEnd, acc, absAcc, value;
    __m256i linear, ox, oy, oz, steps;
    __m256d active;  // all ones in the lanes still walking
};

// Four values widened to doubles (float -> double and int16 -> double are exact), each read at
// its index clamped to [0, last] (a lane that is done reads a valid voxel too; its sum is not
// updated).
// Four values widened to doubles (float -> double and int16 -> int32 -> double are exact, one
// vector conversion for the four), each read at its index clamped to [0, last] (a lane that is
// done reads a valid voxel too; its sum is not updated).
FM_AVX2 inline __m256d widen(const float* values, const std::int64_t* idx) {
    return _mm256_cvtps_pd(_mm_setr_ps(values[idx[0]], values[idx[1]], values[idx[2]], values[idx[3]]));
}
FM_AVX2 inline __m256d widen(const std::int16_t* values, const std::int64_t* idx) {
    return _mm256_cvtepi32_pd(_mm_setr_epi32(values[idx[0]], values[idx[1]], values[idx[2]], values[idx[3]]));
}
template <class T>
FM_AVX2 inline __m256d gather(const T* values, __m256i linear, std::int64_t last) {
    alignas(32) std::int64_t idx[4];
    _mm256_store_si256(reinterpret_cast<__m256i*>(idx), linear);
    for (std::int64_t& i : idx) i = std::clamp<std::int64_t>(i, 0, last);
    return widen(values, idx);
}

template <class T>
FM_AVX2 inline void load(Lanes4& l, const T* values, std::int64_t last, const DenseRay* rays, int count) {
    alignas(32) double lane[8][4];
    alignas(32) std::int64_t ilane[5][4];
    alignas(32) std::int64_t on[4];
    for (int i = 0; i < 4; ++i) {
        // Unused lanes get an empty ray; they are inactive from the start.
        const DenseRay r = i < count ? rays[i] : DenseRay{};
        for (int a = 0; a < 3; ++a) {
            lane[a][i] = r.next[a];
            lane[3 + a][i] = r.delta[a];
            ilane[1 + a][i] = r.offset[a];
        }
        lane[6][i] = r.aBegin;
        lane[7][i] = r.aEnd;
        ilane[0][i] = r.linear;
        ilane[4][i] = r.steps;
        on[i] = i < count ? -1 : 0;
    }
    l.nx = _mm256_load_pd(lane[0]);
    l.ny = _mm256_load_pd(lane[1]);
    l.nz = _mm256_load_pd(lane[2]);
    l.dx = _mm256_load_pd(lane[3]);
    l.dy = _mm256_load_pd(lane[4]);
    l.dz = _mm256_load_pd(lane[5]);
    l.alpha = _mm256_load_pd(lane[6]);
    l.aEnd = _mm256_load_pd(lane[7]);
    l.linear = _mm256_load_si256(reinterpret_cast<const __m256i*>(ilane[0]));
    l.ox = _mm256_load_si256(reinterpret_cast<const __m256i*>(ilane[1]));
    l.oy = _mm256_load_si256(reinterpret_cast<const __m256i*>(ilane[2]));
    l.oz = _mm256_load_si256(reinterpret_cast<const __m256i*>(ilane[3]));
    l.steps = _mm256_load_si256(reinterpret_cast<const __m256i*>(ilane[4]));
    l.active = _mm256_castsi256_pd(_mm256_load_si256(reinterpret_cast<const __m256i*>(on)));
    l.acc = _mm256_setzero_pd();
    l.absAcc = _mm256_setzero_pd();
    l.value = gather(values, l.linear, last);
}

// One step of every active lane: walkDense's loop body. Returns whether a lane is still active.
template <class T, bool WithAbs>
FM_AVX2 inline bool step(Lanes4& l, const T* values, std::int64_t last) {
    // The smallest next crossing; on ties the later axis (as walkDense and the AVX-512 form).
    const __m256d nextMin = _mm256_min_pd(l.nx, _mm256_min_pd(l.ny, l.nz));
    const __m256d onZ = _mm256_cmp_pd(l.nz, nextMin, _CMP_EQ_OQ);
    const __m256d onY = _mm256_andnot_pd(onZ, _mm256_cmp_pd(l.ny, nextMin, _CMP_EQ_OQ));
    const __m256d aNext = _mm256_min_pd(nextMin, l.aEnd);
    const __m256d segment = _mm256_mul_pd(_mm256_sub_pd(aNext, l.alpha), l.value);
    l.acc = _mm256_blendv_pd(l.acc, _mm256_add_pd(l.acc, segment), l.active);
    if constexpr (WithAbs)
        l.absAcc = _mm256_blendv_pd(
            l.absAcc, _mm256_add_pd(l.absAcc, _mm256_andnot_pd(_mm256_set1_pd(-0.0), segment)), l.active);
    l.alpha = aNext;
    // Done: the next crossing is at or beyond the end, or no step is left.
    const __m256i stepsLeft = _mm256_xor_si256(_mm256_cmpeq_epi64(l.steps, _mm256_setzero_si256()),
                                                _mm256_set1_epi64x(-1));
    l.active = _mm256_and_pd(_mm256_and_pd(l.active, _mm256_cmp_pd(nextMin, l.aEnd, _CMP_LT_OQ)),
                             _mm256_castsi256_pd(stepsLeft));
    const __m256i move = _mm256_castpd_si256(l.active);  // -1 in the lanes that step on
    l.steps = _mm256_add_epi64(l.steps, move);
    // The lanes that step on cross the plane of their next crossing.
    const __m256d sz = _mm256_and_pd(l.active, onZ), sy = _mm256_and_pd(l.active, onY);
    const __m256d sx = _mm256_andnot_pd(_mm256_or_pd(onZ, onY), l.active);
    l.linear = _mm256_add_epi64(l.linear, _mm256_and_si256(_mm256_castpd_si256(sx), l.ox));
    l.linear = _mm256_add_epi64(l.linear, _mm256_and_si256(_mm256_castpd_si256(sy), l.oy));
    l.linear = _mm256_add_epi64(l.linear, _mm256_and_si256(_mm256_castpd_si256(sz), l.oz));
    l.nx = _mm256_blendv_pd(l.nx, _mm256_add_pd(l.nx, l.dx), sx);
    l.ny = _mm256_blendv_pd(l.ny, _mm256_add_pd(l.ny, l.dy), sy);
    l.nz = _mm256_blendv_pd(l.nz, _mm256_add_pd(l.nz, l.dz), sz);
    l.value = gather(values, l.linear, last);
    return _mm256_movemask_pd(l.active) != 0;
}

FM_AVX2 inline void store(const Lanes4& l, int count, WalkSums* sums) {
    alignas(32) double out[4], outAbs[4];
    _mm256_store_pd(out, l.acc);
    _mm256_store_pd(outAbs, l.absAcc);
    for (int i = 0; i < count; ++i) sums[i] = {out[i], outAbs[i]};
}

}  // namespace

template <class T, bool WithAbs>
FM_AVX2 void walkDense16Avx2(const T* values, std::int64_t last, const DenseRay* rays, int count,
                             WalkSums* sums) {
    for (int base = 0; base < count; base += 8) {
        const int n = std::min(8, count - base);
        const int countA = std::min(4, n), countB = n - countA;
        Lanes4 a, b;
        load(a, values, last, rays + base, countA);
        load(b, values, last, rays + base + countA, countB);
        bool liveA = countA > 0, liveB = countB > 0;
        while (liveA && liveB) {
            liveA = step<T, WithAbs>(a, values, last);
            liveB = step<T, WithAbs>(b, values, last);
        }
        while (liveA) liveA = step<T, WithAbs>(a, values, last);
        while (liveB) liveB = step<T, WithAbs>(b, values, last);
        store(a, countA, sums + base);
        store(b, countB, sums + base + countA);
    }
}

#define FM_WALK_DENSE16(T, WITH_ABS) \
    template void walkDense16Avx2<T, WITH_ABS>(const T*, std::int64_t, const DenseRay*, int, WalkSums*);
FM_WALK_DENSE16(float, false)
FM_WALK_DENSE16(float, true)
FM_WALK_DENSE16(std::int16_t, false)
FM_WALK_DENSE16(std::int16_t, true)
#undef FM_WALK_DENSE16

}  // namespace fm::detail
#endif

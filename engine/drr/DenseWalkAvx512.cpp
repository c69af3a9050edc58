// Plain walks in the lanes of AVX-512 vectors (see DenseWalk.h): two groups of eight rays
// stepped in turn, so that one group's compare -> mask -> masked-add chain runs while the
// other's waits. Lane i does what walkDense does for ray i, operation for operation; a lane
// that is done is masked off and a group runs until all its lanes are done (neighbouring
// pixels' rays are about equally long). The step bound and the read clamp are off the chain,
// and each gather starts from a fresh zero vector (no chain from one gather to the next).
#include "drr/DenseWalk.h"

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>

// GCC 12 flags the undefined source vector inside _mm512_min_pd / _mm512_cvtps_pd.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#pragma GCC diagnostic ignored "-Wuninitialized"
// The vector arguments of the inline helpers below never cross a non-AVX-512 call.
#pragma GCC diagnostic ignored "-Wpsabi"

#define FM_AVX512 __attribute__((target("avx512f,avx512dq")))

namespace fm::detail {
namespace {

struct Lanes {
    __m512d nx, ny, nz, dx, dy, dz, alpha, aEnd, acc, value;
    __m512i linear, ox, oy, oz, steps;
    __mmask8 active;
};

// The values at the lanes' indices, each clamped to [0, last]; zero in the lanes not asked for.
FM_AVX512 inline __m512d gather(const float* values, __m512i linear, __m512i lastIndex,
                                __mmask8 lanes) {
    const __m512i at =
        _mm512_min_epi64(_mm512_max_epi64(linear, _mm512_setzero_si512()), lastIndex);
    return _mm512_cvtps_pd(_mm512_mask_i64gather_ps(_mm256_setzero_ps(), lanes, at, values, 4));
}

FM_AVX512 inline void load(Lanes& l, const float* values, __m512i lastIndex,
                           const DenseRay* rays, int count) {
    alignas(64) double lane[8][8];
    alignas(64) std::int64_t ilane[5][8];
    for (int i = 0; i < 8; ++i) {
        // Unused lanes get an empty ray; they are masked off from the start.
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
    }
    l.nx = _mm512_load_pd(lane[0]);
    l.ny = _mm512_load_pd(lane[1]);
    l.nz = _mm512_load_pd(lane[2]);
    l.dx = _mm512_load_pd(lane[3]);
    l.dy = _mm512_load_pd(lane[4]);
    l.dz = _mm512_load_pd(lane[5]);
    l.alpha = _mm512_load_pd(lane[6]);
    l.aEnd = _mm512_load_pd(lane[7]);
    l.linear = _mm512_load_si512(ilane[0]);
    l.ox = _mm512_load_si512(ilane[1]);
    l.oy = _mm512_load_si512(ilane[2]);
    l.oz = _mm512_load_si512(ilane[3]);
    l.steps = _mm512_load_si512(ilane[4]);
    l.active = static_cast<__mmask8>(count >= 8 ? 0xffu : (1u << count) - 1u);
    l.acc = _mm512_setzero_pd();
    l.value = gather(values, l.linear, lastIndex, l.active);
}

// One step of every active lane: walkDense's loop body.
FM_AVX512 inline void step(Lanes& l, const float* values, __m512i lastIndex) {
    // The axis of the smallest next crossing, ties to the later axis (as walkDense).
    const __mmask8 xLessY = _mm512_cmp_pd_mask(l.nx, l.ny, _CMP_LT_OQ);
    const __mmask8 onX = _mm512_mask_cmp_pd_mask(xLessY, l.nx, l.nz, _CMP_LT_OQ);
    const __mmask8 onY =
        _mm512_mask_cmp_pd_mask(static_cast<__mmask8>(~xLessY), l.ny, l.nz, _CMP_LT_OQ);
    const __m512d nextMin = _mm512_min_pd(l.nx, _mm512_min_pd(l.ny, l.nz));
    const __m512d aNext = _mm512_min_pd(nextMin, l.aEnd);
    const __mmask8 grow = _mm512_mask_cmp_pd_mask(l.active, aNext, l.alpha, _CMP_GT_OQ);
    l.acc = _mm512_mask_add_pd(l.acc, grow, l.acc,
                               _mm512_mul_pd(_mm512_sub_pd(aNext, l.alpha), l.value));
    l.alpha = _mm512_mask_mov_pd(l.alpha, grow, aNext);
    // Done: the next crossing is at or beyond the end, or no step is left.
    l.active = _mm512_mask_cmp_pd_mask(l.active, nextMin, l.aEnd, _CMP_LT_OQ) &
               _mm512_test_epi64_mask(l.steps, l.steps);
    l.steps = _mm512_mask_sub_epi64(l.steps, l.active, l.steps, _mm512_set1_epi64(1));
    const __mmask8 sx = l.active & onX, sy = l.active & onY,
                   sz = l.active & static_cast<__mmask8>(~(onX | onY));
    l.linear = _mm512_mask_add_epi64(l.linear, sx, l.linear, l.ox);
    l.linear = _mm512_mask_add_epi64(l.linear, sy, l.linear, l.oy);
    l.linear = _mm512_mask_add_epi64(l.linear, sz, l.linear, l.oz);
    l.nx = _mm512_mask_add_pd(l.nx, sx, l.nx, l.dx);
    l.ny = _mm512_mask_add_pd(l.ny, sy, l.ny, l.dy);
    l.nz = _mm512_mask_add_pd(l.nz, sz, l.nz, l.dz);
    l.value = gather(values, l.linear, lastIndex, l.active);
}

FM_AVX512 inline void store(const Lanes& l, int count, double* sums) {
    alignas(64) double out[8];
    _mm512_store_pd(out, l.acc);
    for (int i = 0; i < count; ++i) sums[i] = out[i];
}

}  // namespace

FM_AVX512 void walkDense16Avx512(const float* values, std::int64_t last, const DenseRay* rays,
                                 int count, double* sums) {
    const __m512i lastIndex = _mm512_set1_epi64(last);
    const int countA = count < 8 ? count : 8, countB = count - countA;
    Lanes a, b;
    load(a, values, lastIndex, rays, countA);
    load(b, values, lastIndex, rays + countA, countB);
    while (a.active && b.active) {
        step(a, values, lastIndex);
        step(b, values, lastIndex);
    }
    while (a.active) step(a, values, lastIndex);
    while (b.active) step(b, values, lastIndex);
    store(a, countA, sums);
    store(b, countB, sums + countA);
}

}  // namespace fm::detail
#endif

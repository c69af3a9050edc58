// The dense walk's ray set-up in AVX-512 lanes (see DenseRaySetup.h). Lane i computes what
// RenderDrr.cpp's makeRay, clipRay and denseRay compute for ray i, operation for operation;
// where the scalar code branches or calls std::min / std::max / std::clamp, the lanes compare
// and blend with the same comparison, so even signed zeros and ties come out the same.
#include "drr/DenseRaySetup.h"

#include <cstdint>
#include <limits>

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>

// GCC 12 flags the undefined source vector inside _mm512_* intrinsics' headers.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#pragma GCC diagnostic ignored "-Wuninitialized"
// The vector arguments of the inline helpers below never cross a non-AVX-512 call.
#pragma GCC diagnostic ignored "-Wpsabi"

#define FM_AVX512 __attribute__((target("avx512f,avx512dq,avx512vl")))

namespace fm {
namespace {

// The scalar helpers' selections: (a < b) ? b : a is std::max(a, b); (b < a) ? b : a is
// std::min(a, b).
FM_AVX512 inline __m512d stdMax(__m512d a, __m512d b) {
    return _mm512_mask_mov_pd(a, _mm512_cmp_pd_mask(a, b, _CMP_LT_OQ), b);
}
FM_AVX512 inline __m512d stdMin(__m512d a, __m512d b) {
    return _mm512_mask_mov_pd(a, _mm512_cmp_pd_mask(b, a, _CMP_LT_OQ), b);
}
FM_AVX512 inline __m512d absPd(__m512d x) {
    return _mm512_castsi512_pd(
        _mm512_and_si512(_mm512_castpd_si512(x), _mm512_set1_epi64(0x7fffffffffffffffLL)));
}

}  // namespace

namespace detail {

FM_AVX512 unsigned setupDenseRays8Avx512(const DrrVolume& v, const glm::dvec3& q0,
                                   const glm::dvec3* q1, int count, const BrickDepthTiles* tiles,
                                   const int* cols, int row, DenseRay* out) {
    alignas(64) double in[3][8];
    for (int i = 0; i < 8; ++i)
        for (int a = 0; a < 3; ++a) in[a][i] = i < count ? q1[i][a] : q0[a] + 1.0;
    const __m512d zero = _mm512_setzero_pd(), one = _mm512_set1_pd(1.0);
    const __m512d boxExtent[3] = {_mm512_set1_pd(double(v.dims.x) * v.spacing.x),
                                  _mm512_set1_pd(double(v.dims.y) * v.spacing.y),
                                  _mm512_set1_pd(double(v.dims.z) * v.spacing.z)};

    // makeRay: d = q1 - q0, parallel where |d| < the limit, invD = 1 / d elsewhere (else 0).
    __m512d q[3], d[3], invD[3];
    __mmask8 parallel[3];
    for (int a = 0; a < 3; ++a) {
        q[a] = _mm512_set1_pd(q0[a]);
        d[a] = _mm512_sub_pd(_mm512_load_pd(in[a]), q[a]);
        parallel[a] = _mm512_cmp_pd_mask(absPd(d[a]), _mm512_set1_pd(kRayParallelLimit),
                                         _CMP_LT_OQ);
        invD[a] = _mm512_mask_div_pd(zero, static_cast<__mmask8>(~parallel[a]), one, d[a]);
    }

    // clipRay against [0, boxExtent): alpha in [0, 1].
    __mmask8 valid = static_cast<__mmask8>(count >= 8 ? 0xff : (1u << count) - 1u);
    __m512d aMin = zero, aMax = one;
    for (int a = 0; a < 3; ++a) {
        // A parallel ray inside the slab keeps its range; one outside it meets nothing.
        const __mmask8 inside = _mm512_cmp_pd_mask(q[a], zero, _CMP_GE_OQ) &
                                _mm512_cmp_pd_mask(q[a], boxExtent[a], _CMP_LT_OQ);
        valid &= static_cast<__mmask8>(~parallel[a] | inside);
        const __mmask8 slab = static_cast<__mmask8>(~parallel[a]);
        __m512d t0 = _mm512_mul_pd(_mm512_sub_pd(zero, q[a]), invD[a]);
        __m512d t1 = _mm512_mul_pd(_mm512_sub_pd(boxExtent[a], q[a]), invD[a]);
        const __mmask8 swap = _mm512_cmp_pd_mask(t0, t1, _CMP_GT_OQ);
        const __m512d lo = _mm512_mask_mov_pd(t0, swap, t1), hi = _mm512_mask_mov_pd(t1, swap, t0);
        t0 = lo;
        t1 = hi;
        aMin = _mm512_mask_mov_pd(aMin, slab, stdMax(aMin, t0));
        aMax = _mm512_mask_mov_pd(aMax, slab, stdMin(aMax, t1));
    }
    valid &= _mm512_cmp_pd_mask(aMax, aMin, _CMP_GT_OQ);

    // The pixel's tile narrows the range (BrickDepthTiles::clip).
    if (tiles && valid) {
        alignas(64) double lo[8], hi[8];
        _mm512_store_pd(lo, aMin);
        _mm512_store_pd(hi, aMax);
        for (int i = 0; i < count; ++i)
            if ((valid >> i) & 1u) {
                if (!tiles->clip(cols[i], row, lo[i], hi[i]))
                    valid &= static_cast<__mmask8>(~(1u << i));
            }
        aMin = _mm512_load_pd(lo);
        aMax = _mm512_load_pd(hi);
    }
    if (!valid) return 0;

    // denseRay: the first voxel, the first crossings (never before aBegin), the increments.
    const __m512d aBegin = aMin, aEnd = stdMax(aBegin, aMax);
    const double dims[3] = {double(v.dims.x), double(v.dims.y), double(v.dims.z)};
    alignas(64) double next[3][8], delta[3][8], aEndOut[8], aBeginOut[8];
    alignas(32) std::int32_t index[3][8];
    for (int a = 0; a < 3; ++a) {
        const __m512d last = _mm512_set1_pd(dims[a] - 1.0);
        __m512d cell = _mm512_roundscale_pd(
            _mm512_mul_pd(_mm512_add_pd(q[a], _mm512_mul_pd(aBegin, d[a])),
                          _mm512_set1_pd(v.invSpacing[a])),
            _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC);
        // std::clamp(cell, 0, last): cell < 0 ? 0 : (last < cell ? last : cell).
        cell = _mm512_mask_mov_pd(cell, _mm512_cmp_pd_mask(last, cell, _CMP_LT_OQ), last);
        cell = _mm512_mask_mov_pd(cell, _mm512_cmp_pd_mask(cell, zero, _CMP_LT_OQ), zero);
        const __m256i idx = _mm512_cvttpd_epi32(cell);
        _mm256_store_si256(reinterpret_cast<__m256i*>(index[a]), idx);
        // exitAlpha: (double(index + (step > 0)) * size - q0) * invD.
        const __mmask8 forward = _mm512_cmp_pd_mask(d[a], zero, _CMP_GT_OQ);
        const __m512d plane = _mm512_cvtepi32_pd(
            _mm256_mask_add_epi32(idx, forward, idx, _mm256_set1_epi32(1)));
        const __m512d size = _mm512_set1_pd(v.spacing[a]);
        const __m512d exit =
            _mm512_mul_pd(_mm512_sub_pd(_mm512_mul_pd(plane, size), q[a]), invD[a]);
        _mm512_store_pd(next[a],
                        _mm512_mask_mov_pd(stdMax(aBegin, exit), parallel[a],
                                           _mm512_set1_pd(std::numeric_limits<double>::infinity())));
        _mm512_store_pd(delta[a], _mm512_mul_pd(size, absPd(invD[a])));
    }
    _mm512_store_pd(aBeginOut, aBegin);
    _mm512_store_pd(aEndOut, aEnd);

    const std::ptrdiff_t stride[3] = {1, v.paddedDims.x,
                                      std::ptrdiff_t(v.paddedDims.x) * v.paddedDims.y};
    alignas(64) double dOut[3][8];
    for (int a = 0; a < 3; ++a) _mm512_store_pd(dOut[a], d[a]);
    for (int i = 0; i < count; ++i) {
        if (!((valid >> i) & 1u)) continue;
        DenseRay& r = out[i];
        r.aBegin = aBeginOut[i];
        r.aEnd = aEndOut[i];
        r.steps = 1;
        for (int a = 0; a < 3; ++a) {
            const bool isParallel = (parallel[a] >> i) & 1u;
            const int step = isParallel ? 0 : (dOut[a][i] > 0.0 ? 1 : -1);
            r.next[a] = next[a][i];
            r.delta[a] = delta[a][i];
            r.offset[a] = step * stride[a];
            r.steps += step > 0 ? v.dims[a] - 1 - index[a][i] : (step < 0 ? index[a][i] : 0);
        }
        r.linear = v.at(index[0][i], index[1][i], index[2][i]);
    }
    return valid;
}

}  // namespace detail
}  // namespace fm

#else

namespace fm::detail {
unsigned setupDenseRays8Avx512(const DrrVolume&, const glm::dvec3&, const glm::dvec3*, int,
                         const BrickDepthTiles*, const int*, int, DenseRay*) {
    return 0;  // never called: denseWalkSimd() is never Avx512 here
}
}  // namespace fm::detail

#endif

// The dense walk's ray set-up in AVX2 lanes (see DenseRaySetup.h): DenseRaySetupAvx512.cpp's
// arithmetic four rays at a time, with all-ones lanes and blends where that form has mask
// registers. Lane i computes what RenderDrr.cpp's makeRay, clipRay and denseRay compute for ray
// i, operation for operation, so even signed zeros and ties come out the same.
#include "drr/DenseRaySetup.h"

#include <cstdint>
#include <limits>

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>

// The vector arguments of the inline helpers below never cross a non-AVX2 call.
#pragma GCC diagnostic ignored "-Wpsabi"

#define FM_AVX2 __attribute__((target("avx2")))

namespace fm::detail {
namespace {

// The scalar helpers' selections: (a < b) ? b : a is std::max(a, b); (b < a) ? b : a is
// std::min(a, b).
FM_AVX2 inline __m256d stdMax(__m256d a, __m256d b) {
    return _mm256_blendv_pd(a, b, _mm256_cmp_pd(a, b, _CMP_LT_OQ));
}
FM_AVX2 inline __m256d stdMin(__m256d a, __m256d b) {
    return _mm256_blendv_pd(a, b, _mm256_cmp_pd(b, a, _CMP_LT_OQ));
}
FM_AVX2 inline __m256d absPd(__m256d x) { return _mm256_andnot_pd(_mm256_set1_pd(-0.0), x); }

// Rays first .. first + count (count 1..4) of the eight; returns their bits of the hit mask.
FM_AVX2 unsigned setUpFour(const DrrVolume& v, const glm::dvec3& q0, const glm::dvec3* q1,
                           int count, const BrickDepthTiles* tiles, const int* cols, int row,
                           DenseRay* out) {
    alignas(32) double in[3][4];
    for (int i = 0; i < 4; ++i)
        for (int a = 0; a < 3; ++a) in[a][i] = i < count ? q1[i][a] : q0[a] + 1.0;
    const __m256d zero = _mm256_setzero_pd(), one = _mm256_set1_pd(1.0);
    const __m256d boxExtent[3] = {_mm256_set1_pd(double(v.dims.x) * v.spacing.x),
                                  _mm256_set1_pd(double(v.dims.y) * v.spacing.y),
                                  _mm256_set1_pd(double(v.dims.z) * v.spacing.z)};

    // makeRay: d = q1 - q0, parallel where |d| < the limit, invD = 1 / d elsewhere (else 0).
    __m256d q[3], d[3], invD[3], parallel[3];
    for (int a = 0; a < 3; ++a) {
        q[a] = _mm256_set1_pd(q0[a]);
        d[a] = _mm256_sub_pd(_mm256_load_pd(in[a]), q[a]);
        parallel[a] = _mm256_cmp_pd(absPd(d[a]), _mm256_set1_pd(kRayParallelLimit), _CMP_LT_OQ);
        invD[a] = _mm256_blendv_pd(_mm256_div_pd(one, d[a]), zero, parallel[a]);
    }

    // clipRay against [0, boxExtent): alpha in [0, 1].
    __m256d valid = _mm256_castsi256_pd(_mm256_cmpgt_epi64(_mm256_set1_epi64x(count), _mm256_setr_epi64x(0, 1, 2, 3)));
    __m256d aMin = zero, aMax = one;
    for (int a = 0; a < 3; ++a) {
        // A parallel ray inside the slab keeps its range; one outside it meets nothing.
        const __m256d inside = _mm256_and_pd(_mm256_cmp_pd(q[a], zero, _CMP_GE_OQ),
                                             _mm256_cmp_pd(q[a], boxExtent[a], _CMP_LT_OQ));
        valid = _mm256_and_pd(valid, _mm256_or_pd(_mm256_andnot_pd(parallel[a], _mm256_castsi256_pd(
                                                                   _mm256_set1_epi64x(-1))),
                                                  inside));
        const __m256d t0 = _mm256_mul_pd(_mm256_sub_pd(zero, q[a]), invD[a]);
        const __m256d t1 = _mm256_mul_pd(_mm256_sub_pd(boxExtent[a], q[a]), invD[a]);
        const __m256d swap = _mm256_cmp_pd(t0, t1, _CMP_GT_OQ);
        const __m256d lo = _mm256_blendv_pd(t0, t1, swap), hi = _mm256_blendv_pd(t1, t0, swap);
        aMin = _mm256_blendv_pd(stdMax(aMin, lo), aMin, parallel[a]);
        aMax = _mm256_blendv_pd(stdMin(aMax, hi), aMax, parallel[a]);
    }
    unsigned hit = unsigned(_mm256_movemask_pd(_mm256_and_pd(valid, _mm256_cmp_pd(aMax, aMin, _CMP_GT_OQ))));

    // The pixel's tile narrows the range (BrickDepthTiles::clip).
    if (tiles && hit) {
        alignas(32) double lo[4], hi[4];
        _mm256_store_pd(lo, aMin);
        _mm256_store_pd(hi, aMax);
        for (int i = 0; i < count; ++i)
            if (((hit >> i) & 1u) && !tiles->clip(cols[i], row, lo[i], hi[i])) hit &= ~(1u << i);
        aMin = _mm256_load_pd(lo);
        aMax = _mm256_load_pd(hi);
    }
    if (!hit) return 0;

    // denseRay: the first voxel, the first crossings (never before aBegin), the increments.
    const __m256d aBegin = aMin, aEnd = stdMax(aBegin, aMax);
    const double dims[3] = {double(v.dims.x), double(v.dims.y), double(v.dims.z)};
    alignas(32) double next[3][4], delta[3][4], aEndOut[4], aBeginOut[4], dOut[3][4], cellOut[3][4];
    for (int a = 0; a < 3; ++a) {
        const __m256d last = _mm256_set1_pd(dims[a] - 1.0);
        __m256d cell = _mm256_round_pd(
            _mm256_mul_pd(_mm256_add_pd(q[a], _mm256_mul_pd(aBegin, d[a])), _mm256_set1_pd(v.invSpacing[a])),
            _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC);
        // std::clamp(cell, 0, last): cell < 0 ? 0 : (last < cell ? last : cell).
        cell = _mm256_blendv_pd(cell, last, _mm256_cmp_pd(last, cell, _CMP_LT_OQ));
        cell = _mm256_blendv_pd(cell, zero, _mm256_cmp_pd(cell, zero, _CMP_LT_OQ));
        _mm256_store_pd(cellOut[a], cell);
        // exitAlpha: (double(index + (step > 0)) * size - q0) * invD; the cell is a whole
        // number below 2^31, so cell + 1 is exactly the int's double.
        const __m256d forward = _mm256_cmp_pd(d[a], zero, _CMP_GT_OQ);
        const __m256d plane = _mm256_add_pd(cell, _mm256_and_pd(forward, one));
        const __m256d size = _mm256_set1_pd(v.spacing[a]);
        const __m256d exit = _mm256_mul_pd(_mm256_sub_pd(_mm256_mul_pd(plane, size), q[a]), invD[a]);
        _mm256_store_pd(next[a], _mm256_blendv_pd(stdMax(aBegin, exit),
                                                  _mm256_set1_pd(std::numeric_limits<double>::infinity()),
                                                  parallel[a]));
        _mm256_store_pd(delta[a], _mm256_mul_pd(size, absPd(invD[a])));
        _mm256_store_pd(dOut[a], d[a]);
    }
    _mm256_store_pd(aBeginOut, aBegin);
    _mm256_store_pd(aEndOut, aEnd);

    const std::ptrdiff_t stride[3] = {1, v.paddedDims.x, std::ptrdiff_t(v.paddedDims.x) * v.paddedDims.y};
    const int parallelBits[3] = {_mm256_movemask_pd(parallel[0]), _mm256_movemask_pd(parallel[1]),
                                 _mm256_movemask_pd(parallel[2])};
    for (int i = 0; i < count; ++i) {
        if (!((hit >> i) & 1u)) continue;
        DenseRay& r = out[i];
        r.aBegin = aBeginOut[i];
        r.aEnd = aEndOut[i];
        r.steps = 1;
        int index[3];
        for (int a = 0; a < 3; ++a) {
            index[a] = static_cast<int>(cellOut[a][i]);
            const bool isParallel = (parallelBits[a] >> i) & 1;
            const int step = isParallel ? 0 : (dOut[a][i] > 0.0 ? 1 : -1);
            r.next[a] = next[a][i];
            r.delta[a] = delta[a][i];
            r.offset[a] = step * stride[a];
            r.steps += step > 0 ? v.dims[a] - 1 - index[a] : (step < 0 ? index[a] : 0);
        }
        r.linear = v.at(index[0], index[1], index[2]);
    }
    return hit;
}

}  // namespace

FM_AVX2 unsigned setupDenseRays8Avx2(const DrrVolume& v, const glm::dvec3& q0, const glm::dvec3* q1,
                                     int count, const BrickDepthTiles* tiles, const int* cols, int row,
                                     DenseRay* out) {
    const int countA = count < 4 ? count : 4, countB = count - countA;
    unsigned hit = setUpFour(v, q0, q1, countA, tiles, cols, row, out);
    if (countB > 0) hit |= setUpFour(v, q0, q1 + 4, countB, tiles, cols + 4, row, out + 4) << 4;
    return hit;
}

}  // namespace fm::detail

#else

namespace fm::detail {
unsigned setupDenseRays8Avx2(const DrrVolume&, const glm::dvec3&, const glm::dvec3*, int,
                             const BrickDepthTiles*, const int*, int, DenseRay*) {
    return 0;  // never called: denseWalkSimd() is never Avx2 here
}
}  // namespace fm::detail

#endif

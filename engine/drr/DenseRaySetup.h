#pragma once
// Setting up the dense walk's rays eight at a time, in vector lanes (DenseRaySetupAvx512.cpp,
// DenseRaySetupAvx2.cpp).
//
// Why: once the walk itself ran without the gather instruction (DenseWalk.h), the scalar set-up
// of each ray (1/d, slab clipping, the first voxel by floor, the first crossings) was a quarter
// of a 256^2 render of a real CT. The lanes do exactly the scalar set-up's arithmetic (same
// operations and order, compares and blends where it branches, no fused multiply-add), so a
// ray set up here is the ray RenderDrr.cpp's makeRay -> clipRay -> denseRay would give, bit for
// bit (checked by the DrrDenseWalk tests, which compare every pixel with the scalar walk).
#include <glm/vec3.hpp>

#include "drr/BrickDepthTiles.h"
#include "drr/DenseWalk.h"
#include "drr/DrrVolume.h"

namespace fm {

// A ray whose direction component moves less than this (mm over the whole source-to-pixel
// segment) along an axis is treated as exactly parallel to it: the neglected displacement is
// ~1e-200 mm, and it keeps 1/d finite so that no 0 * inf = NaN can appear.
inline constexpr double kRayParallelLimit = 1e-200;

namespace detail {
unsigned setupDenseRays8Avx512(const DrrVolume& v, const glm::dvec3& q0, const glm::dvec3* q1,
                               int count, const BrickDepthTiles* tiles, const int* cols, int row,
                               DenseRay* out);
unsigned setupDenseRays8Avx2(const DrrVolume& v, const glm::dvec3& q0, const glm::dvec3* q1,
                             int count, const BrickDepthTiles* tiles, const int* cols, int row,
                             DenseRay* out);
}  // namespace detail

// Rays from the source q0 to the pixel centres q1[0..count) (count <= 8), all in the volume's
// local frame (mm, box [0, dims * spacing)). Each ray is clipped to the box, then to its pixel's
// tile of `tiles` (if given; pixel (cols[i], row)), and set up for walkDense. Returns a bit mask
// of the rays that meet something; out[i] is set for those only. In the lanes of the walk's
// form (denseWalkSimd(): AVX-512 eight at a time, AVX2 four); call only when
// denseWalkSimdAvailable().
inline unsigned setupDenseRays8(const DrrVolume& v, const glm::dvec3& q0, const glm::dvec3* q1,
                                int count, const BrickDepthTiles* tiles, const int* cols, int row,
                                DenseRay* out) {
    return denseWalkSimd() == DenseWalkSimd::Avx512
               ? detail::setupDenseRays8Avx512(v, q0, q1, count, tiles, cols, row, out)
               : detail::setupDenseRays8Avx2(v, q0, q1, count, tiles, cols, row, out);
}

}  // namespace fm

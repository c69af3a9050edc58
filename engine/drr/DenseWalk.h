#pragma once
// The plain Siddon/Jacobs voxel walk (no bricks) in forms that give bit-identical sums: one ray
// at a time (scalar), and sixteen rays at once in vector lanes where the CPU has them (AVX-512,
// else AVX2).
//
// Why a vector form: on real CTs almost every voxel is non-zero (air noise above -1000 HU),
// so empty-space skipping passes over little and the cost is the walk itself. One ray's walk
// is a chain of dependent steps (the axis chosen by a compare decides the next crossing), so a
// scalar core waits on latencies and mispredicted 3-way branches; sixteen independent rays in
// the lanes of two vectors fill that time. Each lane does exactly the scalar step's arithmetic
// (same operations, same order, no fused multiply-add: this file's sources are compiled with
// -ffp-contract=off), so a pixel never depends on which form traced it.
#include <cstddef>
#include <cstdint>

namespace fm {

// A ray ready to walk: the alpha range inside the kept box and, per axis, the alpha of the
// next plane crossing, its increment and the step of the linear index into the padded values.
// The walk ends when the next crossing is at or beyond aEnd. `steps` bounds it as well: the
// crossings the ray has inside the box, plus one. Rounding near the exit face may take a ray
// one voxel out, into the zero padding (adding exactly nothing); the bound and a clamp of
// every read to [0, last] keep even absurd input from running on or reading outside.
struct DenseRay {
    double aBegin = 0.0, aEnd = 0.0;
    double next[3] = {0.0, 0.0, 0.0};  // +inf for an axis the ray is parallel to
    double delta[3] = {0.0, 0.0, 0.0};
    std::int64_t linear = 0;  // index of the first voxel in the padded values
    std::int64_t offset[3] = {0, 0, 0};
    std::int64_t steps = 0;
};

// What a walk adds up per ray: sum = sum over its voxel segments of (alpha length) * value;
// absSum (only when asked for) = the same of |value|, from the same segments in the same walk:
// the positive and the negative values' integrals are then (absSum +- sum) / 2
// (renderDrrBySign).
struct WalkSums {
    double sum = 0.0, absSum = 0.0;
};

// The sums of one ray, for the stored values of either type (DrrVolume: float or int16;
// instantiated for both). `last` is the index of the last padded value. absSum stays 0 unless
// WithAbs.
template <class T, bool WithAbs = false>
WalkSums walkDense(const T* values, std::int64_t last, const DenseRay& ray);

// The same for `count` (1..16) rays at once; sums[i] is bit-identical to walkDense(rays[i]).
// In the lanes of denseWalkSimd()'s form, else one ray at a time.
template <class T, bool WithAbs = false>
void walkDense16(const T* values, std::int64_t last, const DenseRay* rays, int count,
                 WalkSums* sums);

// The vector forms of the walk, by instruction set.
enum class DenseWalkSimd { None, Avx2, Avx512 };

// The form walkDense16 uses: the widest this CPU (and OS) runs, unless a test chose a narrower
// one (ScopedDenseWalkSimd).
DenseWalkSimd denseWalkSimd();
// True when walkDense16 runs in vector lanes (renderDrr's automatic choice walks densely only
// then: the scalar plain walk is slower than skipping bricks).
inline bool denseWalkSimdAvailable() { return denseWalkSimd() != DenseWalkSimd::None; }
// The widest form this CPU runs.
DenseWalkSimd denseWalkSimdSupported();

// For tests: walkDense16 (and so renderDrr) uses `form` while this lives, so that every form
// this CPU runs is checked against the scalar walk on it. Not for concurrent use with renders.
class ScopedDenseWalkSimd {
public:
    explicit ScopedDenseWalkSimd(DenseWalkSimd form);
    ~ScopedDenseWalkSimd();
    ScopedDenseWalkSimd(const ScopedDenseWalkSimd&) = delete;
    ScopedDenseWalkSimd& operator=(const ScopedDenseWalkSimd&) = delete;

private:
    DenseWalkSimd previous_;
};

// From this many bytes of stored values up, the AVX-512 form prefetches every lane's voxels
// some steps ahead (DenseWalkAvx512.cpp). Measured on crops of the GE head (docs/drr.md,
// "Prefetching on large volumes"): 2-3x faster from 80 MB up, ~1.3x at 20 MB, but up to 40 %
// slower at 5-12 MB (the aorta crop, the DICOM series), whose voxels stay in the caches after
// the first rays.
inline constexpr std::uint64_t kDenseWalkPrefetchFromBytes = std::uint64_t{16} << 20;
inline bool denseWalkPrefetches(std::uint64_t valueBytes) {
    return valueBytes >= kDenseWalkPrefetchFromBytes;
}

}  // namespace fm

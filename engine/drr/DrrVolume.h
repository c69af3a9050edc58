#pragma once
// The prepared volume behind the opaque DrrVolumePtr (engine/drr only).
//
// Rays are traced in the "local" frame: millimetres along the volume's own i, j, k axes, with
// the kept (cropped) box spanning [0, dims * spacing]: voxel (i, j, k) of `values` covers
// [i*s.x, (i+1)*s.x) x ... (half-open, so a ray lying exactly on an inner face belongs to
// the higher voxel). local = worldToLocal * (world - origin) + localShift.
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/type_precision.hpp>

#include "core/LargeAllocation.h"
#include "drr/Drr.h"

namespace fm {

struct DrrVolume {
    DrrValueOptions options;
    glm::ivec3 dims{0};       // kept voxels
    glm::ivec3 cropBegin{0};  // first kept voxel in the (downsampled) source grid
    glm::dvec3 spacing{1.0};
    glm::dvec3 invSpacing{1.0};  // 1 / spacing
    // World -> local: the inverse of the direction matrix (the exact inverse rather than the
    // transpose, because files store cosines with 6-8 digits), then the crop shift.
    glm::dmat3 worldToLocal{1.0};
    glm::dvec3 origin{0.0};      // world position of source-grid voxel (0,0,0)'s centre
    glm::dvec3 localShift{0.0};  // spacing * (0.5 - cropBegin)
    glm::dmat3 direction{1.0};   // to map the kept box back to the world (projected box)
    // Converted (mu or raw), thresholded values of the kept voxels, i fastest, stored with one
    // layer of zeros on every side (padded dims = dims + 2): the traversal may then read a
    // neighbour of a border voxel without a bounds check (with zero weight). Use at().
    // One copy, in the smallest type that holds them exactly (DrrValueOptions::compactVoxels):
    // int16 when every value per mm is valueScale times an integer of int16's range (CTs in
    // whole HU: mu = (mu_water / 1000) (HU + 1000)), else float with valueScale 1. A ray sums
    // stored values times lengths and multiplies by valueScale once, at the end. Large arrays
    // live in huge pages of their own (allocateMapped): rays read them in scattered order.
    DrrVoxelType voxelType = DrrVoxelType::Float32;
    std::vector<float, MappedAllocator<float>> values;                // Float32
    std::vector<std::int16_t, MappedAllocator<std::int16_t>> values16;  // Int16
    double valueScale = 1.0;
    glm::ivec3 paddedDims{2};
    bool empty = true;

    // Empty-space skipping: bricks of brickSize^3 voxels (the last ones along an axis may be
    // partial). A brick is "uniform" when all its voxels hold the same value (0 = empty):
    // the ray then needs one multiplication for the whole brick instead of a voxel walk.
    int brickSize = 8;
    int brickShift = 3;  // log2(brickSize) if a power of two (fast division), else -1
    glm::ivec3 brickDims{0};
    std::vector<float> brickValue;  // the common stored value of a uniform brick (exact for int16)
    std::vector<std::uint8_t> brickMixed;  // 1 = voxels differ: walk the voxels
    // Few bricks to skip (real CTs: air noise above -1000 HU): walking every voxel 16 rays at
    // a time beats skipping one ray at a time (DenseWalk.h; measured in docs/drr.md).
    bool preferDenseWalk = false;
    std::size_t bricksEmpty = 0;  // uniform bricks of value 0 (BrickDepthTiles skips them)
    // What BrickDepthTiles projects, when some bricks are empty: the bricks that hold a non-zero
    // value, (i, j, k) in bricks; and, where they are at most kMaxHalfBricks, the half-bricks
    // (blocks of brickSize / 2, in half-brick units) that do. A tile's depth range then holds
    // less empty space, but the tiles project every block's corners per render: renders with
    // enough rays per half-brick use them (BrickDepthTiles.h; docs/drr.md, "Half-bricks for the tiles").
    std::vector<glm::u16vec3> occupiedBricks;
    std::vector<glm::u16vec3> occupiedHalfBricks;

    std::ptrdiff_t at(int i, int j, int k) const {
        return (i + 1) +
               std::ptrdiff_t(paddedDims.x) * ((j + 1) + std::ptrdiff_t(paddedDims.y) * (k + 1));
    }
    glm::dvec3 worldToLocalPoint(const glm::dvec3& world) const {
        return worldToLocal * (world - origin) + localShift;
    }
    std::size_t valueCount() const {
        return voxelType == DrrVoxelType::Int16 ? values16.size() : values.size();
    }
    // The stored value at a padded index, as a double (times valueScale: per mm).
    double storedAt(std::ptrdiff_t n) const {
        return voxelType == DrrVoxelType::Int16 ? double(values16[n]) : double(values[n]);
    }
    // Calls f(const T* values) with the array in use (T = float or std::int16_t): the walks are
    // compiled once per type.
    template <class F>
    decltype(auto) withValues(F&& f) const {
        return voxelType == DrrVoxelType::Int16 ? f(values16.data()) : f(values.data());
    }
};

// Bricks at least this fraction of which are mixed make renderDrr walk densely (Auto).
inline constexpr double kDenseWalkMixedFraction = 0.2;
// Half-bricks are kept for the tiles when there are at most this many of them (DrrVolume).
inline constexpr std::size_t kMaxHalfBricks = 32768;

// Fills brickDims, brickValue, brickMixed and preferDenseWalk from `values` (per brick slab in parallel; the
// same for any thread count).
void buildDrrBricks(DrrVolume& v, int threads);

}  // namespace fm

// Preparation of a volume for DRRs: value conversion, threshold, optional downsampling,
// cropping to the non-zero content and the brick map for empty-space skipping.
//
// Passes over the source and no volume-sized scratch array: (1) the check for infinite values
// and whether int16 holds every converted value exactly; (2) the bounding box of the non-zero
// values; (3) per slab of bricks in parallel, the kept box converted into the padded array (of
// int16 or float) and that slab's bricks classified while its values are fresh. (Before: a
// converted full-size copy, then a cropped copy of it, then the bricks: three passes and two
// extra volume-sized arrays.)
#include <algorithm>
#include <cmath>
#include <sstream>
#include <type_traits>

#include "core/Error.h"
#include "core/Parallel.h"
#include "drr/DenseWalk.h"
#include "drr/Drr.h"
#include "drr/DrrVolume.h"

namespace fm {

double huToMu(double hu) {
    return std::max(0.0, kMuWaterPerMm * (1.0 + hu / 1000.0));
}

double drrVoxelValue(double stored, const DrrValueOptions& options) {
    if (std::isnan(stored)) return 0.0;  // "no data" (float NIfTIs use NaN outside the scan)
    if (options.thresholdHU && stored < *options.thresholdHU) return 0.0;
    return options.values == DrrValues::Mu ? huToMu(stored) : stored;
}

namespace {

// The int16 form of a stored value: value per mm = kInt16Scale(options) * this. NaN and voxels
// below the threshold give 0, as in drrVoxelValue; mu = (mu_water / 1000) (HU + 1000), which is
// huToMu without its rounding, for HU >= -1000.
double int16Form(double stored, const DrrValueOptions& options) {
    if (std::isnan(stored)) return 0.0;
    if (options.thresholdHU && stored < *options.thresholdHU) return 0.0;
    return options.values == DrrValues::Mu ? std::max(0.0, stored + 1000.0) : stored;
}
double int16Scale(const DrrValueOptions& options) {
    return options.values == DrrValues::Mu ? kMuWaterPerMm / 1000.0 : 1.0;
}
bool fitsInt16(double q) {
    return q == std::trunc(q) && q >= -32768.0 && q <= 32767.0;
}

// The grid the DRR volume is cut from: the source volume's values converted on the fly (to
// float, or to their int16 form), or (downsampling) a converted block-mean grid.
struct SourceGrid {
    glm::ivec3 dims{0};
    glm::dvec3 spacing{1.0};
    glm::dvec3 origin{0.0};  // world position of voxel (0,0,0)'s centre
    const Volume* volume = nullptr;  // converted on the fly when `coarse` is empty
    const DrrValueOptions* options = nullptr;
    bool int16 = false;  // at() gives the int16 form (exact in a double)
    std::vector<float> coarse;

    double at(std::size_t n) const {
        if (!coarse.empty()) return coarse[n];
        return int16 ? int16Form(volume->values[n], *options)
                     : static_cast<float>(drrVoxelValue(volume->values[n], *options));
    }
    std::size_t index(int i, int j, int k) const {
        return static_cast<std::size_t>(i) +
               static_cast<std::size_t>(dims.x) *
                   (static_cast<std::size_t>(j) + static_cast<std::size_t>(dims.y) * k);
    }
};

// Refuses infinite voxels, naming the first in memory order, and tells whether every voxel's
// int16 form is exact (per slice in parallel; the result does not depend on the thread count).
bool checkFiniteAndFitsInt16(const Volume& volume, const DrrValueOptions& options, int threads) {
    const std::size_t sliceSize = static_cast<std::size_t>(volume.dims.x) * volume.dims.y;
    constexpr std::size_t kNone = static_cast<std::size_t>(-1);
    std::vector<std::size_t> firstInfinite(volume.dims.z, kNone);
    std::vector<std::uint8_t> sliceFits(volume.dims.z, 1);
    parallelFor(
        volume.dims.z, threads,
        [&](int k0, int k1) {
            for (int k = k0; k < k1; ++k) {
                bool fits = options.compactVoxels && options.downsample == 1;
                for (std::size_t n = k * sliceSize; n < (k + 1) * sliceSize; ++n) {
                    if (std::isinf(volume.values[n])) {
                        firstInfinite[k] = n;
                        break;
                    }
                    if (fits) fits = fitsInt16(int16Form(volume.values[n], options));
                }
                sliceFits[k] = fits;
            }
        },
        4);
    for (std::size_t n : firstInfinite) {
        if (n == kNone) continue;
        std::ostringstream msg;
        msg << "volume '" << volume.meta.source << "' holds an infinite value at voxel " << n
            << ": cannot compute a DRR";
        throw Error(msg.str());
    }
    return std::all_of(sliceFits.begin(), sliceFits.end(), [](std::uint8_t f) { return f != 0; });
}

SourceGrid sourceGrid(const Volume& volume, const DrrValueOptions& options, bool int16,
                      int threads) {
    SourceGrid g;
    g.volume = &volume;
    g.options = &options;
    g.int16 = int16;
    const int f = options.downsample;
    if (f == 1) {
        g.dims = volume.dims;
        g.spacing = volume.spacing;
        g.origin = volume.origin;
        return g;
    }
    g.dims = (volume.dims + (f - 1)) / f;
    g.spacing = volume.spacing * double(f);
    // Coarse voxel I covers fine voxels [I f, I f + f): its centre is at fine index I f + (f-1)/2.
    g.origin = volume.indexToWorld(glm::dvec3((f - 1) * 0.5));
    std::vector<float> coarse(static_cast<std::size_t>(g.dims.x) * g.dims.y * g.dims.z);
    parallelFor(
        g.dims.z, threads,
        [&](int K0, int K1) {
            for (int K = K0; K < K1; ++K)
                for (int J = 0; J < g.dims.y; ++J)
                    for (int I = 0; I < g.dims.x; ++I) {
                        double sum = 0.0;
                        int count = 0;
                        for (int k = K * f; k < std::min(K * f + f, volume.dims.z); ++k)
                            for (int j = J * f; j < std::min(J * f + f, volume.dims.y); ++j)
                                for (int i = I * f; i < std::min(I * f + f, volume.dims.x); ++i) {
                                    sum += static_cast<float>(
                                        drrVoxelValue(volume.values[volume.index(i, j, k)], options));
                                    ++count;
                                }
                        coarse[g.index(I, J, K)] = static_cast<float>(sum / count);
                    }
        },
        4);
    g.coarse = std::move(coarse);
    return g;
}

// Bounding box [lo, hi] of the non-zero values; hi.x < 0 when there are none. Per slice in
// parallel (min and max combine in any order), each row scanned from both ends.
void nonZeroBox(const SourceGrid& grid, int threads, glm::ivec3& lo, glm::ivec3& hi) {
    const glm::ivec3 dims = grid.dims;
    std::vector<glm::ivec3> sliceLo(dims.z, dims), sliceHi(dims.z, glm::ivec3(-1));
    parallelFor(
        dims.z, threads,
        [&](int k0, int k1) {
            for (int k = k0; k < k1; ++k)
                for (int j = 0; j < dims.y; ++j) {
                    const std::size_t row = grid.index(0, j, k);
                    int first = 0;
                    while (first < dims.x && grid.at(row + first) == 0.0) ++first;
                    if (first == dims.x) continue;
                    int last = dims.x - 1;
                    while (grid.at(row + last) == 0.0) --last;
                    sliceLo[k] = glm::min(sliceLo[k], glm::ivec3(first, j, k));
                    sliceHi[k] = glm::max(sliceHi[k], glm::ivec3(last, j, k));
                }
        },
        4);
    lo = dims;
    hi = glm::ivec3(-1);
    for (int k = 0; k < dims.z; ++k) {
        lo = glm::min(lo, sliceLo[k]);
        hi = glm::max(hi, sliceHi[k]);
    }
}

// Classifies the bricks of slab bk (brick index bk along k) from the stored values.
template <class T>
void classifyBrickSlab(DrrVolume& v, const T* values, int bk) {
    const int b = v.brickSize;
    for (int bj = 0; bj < v.brickDims.y; ++bj)
        for (int bi = 0; bi < v.brickDims.x; ++bi) {
            const std::size_t brick =
                bi + static_cast<std::size_t>(v.brickDims.x) *
                         (bj + static_cast<std::size_t>(v.brickDims.y) * bk);
            const T first = values[v.at(bi * b, bj * b, bk * b)];
            bool mixed = false;
            for (int k = bk * b; k < std::min(bk * b + b, v.dims.z) && !mixed; ++k)
                for (int j = bj * b; j < std::min(bj * b + b, v.dims.y) && !mixed; ++j)
                    for (int i = bi * b; i < std::min(bi * b + b, v.dims.x); ++i)
                        if (values[v.at(i, j, k)] != first) {
                            mixed = true;
                            break;
                        }
            v.brickMixed[brick] = mixed ? 1 : 0;
            v.brickValue[brick] = mixed ? 0.0f : static_cast<float>(first);
        }
}

void allocateBricks(DrrVolume& v) {
    const int b = v.brickSize;
    v.brickDims = (v.dims + (b - 1)) / b;
    const std::size_t count =
        static_cast<std::size_t>(v.brickDims.x) * v.brickDims.y * v.brickDims.z;
    v.brickValue.assign(count, 0.0f);
    v.brickMixed.assign(count, 0);
}

void decideWalk(DrrVolume& v) {
    const auto mixed =
        static_cast<std::size_t>(std::count(v.brickMixed.begin(), v.brickMixed.end(), 1));
    v.preferDenseWalk = double(mixed) >= kDenseWalkMixedFraction * double(v.brickMixed.size());
    v.bricksEmpty = 0;
    for (std::size_t b = 0; b < v.brickMixed.size(); ++b)
        v.bricksEmpty += !v.brickMixed[b] && v.brickValue[b] == 0.0f;
    v.occupiedBricks.clear();
    v.occupiedHalfBricks.clear();
    if (v.bricksEmpty == 0) return;
    for (int k = 0; k < v.brickDims.z; ++k)
        for (int j = 0; j < v.brickDims.y; ++j)
            for (int i = 0; i < v.brickDims.x; ++i) {
                const std::size_t b = i + static_cast<std::size_t>(v.brickDims.x) *
                                              (j + static_cast<std::size_t>(v.brickDims.y) * k);
                if (v.brickMixed[b] || v.brickValue[b] != 0.0f) v.occupiedBricks.emplace_back(i, j, k);
            }
    // Few enough: the half-bricks, each of an occupied brick's eight that holds a non-zero value
    // (a uniform non-zero brick's all do).
    if (v.brickSize < 2 || v.brickSize % 2 != 0 || v.occupiedBricks.size() * 8 > kMaxHalfBricks) return;
    const int h = v.brickSize / 2;
    std::vector<glm::u16vec3> fine;
    v.withValues([&](const auto* values) {
        for (const glm::u16vec3& brick : v.occupiedBricks) {
            const std::size_t b = brick.x + static_cast<std::size_t>(v.brickDims.x) *
                                                (brick.y + static_cast<std::size_t>(v.brickDims.y) * brick.z);
            for (int c = 0; c < 8; ++c) {
                const glm::ivec3 block(2 * brick.x + (c & 1), 2 * brick.y + ((c >> 1) & 1), 2 * brick.z + (c >> 2));
                const glm::ivec3 lo = block * h, hi = glm::min(lo + h, v.dims);
                if (lo.x >= v.dims.x || lo.y >= v.dims.y || lo.z >= v.dims.z) continue;
                bool occupied = !v.brickMixed[b];  // uniform and not empty
                for (int k = lo.z; k < hi.z && !occupied; ++k)
                    for (int j = lo.y; j < hi.y && !occupied; ++j)
                        for (int i = lo.x; i < hi.x; ++i)
                            if (values[v.at(i, j, k)] != 0) {
                                occupied = true;
                                break;
                            }
                if (occupied) fine.emplace_back(block);
            }
        }
    });
    v.occupiedHalfBricks = std::move(fine);
}

}  // namespace

void buildDrrBricks(DrrVolume& v, int threads) {
    allocateBricks(v);
    parallelFor(
        v.brickDims.z, threads,
        [&](int bk0, int bk1) {
            for (int bk = bk0; bk < bk1; ++bk)
                v.withValues([&](const auto* values) { classifyBrickSlab(v, values, bk); });
        },
        4);
    decideWalk(v);
}

DrrVolumePtr prepareDrrVolume(const Volume& volume, const DrrValueOptions& options) {
    const std::string what = "volume '" + volume.meta.source + "'";
    volume.validate(what);
    if (volume.values.size() != volume.voxelCount()) throw Error(what + ": has no voxel values");
    if (options.brickSize < 1 || options.brickSize > 256)
        throw Error("DRR brick size must be 1..256 voxels, got " +
                    std::to_string(options.brickSize));
    if (options.downsample < 1 || options.downsample > 16)
        throw Error("DRR downsample factor must be 1..16, got " +
                    std::to_string(options.downsample));
    if (options.threads < 0) throw Error("DRR preparation thread count must not be negative");
    if (options.thresholdHU && !std::isfinite(*options.thresholdHU))
        throw Error("DRR threshold must be a finite number");

    auto v = std::make_shared<DrrVolume>();
    v->options = options;
    v->brickSize = options.brickSize;
    v->brickShift = -1;
    for (int shift = 0; shift < 9; ++shift)
        if ((1 << shift) == options.brickSize) v->brickShift = shift;
    const int threads = options.threads <= 0 ? defaultThreadCount() : options.threads;
    const bool int16 = checkFiniteAndFitsInt16(volume, options, threads);
    const SourceGrid grid = sourceGrid(volume, options, int16, threads);
    v->spacing = grid.spacing;

    // Bounding box of the non-zero values (everything outside contributes exactly nothing).
    glm::ivec3 lo, hi;
    nonZeroBox(grid, threads, lo, hi);
    v->empty = hi.x < 0;
    if (!options.cropToContent) {
        lo = glm::ivec3(0);
        hi = grid.dims - 1;
    } else if (v->empty) {
        lo = hi = glm::ivec3(0);  // keep one voxel so every size stays positive
    }
    v->cropBegin = lo;
    v->dims = hi - lo + 1;
    v->paddedDims = v->dims + 2;
    const std::size_t padded =
        static_cast<std::size_t>(v->paddedDims.x) * v->paddedDims.y * v->paddedDims.z;
    if (int16) {
        v->voxelType = DrrVoxelType::Int16;
        v->valueScale = int16Scale(options);
        v->values16.assign(padded, 0);
    } else {
        v->values.assign(padded, 0.0f);
    }
    // The kept box converted, slab of bricks by slab of bricks, each slab's bricks classified
    // right after its values are written.
    allocateBricks(*v);
    const int b = v->brickSize;
    auto convert = [&](auto* values) {
        using T = std::remove_pointer_t<decltype(values)>;
        parallelFor(
            v->brickDims.z, threads,
            [&](int bk0, int bk1) {
                for (int bk = bk0; bk < bk1; ++bk) {
                    for (int k = bk * b; k < std::min(bk * b + b, v->dims.z); ++k)
                        for (int j = 0; j < v->dims.y; ++j) {
                            const std::size_t src = grid.index(lo.x, lo.y + j, lo.z + k);
                            T* dst = values + v->at(0, j, k);
                            for (int i = 0; i < v->dims.x; ++i)
                                dst[i] = static_cast<T>(grid.at(src + i));
                        }
                    classifyBrickSlab(*v, static_cast<const T*>(values), bk);
                }
            },
            4);
    };
    if (int16)
        convert(v->values16.data());
    else
        convert(v->values.data());
    decideWalk(*v);

    v->origin = grid.origin;
    v->direction = volume.direction;
    v->worldToLocal = glm::inverse(volume.direction);
    v->localShift = v->spacing * (0.5 - glm::dvec3(lo));
    v->invSpacing = 1.0 / v->spacing;
    return v;
}
DrrVolumeInfo drrVolumeInfo(const DrrVolume& v) {
    DrrVolumeInfo info;
    info.dims = v.dims;
    info.cropBegin = v.cropBegin;
    info.spacing = v.spacing;
    info.empty = v.empty;
    info.denseWalk = v.preferDenseWalk && denseWalkSimdAvailable();
    info.voxelType = v.voxelType;
    info.voxelBytes = v.voxelType == DrrVoxelType::Int16 ? v.values16.size() * sizeof(std::int16_t)
                                                         : v.values.size() * sizeof(float);
    info.bricksTotal = static_cast<int>(v.brickMixed.size());
    // decideWalk counted the empty bricks; the other unmixed ones are uniform.
    info.bricksEmpty = static_cast<int>(v.bricksEmpty);
    const auto unmixed = std::count(v.brickMixed.begin(), v.brickMixed.end(), std::uint8_t{0});
    info.bricksUniform = static_cast<int>(unmixed) - info.bricksEmpty;
    return info;
}

}  // namespace fm

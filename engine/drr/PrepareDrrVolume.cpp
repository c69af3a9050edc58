// Preparation of a volume for DRRs: value conversion, threshold, optional downsampling,
// cropping to the non-zero content and the brick map for empty-space skipping.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/Error.h"
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

// Converted values of the whole source grid, downsampled by `f` (block means) if f > 1.
// Returns the grid's dims, spacing and the world position of its voxel (0,0,0)'s centre.
std::vector<float> convertedValues(const Volume& volume, const DrrValueOptions& options,
                                   glm::ivec3& dims, glm::dvec3& spacing, glm::dvec3& origin) {
    const int f = options.downsample;
    std::vector<float> fine(volume.voxelCount());
    for (std::size_t n = 0; n < fine.size(); ++n) {
        const float stored = volume.values[n];
        if (std::isinf(stored)) {
            std::ostringstream msg;
            msg << "volume '" << volume.meta.source << "' holds an infinite value at voxel " << n
                << ": cannot compute a DRR";
            throw Error(msg.str());
        }
        fine[n] = static_cast<float>(drrVoxelValue(stored, options));
    }
    if (f == 1) {
        dims = volume.dims;
        spacing = volume.spacing;
        origin = volume.origin;
        return fine;
    }
    dims = (volume.dims + (f - 1)) / f;
    spacing = volume.spacing * double(f);
    // Coarse voxel I covers fine voxels [I f, I f + f): its centre is at fine index I f + (f-1)/2.
    origin = volume.indexToWorld(glm::dvec3((f - 1) * 0.5));
    std::vector<float> coarse(static_cast<std::size_t>(dims.x) * dims.y * dims.z);
    for (int K = 0; K < dims.z; ++K)
        for (int J = 0; J < dims.y; ++J)
            for (int I = 0; I < dims.x; ++I) {
                double sum = 0.0;
                int count = 0;
                for (int k = K * f; k < std::min(K * f + f, volume.dims.z); ++k)
                    for (int j = J * f; j < std::min(J * f + f, volume.dims.y); ++j)
                        for (int i = I * f; i < std::min(I * f + f, volume.dims.x); ++i) {
                            sum += fine[volume.index(i, j, k)];
                            ++count;
                        }
                coarse[I + static_cast<std::size_t>(dims.x) *
                               (J + static_cast<std::size_t>(dims.y) * K)] =
                    static_cast<float>(sum / count);
            }
    return coarse;
}

void buildBricks(DrrVolume& v) {
    const int b = v.brickSize;
    v.brickDims = (v.dims + (b - 1)) / b;
    const std::size_t count =
        static_cast<std::size_t>(v.brickDims.x) * v.brickDims.y * v.brickDims.z;
    v.brickValue.assign(count, 0.0f);
    v.brickMixed.assign(count, 0);
    for (int bk = 0; bk < v.brickDims.z; ++bk)
        for (int bj = 0; bj < v.brickDims.y; ++bj)
            for (int bi = 0; bi < v.brickDims.x; ++bi) {
                const std::size_t brick =
                    bi + static_cast<std::size_t>(v.brickDims.x) *
                             (bj + static_cast<std::size_t>(v.brickDims.y) * bk);
                const float first = v.values[v.at(bi * b, bj * b, bk * b)];
                bool mixed = false;
                for (int k = bk * b; k < std::min(bk * b + b, v.dims.z) && !mixed; ++k)
                    for (int j = bj * b; j < std::min(bj * b + b, v.dims.y) && !mixed; ++j)
                        for (int i = bi * b; i < std::min(bi * b + b, v.dims.x); ++i)
                            if (v.values[v.at(i, j, k)] != first) {
                                mixed = true;
                                break;
                            }
                v.brickMixed[brick] = mixed ? 1 : 0;
                v.brickValue[brick] = mixed ? 0.0f : first;
            }
}

}  // namespace

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
    if (options.thresholdHU && !std::isfinite(*options.thresholdHU))
        throw Error("DRR threshold must be a finite number");

    auto v = std::make_shared<DrrVolume>();
    v->options = options;
    v->brickSize = options.brickSize;
    v->brickShift = -1;
    for (int shift = 0; shift < 9; ++shift)
        if ((1 << shift) == options.brickSize) v->brickShift = shift;
    glm::ivec3 gridDims;
    glm::dvec3 gridOrigin;
    std::vector<float> grid = convertedValues(volume, options, gridDims, v->spacing, gridOrigin);
    auto gridIndex = [&](int i, int j, int k) {
        return i + static_cast<std::size_t>(gridDims.x) *
                       (j + static_cast<std::size_t>(gridDims.y) * k);
    };

    // Bounding box of the non-zero values (everything outside contributes exactly nothing).
    glm::ivec3 lo = gridDims, hi(-1);
    if (options.cropToContent) {
        for (int k = 0; k < gridDims.z; ++k)
            for (int j = 0; j < gridDims.y; ++j)
                for (int i = 0; i < gridDims.x; ++i)
                    if (grid[gridIndex(i, j, k)] != 0.0f) {
                        lo = glm::min(lo, glm::ivec3(i, j, k));
                        hi = glm::max(hi, glm::ivec3(i, j, k));
                    }
        v->empty = hi.x < 0;
        if (v->empty) lo = hi = glm::ivec3(0);  // keep one voxel so every size stays positive
    } else {
        lo = glm::ivec3(0);
        hi = gridDims - 1;
        v->empty = std::all_of(grid.begin(), grid.end(), [](float x) { return x == 0.0f; });
    }
    v->cropBegin = lo;
    v->dims = hi - lo + 1;
    v->paddedDims = v->dims + 2;
    v->values.assign(static_cast<std::size_t>(v->paddedDims.x) * v->paddedDims.y * v->paddedDims.z,
                     0.0f);
    for (int k = 0; k < v->dims.z; ++k)
        for (int j = 0; j < v->dims.y; ++j)
            for (int i = 0; i < v->dims.x; ++i)
                v->values[v->at(i, j, k)] = grid[gridIndex(lo.x + i, lo.y + j, lo.z + k)];

    v->origin = gridOrigin;
    v->direction = volume.direction;
    v->worldToLocal = glm::inverse(volume.direction);
    v->localShift = v->spacing * (0.5 - glm::dvec3(lo));
    v->invSpacing = 1.0 / v->spacing;
    buildBricks(*v);
    return v;
}

DrrVolumeInfo drrVolumeInfo(const DrrVolume& v) {
    DrrVolumeInfo info;
    info.dims = v.dims;
    info.cropBegin = v.cropBegin;
    info.spacing = v.spacing;
    info.empty = v.empty;
    info.bricksTotal = static_cast<int>(v.brickMixed.size());
    for (std::size_t b = 0; b < v.brickMixed.size(); ++b) {
        if (v.brickMixed[b]) continue;
        if (v.brickValue[b] == 0.0f)
            ++info.bricksEmpty;
        else
            ++info.bricksUniform;
    }
    return info;
}

}  // namespace fm

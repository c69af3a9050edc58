// Block means of a prepared volume (coarsenDrrVolume): the coarse grid starts at the kept box's
// corner, so the local frame (and with it the world placement) stays exactly the same; only
// the voxel size, the dims and the brick map change.
#include <algorithm>
#include <string>

#include "core/Error.h"
#include "core/Parallel.h"
#include "drr/Drr.h"
#include "drr/DrrVolume.h"

namespace fm {

DrrVolumePtr coarsenDrrVolume(const DrrVolume& v, int f, int threads) {
    if (f < 1 || f > 16)
        throw Error("DRR coarsening factor must be 1..16, got " + std::to_string(f));
    if (threads < 0) throw Error("DRR coarsening thread count must not be negative");
    auto c = std::make_shared<DrrVolume>(v);
    if (f == 1) return c;
    c->options.downsample = v.options.downsample * f;
    c->dims = (v.dims + (f - 1)) / f;
    c->cropBegin = v.cropBegin / f;
    c->spacing = v.spacing * double(f);
    c->invSpacing = 1.0 / c->spacing;
    c->paddedDims = c->dims + 2;
    // Block means are not integers: the coarse copy stores float (value per mm, scale 1).
    c->voxelType = DrrVoxelType::Float32;
    c->valueScale = 1.0;
    c->values16 = {};
    c->values.assign(static_cast<std::size_t>(c->paddedDims.x) * c->paddedDims.y * c->paddedDims.z,
                     0.0f);
    const double blockVolume = double(f) * f * f;
    parallelFor(
        c->dims.z, threads,
        [&](int K0, int K1) {
            for (int K = K0; K < K1; ++K)
                for (int J = 0; J < c->dims.y; ++J)
                    for (int I = 0; I < c->dims.x; ++I) {
                        double sum = 0.0;
                        for (int k = K * f; k < std::min(K * f + f, v.dims.z); ++k)
                            for (int j = J * f; j < std::min(J * f + f, v.dims.y); ++j)
                                for (int i = I * f; i < std::min(I * f + f, v.dims.x); ++i)
                                    sum += v.storedAt(v.at(i, j, k));
                        c->values[c->at(I, J, K)] =
                            static_cast<float>(sum * v.valueScale / blockVolume);
                    }
        },
        4);
    buildDrrBricks(*c, threads <= 0 ? defaultThreadCount() : threads);
    return c;
}

}  // namespace fm

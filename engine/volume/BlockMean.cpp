#include "volume/BlockMean.h"

#include <algorithm>

#include "core/Error.h"
#include "core/Parallel.h"

namespace fm {

Volume blockMean(const Volume& volume, int factor, int threads) {
    if (factor < 1) throw Error("block mean: the factor must be at least 1, got " + std::to_string(factor));
    if (volume.values.empty()) throw Error("block mean: the volume holds no values");
    const glm::ivec3 dims = (volume.dims + glm::ivec3(factor - 1)) / factor;
    Volume out = Volume::allocate(dims);
    out.meta = volume.meta;
    out.direction = volume.direction;
    out.spacing = volume.spacing * double(factor);
    // A full block's centre is (factor - 1) / 2 voxels on from its first voxel.
    out.origin = volume.indexToWorld(glm::dvec3(0.5 * (factor - 1)));
    parallelFor(dims.z, threads, [&](int begin, int end) {
        for (int K = begin; K < end; ++K)
            for (int J = 0; J < dims.y; ++J)
                for (int I = 0; I < dims.x; ++I) {
                    const glm::ivec3 lo = glm::ivec3(I, J, K) * factor;
                    const glm::ivec3 hi = glm::min(lo + factor, volume.dims);
                    double sum = 0.0;
                    for (int k = lo.z; k < hi.z; ++k)
                        for (int j = lo.y; j < hi.y; ++j)
                            for (int i = lo.x; i < hi.x; ++i) sum += volume.at(i, j, k);
                    const glm::ivec3 n = hi - lo;
                    out.at(I, J, K) = static_cast<float>(sum / double(n.x * n.y * n.z));
                }
    });
    return out;
}

}  // namespace fm

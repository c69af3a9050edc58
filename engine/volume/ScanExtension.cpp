#include "volume/ScanExtension.h"

#include <algorithm>
#include <cmath>

#include "core/Error.h"

namespace fm {

namespace {

// Whether the face at index `at` along `axis` (0 = i, 1 = j, 2 = k) holds a body voxel.
bool faceCutsBody(const Volume& v, int axis, int at) {
    const int a = (axis + 1) % 3, b = (axis + 2) % 3;
    glm::ivec3 p(0);
    p[axis] = at;
    for (p[b] = 0; p[b] < v.dims[b]; ++p[b])
        for (p[a] = 0; p[a] < v.dims[a]; ++p[a])
            if (v.at(p.x, p.y, p.z) > kBodyHU) return true;
    return false;
}

}  // namespace

Volume extendedAcrossCutFaces(const Volume& ct, double marginMm) {
    if (!(marginMm > 0.0)) return ct;
    if (marginMm > 10000.0) throw Error("scan extension: at most 10000 mm (got " + std::to_string(marginMm) + ")");
    // 1. Which faces cut the body, and by how many voxels each grows.
    glm::ivec3 before(0), after(0);
    for (int axis = 0; axis < 3; ++axis) {
        const int n = static_cast<int>(std::ceil(marginMm / ct.spacing[axis]));
        if (faceCutsBody(ct, axis, 0)) before[axis] = n;
        if (faceCutsBody(ct, axis, ct.dims[axis] - 1)) after[axis] = n;
    }
    if (before == glm::ivec3(0) && after == glm::ivec3(0)) return ct;
    // 2. The grown grid, its first voxel where index -before of the CT is.
    Volume out = Volume::allocate(ct.dims + before + after);
    out.spacing = ct.spacing;
    out.direction = ct.direction;
    out.origin = ct.indexToWorld(-glm::dvec3(before));
    out.meta = ct.meta;
    // 3. Every voxel takes the CT's nearest one: itself inside, the face's outside.
    for (int k = 0; k < out.dims.z; ++k) {
        const int kk = std::clamp(k - before.z, 0, ct.dims.z - 1);
        for (int j = 0; j < out.dims.y; ++j) {
            const int jj = std::clamp(j - before.y, 0, ct.dims.y - 1);
            for (int i = 0; i < out.dims.x; ++i)
                out.at(i, j, k) = ct.at(std::clamp(i - before.x, 0, ct.dims.x - 1), jj, kk);
        }
    }
    return out;
}

}  // namespace fm

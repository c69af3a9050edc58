#include "bones/LabelMap.h"

#include <cmath>
#include <sstream>

#include "core/Error.h"
#include "core/Parallel.h"
#include "io/ReadVolume.h"

namespace fm {
namespace {

void checkLabelValues(const Volume& labels, const std::string& what) {
    for (std::size_t n = 0; n < labels.values.size(); ++n) {
        const float v = labels.values[n];
        if (!(v >= 0.0f && v <= static_cast<float>(kMaxLabel)) || v != std::floor(v)) {
            std::ostringstream msg;
            msg << what << ": voxel " << n << " holds " << v
                << ", not a label (a whole number 0.." << kMaxLabel << ")";
            throw Error(msg.str());
        }
    }
}

}  // namespace

bool sameGrid(const Volume& a, const Volume& b, double toleranceMm) {
    if (a.dims != b.dims) return false;
    const glm::dvec3 corners[] = {glm::dvec3(0.0), glm::dvec3(a.dims) - 1.0,
                                  glm::dvec3(a.dims.x - 1, 0, 0), glm::dvec3(0, a.dims.y - 1, 0),
                                  glm::dvec3(0, 0, a.dims.z - 1)};
    for (const glm::dvec3& c : corners)
        if (glm::length(a.indexToWorld(c) - b.indexToWorld(c)) > toleranceMm) return false;
    return true;
}

Volume labelsOnGrid(Volume labels, const Volume& ct, const std::string& what) {
    labels.validate(what);
    ct.validate("CT");
    checkLabelValues(labels, what);
    if (sameGrid(labels, ct)) {
        labels.origin = ct.origin;
        labels.spacing = ct.spacing;
        labels.direction = ct.direction;
        return labels;
    }
    Volume out = Volume::allocate(ct.dims, 0.0f);
    out.origin = ct.origin;
    out.spacing = ct.spacing;
    out.direction = ct.direction;
    out.meta = labels.meta;
    std::vector<std::size_t> covered(static_cast<std::size_t>(ct.dims.z), 0);
    parallelFor(ct.dims.z, 0, [&](int k0, int k1) {
        for (int k = k0; k < k1; ++k)
            for (int j = 0; j < ct.dims.y; ++j)
                for (int i = 0; i < ct.dims.x; ++i) {
                    const glm::dvec3 ijk = labels.worldToIndex(ct.indexToWorld({i, j, k}));
                    const glm::dvec3 r = glm::floor(ijk + 0.5);
                    if (r.x < 0 || r.y < 0 || r.z < 0 || r.x >= labels.dims.x ||
                        r.y >= labels.dims.y || r.z >= labels.dims.z)
                        continue;
                    out.at(i, j, k) = labels.at(int(r.x), int(r.y), int(r.z));
                    ++covered[static_cast<std::size_t>(k)];
                }
    });
    std::size_t total = 0;
    for (std::size_t c : covered) total += c;
    if (total == 0) {
        std::ostringstream msg;
        msg << what << ": its grid (" << labels.dims.x << "x" << labels.dims.y << "x"
            << labels.dims.z << ", origin " << labels.origin.x << "," << labels.origin.y << ","
            << labels.origin.z << " mm) covers none of the CT's voxels, so it cannot be "
            << "resampled onto the CT: is it the label map of another scan?";
        throw Error(msg.str());
    }
    return out;
}

Volume loadLabelMap(const std::string& path, const Volume& ct) {
    return labelsOnGrid(readVolume(path), ct, "label map " + path);
}

std::map<int, std::size_t> labelVoxelCounts(const Volume& labels) {
    std::map<int, std::size_t> counts;
    for (float v : labels.values) ++counts[static_cast<int>(v)];
    return counts;
}

}  // namespace fm

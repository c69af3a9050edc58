#include "volume/Volume.h"

#include <cmath>
#include <limits>
#include <sstream>

#include "core/Error.h"
#include "core/WorldLimits.h"

namespace fm {

const char* toString(ValueUnit unit) {
    switch (unit) {
        case ValueUnit::HounsfieldUnits: return "HU";
        case ValueUnit::LinearAttenuation: return "1/mm";
        case ValueUnit::Unknown: break;
    }
    return "unknown";
}

Volume Volume::allocate(glm::ivec3 dims, float fill) {
    if (dims.x <= 0 || dims.y <= 0 || dims.z <= 0) {
        std::ostringstream msg;
        msg << "volume dimensions must be positive, got " << dims.x << " x " << dims.y << " x "
            << dims.z;
        throw Error(msg.str());
    }
    const std::size_t count = static_cast<std::size_t>(dims.x) * static_cast<std::size_t>(dims.y) *
                              static_cast<std::size_t>(dims.z);
    if (count > kMaxVoxelCount) {
        std::ostringstream msg;
        msg << "volume of " << dims.x << " x " << dims.y << " x " << dims.z
            << " voxels is larger than the supported maximum of " << kMaxVoxelCount << " voxels";
        throw Error(msg.str());
    }
    Volume v;
    v.dims = dims;
    v.values.assign(count, fill);
    return v;
}

glm::dvec3 Volume::indexToWorld(const glm::dvec3& ijk) const {
    return origin + direction * (spacing * ijk);
}

glm::dvec3 Volume::worldToIndex(const glm::dvec3& world) const {
    // direction is orthonormal (validated), so its inverse is its transpose.
    return (glm::transpose(direction) * (world - origin)) / spacing;
}

glm::dvec3 Volume::center() const { return indexToWorld((glm::dvec3(dims) - 1.0) * 0.5); }

void Volume::validate(const std::string& what) const {
    auto fail = [&](const std::string& why) { throw Error(what + ": " + why); };
    if (dims.x <= 0 || dims.y <= 0 || dims.z <= 0) fail("dimensions must be positive");
    if (voxelCount() > kMaxVoxelCount) fail("volume is larger than the supported maximum");
    if (!values.empty() && values.size() != voxelCount())
        fail("value count does not match the dimensions");
    for (int a = 0; a < 3; ++a) {
        if (!std::isfinite(spacing[a]) || spacing[a] <= 0.0) {
            std::ostringstream msg;
            msg << "voxel spacing must be positive and finite, got " << spacing.x << " "
                << spacing.y << " " << spacing.z;
            fail(msg.str());
        }
        if (!std::isfinite(origin[a])) fail("origin is not finite");
        // Finite but absurd (spacing 1e300) overflows the first world coordinate computed.
        if (std::abs(origin[a]) > kMaxWorldMm || spacing[a] * dims[a] > kMaxWorldMm) {
            std::ostringstream msg;
            msg << "origin " << origin[a] << " mm or extent " << spacing[a] * dims[a]
                << " mm along axis " << a << " is beyond " << kMaxWorldMm << " mm";
            fail(msg.str());
        }
    }
    // Orthonormal to a tolerance that accepts the 6-8 digits files store cosines with.
    constexpr double kDirectionTolerance = 1e-4;
    for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) {
            const double d = glm::dot(direction[a], direction[b]);
            if (!std::isfinite(d) || std::abs(d - (a == b ? 1.0 : 0.0)) > kDirectionTolerance)
                fail("direction cosines are not orthonormal");
        }
}

std::string orientationCode(const glm::dmat3& direction) {
    // LPS: +x is patient Left, +y Posterior, +z Superior.
    static const char kPositive[3] = {'L', 'P', 'S'};
    static const char kNegative[3] = {'R', 'A', 'I'};
    constexpr double kAxisAligned = 0.999;  // cosine above which an axis counts as aligned
    std::string code;
    for (int a = 0; a < 3; ++a) {
        const glm::dvec3 axis = direction[a];
        char c = '?';
        for (int w = 0; w < 3; ++w) {
            if (axis[w] > kAxisAligned) c = kPositive[w];
            if (axis[w] < -kAxisAligned) c = kNegative[w];
        }
        code += c;
    }
    return code;
}

}  // namespace fm

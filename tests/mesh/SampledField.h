#pragma once
// A volume holding f(world position) at every voxel centre: the analytic shapes the mesh tests
// contour (signed distances, positive inside).
#include <functional>

#include <glm/glm.hpp>

#include "volume/Volume.h"

namespace fm::test {

inline Volume sampleField(glm::ivec3 dims, glm::dvec3 spacing, glm::dvec3 origin,
                          const std::function<double(const glm::dvec3&)>& f,
                          glm::dmat3 direction = glm::dmat3(1.0)) {
    Volume v = Volume::allocate(dims);
    v.spacing = spacing;
    v.origin = origin;
    v.direction = direction;
    v.meta.source = "test field";
    for (int k = 0; k < dims.z; ++k)
        for (int j = 0; j < dims.y; ++j)
            for (int i = 0; i < dims.x; ++i)
                v.at(i, j, k) = static_cast<float>(f(v.indexToWorld(glm::dvec3(i, j, k))));
    return v;
}

// Spacing h in every direction, centred on the world origin.
inline Volume sampleField(glm::ivec3 dims, double h, const std::function<double(const glm::dvec3&)>& f) {
    return sampleField(dims, glm::dvec3(h), -0.5 * h * glm::dvec3(dims - 1), f);
}

}  // namespace fm::test

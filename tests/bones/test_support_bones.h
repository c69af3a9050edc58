#pragma once
// Small volumes for the bone tests.
#include "volume/Volume.h"

namespace fm::test {

inline Volume grid(glm::ivec3 dims, glm::dvec3 spacing, glm::dvec3 origin, float fill = 0.0f) {
    Volume v = Volume::allocate(dims, fill);
    v.spacing = spacing;
    v.origin = origin;
    return v;
}

// Fills the inclusive voxel box [lo, hi] with `value`.
inline void fillBox(Volume& v, glm::ivec3 lo, glm::ivec3 hi, float value) {
    for (int k = lo.z; k <= hi.z; ++k)
        for (int j = lo.y; j <= hi.y; ++j)
            for (int i = lo.x; i <= hi.x; ++i) v.at(i, j, k) = value;
}

}  // namespace fm::test

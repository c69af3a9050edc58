#pragma once
// Casting one ray through a mesh's BVH and summing what a DRR needs: the signed crossing
// parameters. For the ray origin + t dir, t >= 0, with crossings t_i (entering -, leaving +):
//     chord(0..1) = |dir| * sum_i s_i min(t_i, 1)
// is the length inside a closed surface between origin (t = 0) and origin + dir (t = 1), also
// when either end is inside (the winding number is 0 at t = infinity for a closed surface:
// integrating it by parts leaves only this sum). Nested shells add up (winding 2 counts twice).
#include <cstdint>

#include <glm/glm.hpp>

#include "meshdrr/MeshBvh.h"

namespace fm {

struct RayCrossings {
    double signedParameter = 0.0;  // sum_i s_i min(t_i, 1): chord / |dir| for a closed mesh
    std::uint32_t hitsInSegment = 0;  // crossings with 0 <= t <= 1 (silhouette of open meshes)
};

// `dir` must not be zero. Thread-safe (reads the BVH only).
RayCrossings castRay(const MeshBvh& bvh, const glm::dvec3& origin, const glm::dvec3& dir);

}  // namespace fm

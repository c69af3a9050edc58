#pragma once
// One surface of the 3D view: a mesh in its own frame, where it is and its colour (no GL here).
#include <cstdint>

#include <glm/glm.hpp>

#include "mesh/Mesh.h"

namespace fm::render {

struct SurfaceItem {
    const Mesh* mesh = nullptr;
    std::uint64_t generation = 0;     // the mesh is uploaded again only when this changes
    glm::dmat4 worldFromObject{1.0};  // its pose (identity: where the CT has it)
    glm::vec3 color{0.93f, 0.89f, 0.80f};
};

}  // namespace fm::render

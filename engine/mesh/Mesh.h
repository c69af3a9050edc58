#pragma once
// An indexed triangle mesh in world millimetres (the volume's frame), shared vertices,
// counter-clockwise triangles seen from outside (normals point out of the bone).
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace fm {

struct Mesh {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;       // per vertex, unit, outward
    std::vector<glm::uvec3> triangles;    // indices into positions
    std::vector<std::uint32_t> component; // per triangle: connected-component label (optional)

    std::size_t vertexCount() const { return positions.size(); }
    std::size_t triangleCount() const { return triangles.size(); }
};

}  // namespace fm

#include "model/MeshTopology.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

#include "core/Error.h"

namespace fm {

std::string MeshTopology::edgeSummary() const {
    return std::to_string(boundaryEdges) + " boundary edges, " + std::to_string(nonManifoldEdges) +
           " non-manifold, " + std::to_string(misorientedEdges) + " misoriented (of " +
           std::to_string(edges) + ")";
}

MeshTopology analyseMesh(const Mesh& mesh) {
    MeshTopology t;
    const std::size_t n = mesh.positions.size();
    // Each directed edge as (low, high) key plus one bit: which way the triangle runs along it.
    std::vector<std::uint64_t> keys;
    keys.reserve(3 * mesh.triangles.size());
    for (const auto& tri : mesh.triangles) {
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = tri[k], b = tri[(k + 1) % 3];
            if (a >= n || b >= n) throw Error("analyseMesh: triangle index out of range");
            const std::uint64_t lo = std::min(a, b), hi = std::max(a, b);
            // 2^31 vertices at most here (kMaxModelElements is far below it).
            keys.push_back((lo << 33) | (hi << 1) | (a < b ? 0u : 1u));
        }
    }
    std::sort(keys.begin(), keys.end());
    for (std::size_t i = 0; i < keys.size();) {
        std::size_t j = i, forward = 0, backward = 0;
        while (j < keys.size() && (keys[j] >> 1) == (keys[i] >> 1)) {
            (keys[j] & 1u ? backward : forward)++;
            ++j;
        }
        ++t.edges;
        const std::size_t uses = j - i;
        if (uses == 1)
            ++t.boundaryEdges;
        else if (uses > 2)
            ++t.nonManifoldEdges;
        else if (forward != 1 || backward != 1)
            ++t.misorientedEdges;
        i = j;
    }
    t.boundsMin = glm::dvec3(std::numeric_limits<double>::infinity());
    t.boundsMax = -t.boundsMin;
    for (const auto& p : mesh.positions) {
        t.boundsMin = glm::min(t.boundsMin, glm::dvec3(p));
        t.boundsMax = glm::max(t.boundsMax, glm::dvec3(p));
    }
    if (mesh.positions.empty()) t.boundsMin = t.boundsMax = glm::dvec3(0.0);
    // Volume by the divergence theorem, about the bounds' centre (less cancellation).
    const glm::dvec3 c = 0.5 * (t.boundsMin + t.boundsMax);
    for (const auto& tri : mesh.triangles) {
        const glm::dvec3 a = glm::dvec3(mesh.positions[tri.x]) - c;
        const glm::dvec3 b = glm::dvec3(mesh.positions[tri.y]) - c;
        const glm::dvec3 d = glm::dvec3(mesh.positions[tri.z]) - c;
        t.signedVolume += glm::dot(a, glm::cross(b, d)) / 6.0;
        t.area += 0.5 * glm::length(glm::cross(b - a, d - a));
    }
    return t;
}

}  // namespace fm

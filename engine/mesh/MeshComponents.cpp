#include "mesh/MeshComponents.h"

#include <algorithm>
#include <limits>
#include <numeric>

namespace fm {
namespace {

std::uint32_t findRoot(std::vector<std::uint32_t>& parent, std::uint32_t v) {
    while (parent[v] != v) {
        parent[v] = parent[parent[v]];  // path halving
        v = parent[v];
    }
    return v;
}

void unite(std::vector<std::uint32_t>& parent, std::uint32_t a, std::uint32_t b) {
    a = findRoot(parent, a);
    b = findRoot(parent, b);
    if (a == b) return;
    // Smaller index becomes the root: deterministic regardless of triangle order subtleties.
    if (a < b)
        parent[b] = a;
    else
        parent[a] = b;
}

}  // namespace

std::size_t labelComponents(Mesh& mesh) {
    const std::size_t vertexCount = mesh.positions.size();
    std::vector<std::uint32_t> parent(vertexCount);
    std::iota(parent.begin(), parent.end(), 0u);
    for (const auto& t : mesh.triangles) {
        unite(parent, t.x, t.y);
        unite(parent, t.x, t.z);
    }
    // Provisional ids in order of first triangle, then sizes.
    constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
    std::vector<std::uint32_t> provisional(vertexCount, kNone);
    std::vector<std::size_t> sizes;
    mesh.component.resize(mesh.triangles.size());
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const std::uint32_t root = findRoot(parent, mesh.triangles[t].x);
        if (provisional[root] == kNone) {
            provisional[root] = static_cast<std::uint32_t>(sizes.size());
            sizes.push_back(0);
        }
        mesh.component[t] = provisional[root];
        ++sizes[provisional[root]];
    }
    std::vector<std::uint32_t> order(sizes.size());
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(),
                     [&](std::uint32_t a, std::uint32_t b) { return sizes[a] > sizes[b]; });
    std::vector<std::uint32_t> rank(sizes.size());
    for (std::size_t r = 0; r < order.size(); ++r) rank[order[r]] = static_cast<std::uint32_t>(r);
    for (auto& c : mesh.component) c = rank[c];
    return sizes.size();
}

std::vector<std::size_t> componentSizes(const Mesh& mesh) {
    std::vector<std::size_t> sizes;
    for (std::uint32_t c : mesh.component) {
        if (c >= sizes.size()) sizes.resize(c + 1, 0);
        ++sizes[c];
    }
    return sizes;
}

void keepComponents(Mesh& mesh, const std::vector<bool>& keep) {
    constexpr std::uint32_t kUnused = std::numeric_limits<std::uint32_t>::max();
    std::vector<std::uint32_t> remap(mesh.positions.size(), kUnused);
    MeshArray<glm::uvec3> triangles;
    std::vector<std::uint32_t> component;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const std::uint32_t c = mesh.component[t];
        if (c >= keep.size() || !keep[c]) continue;
        triangles.push_back(mesh.triangles[t]);
        component.push_back(c);
        for (int v = 0; v < 3; ++v) remap[mesh.triangles[t][v]] = 0;
    }
    std::uint32_t next = 0;
    for (std::size_t v = 0; v < remap.size(); ++v) {
        if (remap[v] == kUnused) continue;
        remap[v] = next;
        mesh.positions[next] = mesh.positions[v];
        if (v < mesh.normals.size()) mesh.normals[next] = mesh.normals[v];
        ++next;
    }
    mesh.positions.resize(next);
    if (!mesh.normals.empty()) mesh.normals.resize(next);
    for (auto& t : triangles) t = glm::uvec3(remap[t.x], remap[t.y], remap[t.z]);
    mesh.triangles = std::move(triangles);
    mesh.component = std::move(component);
}

void keepLargestComponents(Mesh& mesh, int count) {
    if (count <= 0) return;
    std::vector<bool> keep(static_cast<std::size_t>(count), true);
    keepComponents(mesh, keep);
}

std::uint32_t componentNearest(const Mesh& mesh, const glm::dvec3& world) {
    std::vector<std::uint32_t> vertexComponent(mesh.positions.size(), 0);
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
        for (int v = 0; v < 3; ++v) vertexComponent[mesh.triangles[t][v]] = mesh.component[t];
    double best = std::numeric_limits<double>::max();
    std::uint32_t bestComponent = 0;
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        const glm::dvec3 d = glm::dvec3(mesh.positions[v]) - world;
        const double d2 = glm::dot(d, d);
        if (d2 < best) {
            best = d2;
            bestComponent = vertexComponent[v];
        }
    }
    return bestComponent;
}

}  // namespace fm

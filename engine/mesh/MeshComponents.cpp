#include "mesh/MeshComponents.h"

#include <algorithm>
#include <atomic>
#include <limits>
#include <numeric>

#include "core/Parallel.h"
#include "mesh/VertexForest.h"

namespace fm {
namespace {

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

// Counting by runs: triangles are counted per component by runs of equal labels, not one
// increment each. Neighbouring triangles nearly always share a component, and increments of one
// counter back to back each wait for the previous store (aorta crop: 1.2 ms for 578 k
// triangles).

// [part * n / parts, (part + 1) * n / parts): the fixed split every pass below uses.
std::size_t partBegin(std::size_t n, int part, int parts) {
    return static_cast<std::size_t>(static_cast<unsigned long long>(n) * part / parts);
}

int partsFor(std::size_t n, int threads) {
    if (threads <= 0) threads = defaultThreadCount();
    // Below a few thousand elements per part, threads cost more than they save.
    const std::size_t useful = std::max<std::size_t>(1, n / 4096);
    return static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(threads), useful));
}

// Runs body(part) for part = 0 .. parts - 1 on up to `parts` threads.
template <class Body>
void forParts(int parts, Body&& body) {
    parallelFor(parts, parts, [&](int begin, int end) {
        for (int part = begin; part < end; ++part) body(part);
    });
}

}  // namespace

std::size_t labelComponents(Mesh& mesh, int threads) {
    MeshArray<std::uint32_t> parent(mesh.positions.size());
    std::iota(parent.begin(), parent.end(), 0u);
    TriangleUnion unite(parent.data());
    for (const auto& t : mesh.triangles) unite.add(t);
    return labelComponentsFromForest(mesh, parent.data(), threads);
}

std::size_t labelComponentsFromForest(Mesh& mesh, std::uint32_t* parent, int threads) {
    const std::size_t vertexCount = mesh.positions.size();
    const std::size_t triangleCount = mesh.triangles.size();
    mesh.component.resize(triangleCount);
    if (triangleCount == 0) return 0;

    // 1. Every vertex straight to its root, and the roots numbered in vertex order. Within a
    // part the vertices go up, and parent[v] <= v, so a parent in the same part is already a
    // root; one in an earlier part may be compressed by its own thread while it is read here,
    // hence the relaxed atomics (any ancestor read leads to the same root).
    auto load = [parent](std::size_t v) {
        return std::atomic_ref<std::uint32_t>(parent[v]).load(std::memory_order_relaxed);
    };
    const int vertexParts = partsFor(vertexCount, threads);
    std::vector<std::uint32_t> rootsBefore(static_cast<std::size_t>(vertexParts) + 1, 0);
    forParts(vertexParts, [&](int part) {
        const std::size_t begin = partBegin(vertexCount, part, vertexParts);
        const std::size_t end = partBegin(vertexCount, part + 1, vertexParts);
        std::uint32_t roots = 0;
        for (std::size_t v = begin; v < end; ++v) {
            std::uint32_t r = load(v);
            if (r >= begin)
                r = load(r);
            else
                for (std::uint32_t up; (up = load(r)) != r;) r = up;
            std::atomic_ref<std::uint32_t>(parent[v]).store(r, std::memory_order_relaxed);
            roots += r == v;
        }
        rootsBefore[part + 1] = roots;
    });
    // From here on parent[] is only read.
    for (int part = 0; part < vertexParts; ++part) rootsBefore[part + 1] += rootsBefore[part];
    const std::size_t count = rootsBefore[vertexParts];
    // Number of each root (in vertex order), kept at the root's own index.
    MeshArray<std::uint32_t> rootNumber(vertexCount);
    forParts(vertexParts, [&](int part) {
        std::uint32_t next = rootsBefore[part];
        const std::size_t end = partBegin(vertexCount, part + 1, vertexParts);
        for (std::size_t v = partBegin(vertexCount, part, vertexParts); v < end; ++v)
            if (parent[v] == v) rootNumber[v] = next++;
    });

    // 2. Per triangle its component's number; per part the triangle count and the first
    // triangle of each component.
    const int triangleParts = partsFor(triangleCount, threads);
    std::vector<std::vector<std::uint32_t>> sizes(triangleParts);
    std::vector<std::vector<std::size_t>> firsts(triangleParts);
    forParts(triangleParts, [&](int part) {
        std::vector<std::uint32_t>& size = sizes[part];
        std::vector<std::size_t>& first = firsts[part];
        size.assign(count, 0);
        first.assign(count, 0);
        const std::size_t begin = partBegin(triangleCount, part, triangleParts);
        const std::size_t end = partBegin(triangleCount, part + 1, triangleParts);
        // Counted by runs (top of the file).
        std::uint32_t current = kNone;
        std::size_t runStart = begin;
        auto endRun = [&](std::size_t t) {
            if (current == kNone) return;
            if (size[current] == 0) first[current] = runStart;
            size[current] += static_cast<std::uint32_t>(t - runStart);
        };
        for (std::size_t t = begin; t < end; ++t) {
            const std::uint32_t c = rootNumber[parent[mesh.triangles[t].x]];
            mesh.component[t] = c;
            if (c != current) {
                endRun(t);
                current = c;
                runStart = t;
            }
        }
        endRun(end);
    });
    // 3. Rank: most triangles first, ties by first triangle (as labelled in triangle order).
    std::vector<std::size_t> total(count, 0), firstTriangle(count, 0);
    for (int part = triangleParts - 1; part >= 0; --part)  // the earliest part's first wins
        for (std::size_t c = 0; c < count; ++c) {
            total[c] += sizes[part][c];
            if (sizes[part][c]) firstTriangle[c] = firsts[part][c];
        }
    std::vector<std::uint32_t> order(count);
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
        return total[a] != total[b] ? total[a] > total[b] : firstTriangle[a] < firstTriangle[b];
    });
    std::vector<std::uint32_t> rank(count);
    for (std::size_t r = 0; r < count; ++r) rank[order[r]] = static_cast<std::uint32_t>(r);
    forParts(triangleParts, [&](int part) {
        const std::size_t end = partBegin(triangleCount, part + 1, triangleParts);
        for (std::size_t t = partBegin(triangleCount, part, triangleParts); t < end; ++t)
            mesh.component[t] = rank[mesh.component[t]];
    });
    return count;
}

std::size_t countForestRoots(const std::uint32_t* parent, std::size_t vertexCount, int threads) {
    const int parts = partsFor(vertexCount, threads);
    std::vector<std::size_t> roots(static_cast<std::size_t>(parts), 0);
    forParts(parts, [&](int part) {
        std::size_t n = 0;
        const std::size_t end = partBegin(vertexCount, part + 1, parts);
        for (std::size_t v = partBegin(vertexCount, part, parts); v < end; ++v)
            n += parent[v] == v;
        roots[part] = n;
    });
    return std::accumulate(roots.begin(), roots.end(), std::size_t{0});
}

std::vector<std::size_t> componentSizes(const Mesh& mesh) {
    // The largest rank first (a vectorised reduction), then a count without size checks, by
    // runs (top of the file).
    std::uint32_t largest = 0;
    for (std::uint32_t c : mesh.component) largest = c > largest ? c : largest;
    std::vector<std::size_t> sizes(mesh.component.empty() ? 0 : std::size_t{largest} + 1, 0);
    const std::uint32_t* c = mesh.component.data();
    const std::size_t n = mesh.component.size();
    for (std::size_t i = 0; i < n;) {
        std::size_t j = i + 1;
        while (j < n && c[j] == c[i]) ++j;
        sizes[c[i]] += j - i;
        i = j;
    }
    return sizes;
}

void keepComponents(Mesh& mesh, const std::vector<bool>& keep, int threads) {
    const std::size_t vertexCount = mesh.positions.size();
    const std::size_t triangleCount = mesh.triangles.size();
    // Bytes, not vector<bool>'s bits: this is asked once or twice per triangle.
    const std::vector<std::uint8_t> keepRank(keep.begin(), keep.end());
    const std::uint32_t* const rankOf = mesh.component.data();
    auto kept = [&](std::size_t t) {
        const std::uint32_t c = rankOf[t];
        return c < keepRank.size() && keepRank[c];
    };
    // 1. Kept triangles per part; their vertices marked (a vertex's triangles all belong to its
    // component, so every thread that marks it writes the same value).
    MeshArray<std::uint32_t> remap(vertexCount);
    const int vertexParts = partsFor(vertexCount, threads);
    forParts(vertexParts, [&](int part) {
        std::fill(remap.begin() + partBegin(vertexCount, part, vertexParts),
                  remap.begin() + partBegin(vertexCount, part + 1, vertexParts), kNone);
    });
    const int triangleParts = partsFor(triangleCount, threads);
    std::vector<std::size_t> trianglesBefore(static_cast<std::size_t>(triangleParts) + 1, 0);
    forParts(triangleParts, [&](int part) {
        std::size_t n = 0;
        const std::size_t end = partBegin(triangleCount, part + 1, triangleParts);
        for (std::size_t t = partBegin(triangleCount, part, triangleParts); t < end; ++t) {
            if (!kept(t)) continue;
            ++n;
            for (int v = 0; v < 3; ++v)
                std::atomic_ref<std::uint32_t>(remap[mesh.triangles[t][v]])
                    .store(0, std::memory_order_relaxed);
        }
        trianglesBefore[part + 1] = n;
    });
    for (int part = 0; part < triangleParts; ++part)
        trianglesBefore[part + 1] += trianglesBefore[part];
    if (trianglesBefore[triangleParts] == triangleCount) return;  // everything kept

    // 2. New vertex ids in the old order; positions and normals moved to new arrays.
    std::vector<std::uint32_t> verticesBefore(static_cast<std::size_t>(vertexParts) + 1, 0);
    forParts(vertexParts, [&](int part) {
        const std::size_t end = partBegin(vertexCount, part + 1, vertexParts);
        std::uint32_t n = 0;
        for (std::size_t v = partBegin(vertexCount, part, vertexParts); v < end; ++v)
            n += remap[v] != kNone;
        verticesBefore[part + 1] = n;
    });
    for (int part = 0; part < vertexParts; ++part) verticesBefore[part + 1] += verticesBefore[part];
    const bool normals = mesh.normals.size() == vertexCount;
    MeshArray<glm::vec3> positions(verticesBefore[vertexParts]), newNormals;
    if (normals) newNormals.resize(positions.size());
    forParts(vertexParts, [&](int part) {
        std::uint32_t next = verticesBefore[part];
        const std::size_t end = partBegin(vertexCount, part + 1, vertexParts);
        for (std::size_t v = partBegin(vertexCount, part, vertexParts); v < end; ++v) {
            if (remap[v] == kNone) continue;
            remap[v] = next;
            positions[next] = mesh.positions[v];
            if (normals) newNormals[next] = mesh.normals[v];
            ++next;
        }
    });

    // 3. The kept triangles, renumbered, in their old order.
    MeshArray<glm::uvec3> triangles(trianglesBefore[triangleParts]);
    MeshArray<std::uint32_t> component(triangles.size());
    forParts(triangleParts, [&](int part) {
        std::size_t next = trianglesBefore[part];
        const std::size_t end = partBegin(triangleCount, part + 1, triangleParts);
        for (std::size_t t = partBegin(triangleCount, part, triangleParts); t < end; ++t) {
            if (!kept(t)) continue;
            const glm::uvec3 tri = mesh.triangles[t];
            triangles[next] = glm::uvec3(remap[tri.x], remap[tri.y], remap[tri.z]);
            component[next] = mesh.component[t];
            ++next;
        }
    });
    mesh.positions = std::move(positions);
    if (normals) mesh.normals = std::move(newNormals);
    mesh.triangles = std::move(triangles);
    mesh.component = std::move(component);
}

void keepLargestComponents(Mesh& mesh, int count, int threads) {
    if (count <= 0) return;
    std::vector<bool> keep(static_cast<std::size_t>(count), true);
    keepComponents(mesh, keep, threads);
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

#include "model/WeldVertices.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <unordered_map>

#include "core/Error.h"

namespace fm {
namespace {

constexpr std::uint32_t kUnset = 0xffffffffu;

// representative[v] = the vertex v merges into (the first in file order at the same place).
std::vector<std::uint32_t> exactRepresentatives(const Mesh& mesh) {
    const std::size_t n = mesh.positions.size();
    std::vector<std::uint32_t> order(n);
    std::iota(order.begin(), order.end(), 0u);
    auto less = [&](std::uint32_t a, std::uint32_t b) {
        const glm::vec3 &p = mesh.positions[a], &q = mesh.positions[b];
        if (p.x != q.x) return p.x < q.x;
        if (p.y != q.y) return p.y < q.y;
        if (p.z != q.z) return p.z < q.z;
        return a < b;  // equal positions: file order, so the first one leads its run
    };
    std::sort(order.begin(), order.end(), less);
    std::vector<std::uint32_t> rep(n);
    for (std::size_t i = 0; i < n; ++i) {
        const bool sameAsPrevious = i > 0 && mesh.positions[order[i]] == mesh.positions[order[i - 1]];
        rep[order[i]] = sameAsPrevious ? rep[order[i - 1]] : order[i];
    }
    return rep;
}

std::vector<std::uint32_t> toleranceRepresentatives(const Mesh& mesh, double tolerance) {
    // Grid of cells of the tolerance's size: a vertex within reach lies in one of the 27 cells
    // around its own.
    struct KeyHash {
        std::size_t operator()(const glm::i64vec3& k) const {
            return std::size_t(k.x * 73856093LL ^ k.y * 19349663LL ^ k.z * 83492791LL);
        }
    };
    std::unordered_map<glm::i64vec3, std::vector<std::uint32_t>, KeyHash> grid;
    const std::size_t n = mesh.positions.size();
    double maxAbs = 0.0;
    for (const glm::vec3& p : mesh.positions)
        maxAbs = std::max({maxAbs, std::abs(double(p.x)), std::abs(double(p.y)), std::abs(double(p.z))});
    if (maxAbs / tolerance > 1e15)  // cell indices must stay exact integers
        throw Error("weld tolerance " + std::to_string(tolerance) +
                    " mm is too small for coordinates up to " + std::to_string(maxAbs) + " mm");
    std::vector<std::uint32_t> rep(n, kUnset);
    auto cellOf = [&](const glm::vec3& p) {
        return glm::i64vec3(std::floor(p.x / tolerance), std::floor(p.y / tolerance),
                            std::floor(p.z / tolerance));
    };
    for (std::uint32_t v = 0; v < n; ++v) {
        const glm::vec3 p = mesh.positions[v];
        const glm::i64vec3 c = cellOf(p);
        std::uint32_t best = kUnset;
        for (int dz = -1; dz <= 1; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const auto it = grid.find(c + glm::i64vec3(dx, dy, dz));
                    if (it == grid.end()) continue;
                    for (std::uint32_t k : it->second) {
                        const glm::vec3 q = mesh.positions[k];
                        if (std::abs(double(p.x) - q.x) <= tolerance &&
                            std::abs(double(p.y) - q.y) <= tolerance &&
                            std::abs(double(p.z) - q.z) <= tolerance)
                            best = std::min(best, k);
                    }
                }
        if (best == kUnset) {
            rep[v] = v;
            grid[c].push_back(v);  // only kept vertices are candidates: no chains
        } else {
            rep[v] = best;
        }
    }
    return rep;
}

}  // namespace

Mesh weldVertices(const Mesh& mesh, double toleranceMm, WeldReport* report) {
    if (!(toleranceMm >= 0.0) || !std::isfinite(toleranceMm))
        throw Error("weld tolerance must be a finite number >= 0 mm, got " +
                    std::to_string(toleranceMm));
    const std::size_t n = mesh.positions.size();
    for (const auto& t : mesh.triangles)
        if (t.x >= n || t.y >= n || t.z >= n)
            throw Error("weldVertices: triangle index out of range");
    const std::vector<std::uint32_t> rep =
        toleranceMm == 0.0 ? exactRepresentatives(mesh) : toleranceRepresentatives(mesh, toleranceMm);

    // New indices in order of first use by the triangles: deterministic and cache-friendly.
    std::vector<std::uint32_t> newIndex(n, kUnset);
    Mesh out;
    std::size_t collapsed = 0;
    for (const auto& t : mesh.triangles) {
        const glm::uvec3 r(rep[t.x], rep[t.y], rep[t.z]);
        if (r.x == r.y || r.y == r.z || r.x == r.z) {
            ++collapsed;
            continue;
        }
        glm::uvec3 nt;
        for (int k = 0; k < 3; ++k) {
            if (newIndex[r[k]] == kUnset) {
                newIndex[r[k]] = static_cast<std::uint32_t>(out.positions.size());
                out.positions.push_back(mesh.positions[r[k]]);
            }
            nt[k] = newIndex[r[k]];
        }
        out.triangles.push_back(nt);
    }
    if (report) {
        report->verticesBefore = n;
        report->verticesAfter = out.positions.size();
        report->collapsedTriangles = collapsed;
    }
    return out;
}

}  // namespace fm

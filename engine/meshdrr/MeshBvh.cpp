#include "meshdrr/MeshBvh.h"

#include <algorithm>
#include <array>
#include <limits>
#include <numeric>

#include "core/Error.h"

namespace fm {
namespace {

constexpr int kBins = 16;
constexpr std::uint32_t kLeafSize = 4;
constexpr std::uint32_t kMaxLeafSize = 16;  // a leaf may grow to this when no split pays
constexpr int kMaxSahDepth = 48;

struct Box {
    glm::dvec3 lo{std::numeric_limits<double>::infinity()};
    glm::dvec3 hi{-std::numeric_limits<double>::infinity()};
    void grow(const glm::dvec3& p) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    void grow(const Box& b) {
        lo = glm::min(lo, b.lo);
        hi = glm::max(hi, b.hi);
    }
    double halfArea() const {
        if (lo.x > hi.x) return 0.0;
        const glm::dvec3 e = hi - lo;
        return e.x * e.y + e.y * e.z + e.z * e.x;
    }
};

struct Builder {
    const std::vector<Box>& boxes;
    const std::vector<glm::dvec3>& centroids;
    std::vector<std::uint32_t>& order;  // triangle indices, permuted into leaf order
    std::vector<MeshBvh::Node>& nodes;
    int maxDepth = 0;

    std::uint32_t build(std::uint32_t begin, std::uint32_t end, int depth) {
        maxDepth = std::max(maxDepth, depth);
        const auto self = static_cast<std::uint32_t>(nodes.size());
        nodes.emplace_back();
        Box bounds, centroidBounds;
        for (std::uint32_t i = begin; i < end; ++i) {
            bounds.grow(boxes[order[i]]);
            centroidBounds.grow(centroids[order[i]]);
        }
        nodes[self].lo = bounds.lo;
        nodes[self].hi = bounds.hi;
        const std::uint32_t count = end - begin;
        if (count <= kLeafSize) return makeLeaf(self, begin, count);

        const glm::dvec3 spread = centroidBounds.hi - centroidBounds.lo;
        const int axis = spread.x >= spread.y ? (spread.x >= spread.z ? 0 : 2)
                                              : (spread.y >= spread.z ? 1 : 2);
        std::uint32_t mid = begin + count / 2;
        bool split = false;
        if (spread[axis] > 0.0 && depth < kMaxSahDepth) {
            std::array<Box, kBins> binBox;
            std::array<std::uint32_t, kBins> binCount{};
            const double scale = kBins / spread[axis];
            auto binOf = [&](std::uint32_t t) {
                const int b = static_cast<int>((centroids[t][axis] - centroidBounds.lo[axis]) * scale);
                return std::clamp(b, 0, kBins - 1);
            };
            for (std::uint32_t i = begin; i < end; ++i) {
                const int b = binOf(order[i]);
                binBox[b].grow(boxes[order[i]]);
                ++binCount[b];
            }
            // Sweep: cost of splitting after bin k = area(left) n(left) + area(right) n(right).
            std::array<double, kBins - 1> leftCost{};
            Box acc;
            std::uint32_t n = 0;
            for (int k = 0; k < kBins - 1; ++k) {
                acc.grow(binBox[k]);
                n += binCount[k];
                leftCost[k] = acc.halfArea() * n;
            }
            acc = Box();
            n = 0;
            double best = std::numeric_limits<double>::infinity();
            int bestK = -1;
            for (int k = kBins - 2; k >= 0; --k) {
                acc.grow(binBox[k + 1]);
                n += binCount[k + 1];
                const double cost = leftCost[k] + acc.halfArea() * n;
                if (n > 0 && n < count && cost < best) {  // '<' from the top: ties go high
                    best = cost;
                    bestK = k;
                }
            }
            const double leafCost = bounds.halfArea() * count;
            if (bestK >= 0 && (best < leafCost || count > kMaxLeafSize)) {
                const auto it = std::partition(order.begin() + begin, order.begin() + end,
                                               [&](std::uint32_t t) { return binOf(t) <= bestK; });
                mid = static_cast<std::uint32_t>(it - order.begin());
                split = mid > begin && mid < end;
            } else if (bestK >= 0 && count <= kMaxLeafSize) {
                return makeLeaf(self, begin, count);
            }
        }
        if (!split) {
            // Coincident centroids or too deep: halves by the current order (always shrinks).
            if (count <= kMaxLeafSize && spread[axis] == 0.0) return makeLeaf(self, begin, count);
            mid = begin + count / 2;
        }
        build(begin, mid, depth + 1);
        nodes[self].first = build(mid, end, depth + 1);
        return self;
    }

    std::uint32_t makeLeaf(std::uint32_t self, std::uint32_t begin, std::uint32_t count) {
        nodes[self].first = begin;
        nodes[self].count = count;
        return self;
    }
};

}  // namespace

MeshBvh buildMeshBvh(const Mesh& mesh) {
    const std::size_t n = mesh.triangles.size();
    if (n == 0) throw Error("mesh DRR: the mesh has no triangle");
    if (n >= (std::size_t(1) << 31)) throw Error("mesh DRR: too many triangles");
    std::vector<Box> boxes(n);
    std::vector<glm::dvec3> centroids(n);
    for (std::size_t t = 0; t < n; ++t) {
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t v = mesh.triangles[t][k];
            if (v >= mesh.positions.size()) throw Error("mesh DRR: triangle index out of range");
            boxes[t].grow(glm::dvec3(mesh.positions[v]));
        }
        centroids[t] = 0.5 * (boxes[t].lo + boxes[t].hi);
    }
    MeshBvh bvh;
    std::vector<std::uint32_t> order(n);
    std::iota(order.begin(), order.end(), 0u);
    bvh.nodes.reserve(2 * n / kLeafSize + 1);
    Builder builder{boxes, centroids, order, bvh.nodes};
    builder.build(0, static_cast<std::uint32_t>(n), 0);
    bvh.depth = builder.maxDepth;
    bvh.triangleOfSlot = order;
    bvh.corners.resize(3 * n);
    for (std::size_t s = 0; s < n; ++s)
        for (int k = 0; k < 3; ++k)
            bvh.corners[3 * s + k] = glm::dvec3(mesh.positions[mesh.triangles[order[s]][k]]);
    return bvh;
}

}  // namespace fm

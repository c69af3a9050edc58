#include "bones/ConnectedComponents.h"

#include <algorithm>
#include <cmath>

#include "bones/LabelMap.h"
#include "core/Error.h"

namespace fm {

std::size_t floodComponent(const glm::ivec3& dims, const std::vector<std::uint8_t>& inside,
                           std::size_t seed, std::int32_t id, std::vector<std::int32_t>& component) {
    if (!inside[seed] || component[seed] != 0) return 0;
    const std::size_t sx = 1, sy = static_cast<std::size_t>(dims.x),
                      sz = sy * static_cast<std::size_t>(dims.y);
    std::vector<std::size_t> stack{seed};
    component[seed] = id;
    std::size_t count = 0;
    while (!stack.empty()) {
        const std::size_t n = stack.back();
        stack.pop_back();
        ++count;
        const int i = static_cast<int>(n % sy), j = static_cast<int>((n / sy) % dims.y),
                  k = static_cast<int>(n / sz);
        auto visit = [&](bool ok, std::size_t m) {
            if (ok && inside[m] && component[m] == 0) {
                component[m] = id;
                stack.push_back(m);
            }
        };
        visit(i > 0, n - sx);
        visit(i + 1 < dims.x, n + sx);
        visit(j > 0, n - sy);
        visit(j + 1 < dims.y, n + sy);
        visit(k > 0, n - sz);
        visit(k + 1 < dims.z, n + sz);
    }
    return count;
}

Volume labelConnectedComponents(const Volume& ct, const ComponentOptions& options) {
    ct.validate("CT");
    if (!std::isfinite(options.threshold)) throw Error("components: the threshold must be finite");
    if (options.maxComponents < 1 || options.maxComponents > kMaxLabel)
        throw Error("components: at most 1.." + std::to_string(kMaxLabel) + " components");
    const std::size_t count = ct.voxelCount();
    std::vector<std::uint8_t> inside(count);
    for (std::size_t n = 0; n < count; ++n) inside[n] = ct.values[n] >= options.threshold;
    std::vector<std::int32_t> component(count, 0);
    struct Piece {
        std::size_t first, size;
        std::int32_t id;
    };
    std::vector<Piece> pieces;
    for (std::size_t n = 0; n < count; ++n) {
        if (!inside[n] || component[n] != 0) continue;
        const auto id = static_cast<std::int32_t>(pieces.size() + 1);
        pieces.push_back({n, floodComponent(ct.dims, inside, n, id, component), id});
    }
    std::stable_sort(pieces.begin(), pieces.end(),
                     [](const Piece& a, const Piece& b) { return a.size > b.size; });
    std::vector<float> rankOf(pieces.size() + 1, 0.0f);
    int kept = 0;
    for (const Piece& p : pieces) {
        if (p.size < options.minVoxels || kept >= options.maxComponents) break;
        rankOf[static_cast<std::size_t>(p.id)] = static_cast<float>(++kept);
    }
    Volume out = ct;
    out.meta.description = "connected components of " + ct.meta.source + " at " +
                           std::to_string(options.threshold);
    for (std::size_t n = 0; n < count; ++n)
        out.values[n] = rankOf[static_cast<std::size_t>(component[n])];
    return out;
}

LabelTable componentLabelTable(const Volume& componentLabels) {
    LabelTable table;
    for (const auto& [label, voxels] : labelVoxelCounts(componentLabels))
        if (label != 0) table.entries.push_back({"component " + std::to_string(label), label});
    return table;
}

}  // namespace fm

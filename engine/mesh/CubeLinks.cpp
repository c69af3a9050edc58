#include "mesh/CubeLinks.h"

#include <stdexcept>
#include <utility>
#include <vector>

#include "mesh/MarchingCubesTable.h"

namespace fm::mc {
namespace {

// The face both edges lie on, or -1 (two cube edges share at most one face).
int commonFace(int a, int b) {
    for (int f = 0; f < 6; ++f)
        if (edgeOnFace(a, f) && edgeOnFace(b, f)) return f;
    return -1;
}

CubeLinks buildLinks(const CubeCase& c) {
    // Loop segments are the triangle sides on a cube face: fan chords never join two points on
    // a common face (mesh/MarchingCubesTable.h), and each segment is a side of one triangle.
    std::array<std::vector<int>, 12> next;  // upper-face segments at each edge
    for (int t = 0; t < c.triangleCount; ++t)
        for (int s = 0; s < 3; ++s) {
            const int a = c.triangles[t][s], b = c.triangles[t][(s + 1) % 3];
            const int f = commonFace(a, b);
            if (f < 0 || f % 2 == 0) continue;  // a chord, or a lower face (f = 2 axis + side)
            next[a].push_back(b);
            next[b].push_back(a);
        }
    CubeLinks links;
    std::array<bool, 12> done{};
    auto add = [&](int e, bool start) {
        if (links.count >= links.steps.size()) throw std::logic_error("cube links: too many steps");
        links.steps[links.count++] = static_cast<std::uint8_t>(
            e | (start ? CubeLinks::kPathStart : 0) |
            (e == 3 || e == 7 || e == 11 ? CubeLinks::kFirstCube : 0));
    };
    // Walks a path (or a cycle, less its closing segment) from `e`.
    auto walk = [&](int e) {
        add(e, true);
        done[e] = true;
        for (;;) {
            int to = -1;
            for (int n : next[e])
                if (!done[n]) to = n;
            if (to < 0) return;
            add(to, false);
            done[to] = true;
            e = to;
        }
    };
    for (int e = 0; e < 12; ++e) {
        if (next[e].size() > 2) throw std::logic_error("cube links: a vertex with three segments");
        if (next[e].size() == 1 && !done[e]) walk(e);  // path ends first
    }
    for (int e = 0; e < 12; ++e)
        if (next[e].size() == 2 && !done[e]) walk(e);  // what is left are cycles
    return links;
}

}  // namespace

const std::array<CubeLinks, 256>& cubeLinks() {
    static const std::array<CubeLinks, 256> table = [] {
        std::array<CubeLinks, 256> t;
        const auto& cases = cubeCases();
        for (int c = 0; c < 256; ++c) t[c] = buildLinks(cases[c]);
        return t;
    }();
    return table;
}

}  // namespace fm::mc

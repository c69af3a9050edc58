#include "common/TestMeshes.h"

#include <cmath>
#include <utility>

namespace fm::test {

namespace {
void addQuad(Mesh& m, unsigned a, unsigned b, unsigned c, unsigned d) {  // counter-clockwise
    m.triangles.push_back(glm::uvec3(a, b, c));
    m.triangles.push_back(glm::uvec3(a, c, d));
}
}  // namespace

Mesh boxMesh(const glm::vec3& lo, const glm::vec3& hi) {
    Mesh m;
    for (int k = 0; k < 8; ++k)
        m.positions.push_back(glm::vec3((k & 1) ? hi.x : lo.x, (k & 2) ? hi.y : lo.y,
                                        (k & 4) ? hi.z : lo.z));
    // Faces counter-clockwise seen from outside.
    addQuad(m, 0, 2, 3, 1);  // z = lo (normal -z)
    addQuad(m, 4, 5, 7, 6);  // z = hi
    addQuad(m, 0, 1, 5, 4);  // y = lo
    addQuad(m, 2, 6, 7, 3);  // y = hi
    addQuad(m, 0, 4, 6, 2);  // x = lo
    addQuad(m, 1, 3, 7, 5);  // x = hi
    return m;
}

Mesh uvSphereMesh(const glm::vec3& center, float radius, int rings, int segments,
                  bool planarQuads) {
    Mesh m;
    const double pi = std::acos(-1.0);
    auto q = [&](double v, double step) { return planarQuads ? std::round(v / step) * step : v; };
    m.positions.push_back(center + glm::vec3(0, 0, float(-q(radius, 1.0 / 64))));  // south pole: 0
    for (int i = 1; i < rings; ++i) {
        const double theta = pi * i / rings;  // from the south pole
        const double r = q(radius * std::sin(theta), 1.0 / 64), z = q(-radius * std::cos(theta), 1.0 / 64);
        for (int j = 0; j < segments; ++j) {
            const double phi = 2 * pi * j / segments;
            const double c = q(std::cos(phi), 1.0 / 4096), s = q(std::sin(phi), 1.0 / 4096);
            m.positions.push_back(center + glm::vec3(float(r * c), float(r * s), float(z)));
        }
    }
    const unsigned north = static_cast<unsigned>(m.positions.size());
    m.positions.push_back(center + glm::vec3(0, 0, float(q(radius, 1.0 / 64))));
    auto ring = [&](int i, int j) { return 1u + unsigned((i - 1) * segments + (j % segments)); };
    for (int j = 0; j < segments; ++j) m.triangles.push_back(glm::uvec3(0, ring(1, j + 1), ring(1, j)));
    for (int i = 1; i + 1 < rings; ++i)
        for (int j = 0; j < segments; ++j)
            addQuad(m, ring(i, j), ring(i, j + 1), ring(i + 1, j + 1), ring(i + 1, j));
    for (int j = 0; j < segments; ++j)
        m.triangles.push_back(glm::uvec3(north, ring(rings - 1, j), ring(rings - 1, j + 1)));
    return m;
}

Mesh cylinderMesh(float radius, float z0, float z1, int segments) {
    Mesh m;
    const double pi = std::acos(-1.0);
    for (int j = 0; j < segments; ++j) {
        const double phi = 2 * pi * j / segments;
        const float x = float(radius * std::cos(phi)), y = float(radius * std::sin(phi));
        m.positions.push_back(glm::vec3(x, y, z0));
        m.positions.push_back(glm::vec3(x, y, z1));
    }
    const unsigned bottom = static_cast<unsigned>(m.positions.size());
    m.positions.push_back(glm::vec3(0, 0, z0));
    m.positions.push_back(glm::vec3(0, 0, z1));
    const unsigned top = bottom + 1;
    for (int j = 0; j < segments; ++j) {
        const unsigned a0 = 2 * j, a1 = 2 * j + 1, b0 = 2 * ((j + 1) % segments), b1 = b0 + 1;
        addQuad(m, a0, b0, b1, a1);
        m.triangles.push_back(glm::uvec3(bottom, b0, a0));
        m.triangles.push_back(glm::uvec3(top, a1, b1));
    }
    return m;
}

Mesh squareFrameMesh(float outer, float inner, float z0, float z1) {
    Mesh m;
    // Corners counter-clockwise (seen from +z): outer o0..o3, inner i0..i3, at z0 then z1.
    const float xs[4] = {-1, 1, 1, -1}, ys[4] = {-1, -1, 1, 1};
    for (float z : {z0, z1})
        for (float s : {outer, inner})
            for (int k = 0; k < 4; ++k) m.positions.push_back(glm::vec3(s * xs[k], s * ys[k], z));
    auto o = [](int level, int k) { return unsigned(level * 8 + (k % 4)); };
    auto i = [](int level, int k) { return unsigned(level * 8 + 4 + (k % 4)); };
    for (int k = 0; k < 4; ++k) {
        addQuad(m, o(1, k), o(1, k + 1), i(1, k + 1), i(1, k));  // top ring, normal +z
        addQuad(m, o(0, k), i(0, k), i(0, k + 1), o(0, k + 1));  // bottom ring, normal -z
        addQuad(m, o(0, k), o(0, k + 1), o(1, k + 1), o(1, k));  // outer wall, outward
        addQuad(m, i(0, k), i(1, k), i(1, k + 1), i(0, k + 1));  // hole wall, into the hole
    }
    return m;
}

Mesh mergeMeshes(const Mesh& a, const Mesh& b) {
    Mesh m = a;
    const unsigned shift = static_cast<unsigned>(a.positions.size());
    for (const auto& p : b.positions) m.positions.push_back(p);
    for (const auto& t : b.triangles) m.triangles.push_back(t + glm::uvec3(shift));
    m.normals.clear();
    return m;
}

Mesh flippedMesh(const Mesh& m) {
    Mesh f = m;
    for (auto& t : f.triangles) std::swap(t.y, t.z);
    return f;
}

}  // namespace fm::test

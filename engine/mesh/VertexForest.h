#pragma once
// Union-find over mesh vertex ids, the smaller id always the root: every set's root is its
// smallest vertex whatever order the unions come in, so labels built from it do not depend on
// how the unions were split between threads. Every parent is at most its vertex (parent[v] <= v).
#include <cstdint>
#include <limits>

#include <glm/glm.hpp>

namespace fm {

inline std::uint32_t forestRoot(std::uint32_t* parent, std::uint32_t v) {
    while (parent[v] != v) {
        parent[v] = parent[parent[v]];  // path halving
        v = parent[v];
    }
    return v;
}

// Unites the sets of a and b (the smaller root becomes the root of both).
inline void forestUnite(std::uint32_t* parent, std::uint32_t a, std::uint32_t b) {
    const std::uint32_t ra = forestRoot(parent, a), rb = forestRoot(parent, b);
    if (ra < rb)
        parent[rb] = ra;
    else if (rb < ra)
        parent[ra] = rb;
}

// Unites the vertices of triangles fed one after the other. Marching cubes writes each loop of
// a cube as a fan (the same first vertex, each triangle sharing a second vertex with the one
// before), so the first vertex's root is found once per fan and a vertex the previous triangle
// already joined is skipped: about one root search per vertex instead of four per triangle.
class TriangleUnion {
  public:
    explicit TriangleUnion(std::uint32_t* parent) : parent_(parent) {}

    void add(const glm::uvec3& t) {
        if (t.x != apex_) {
            apex_ = t.x;
            root_ = forestRoot(parent_, t.x);
        } else if (t.y == previous_.y || t.y == previous_.z) {
            join(t.z);  // a fan: y is in the apex's set already
            previous_ = t;
            return;
        }
        join(t.y);
        join(t.z);
        previous_ = t;
    }
    // The next triangle is not a neighbour of the last one added (one was skipped).
    void restart() { apex_ = kNone; }

  private:
    static constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

    void join(std::uint32_t v) {
        const std::uint32_t r = forestRoot(parent_, v);
        if (r > root_) {
            parent_[r] = root_;
        } else if (r < root_) {
            parent_[root_] = r;
            root_ = r;
        }
    }

    std::uint32_t* parent_;
    std::uint32_t apex_ = kNone, root_ = 0;
    glm::uvec3 previous_{kNone};
};

}  // namespace fm

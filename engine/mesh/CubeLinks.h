#pragma once
// What the component labelling of marching cubes unites per cube: the loop segments on the
// cube's three upper faces (x, y or z offset 1), as paths of edge numbers.
// Why that is enough: triangles sharing a vertex are connected exactly when their loops are
// joined by a chain of loop segments (a loop's triangles cover its vertices only); every segment
// lies on a cube face and both cubes of a face draw the same segments there (the face rule in
// mesh/MarchingCubesTable.h); and every face is the upper face of exactly one of its two cubes.
// So uniting the upper-face segments of every cube unites each segment once, about two finds per
// vertex instead of the four of uniting every triangle's vertices (docs/marching-cubes.md).
#include <array>
#include <cstdint>

namespace fm::mc {

struct CubeLinks {
    // Steps: an edge number (bits 0-3) with flags. kPathStart begins a path (the vertex is
    // found, not united); every other step unites its vertex with the path so far. kFirstCube:
    // the edge is 3, 7 or 11 (at corner 7), whose vertex no cube before this one in x-fastest,
    // then y, then z order has: its set is still the vertex alone.
    static constexpr std::uint8_t kPathStart = 0x10;
    static constexpr std::uint8_t kFirstCube = 0x20;
    std::uint8_t count = 0;
    std::array<std::uint8_t, 24> steps{};
};

// Per case number (as in mc::cubeCases()); built once.
const std::array<CubeLinks, 256>& cubeLinks();

}  // namespace fm::mc

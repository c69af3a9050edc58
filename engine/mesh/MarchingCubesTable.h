#pragma once
// The marching-cubes case table, generated at start-up from one rule instead of typed in, so
// that neighbouring cubes always agree (see docs/marching-cubes.md):
// - a corner is inside when its value >= iso;
// - on a face whose two inside corners are diagonal ("ambiguous face"), the inside corners are
//   separated (each gets its own segment), in every cube alike, so both cubes sharing a face
//   draw the same segments there;
// - each cube's segments chain into closed loops on the cube's boundary; each loop becomes a
//   fan from one of its points such that no fan chord joins two points on a common cube face
//   (such a chord would lie in the face and could meet the neighbour's triangles; without
//   such chords the fan provably cannot cross itself). Every loop of all 256 cases has one.
// Triangles are counter-clockwise seen from outside (from the lower values) in index space.
#include <array>
#include <cstdint>

namespace fm::mc {

// Corner c of a cube sits at offset (c & 1, (c >> 1) & 1, (c >> 2) & 1).
// Edge e runs along axis a = e / 4 from its lower corner; the other two axes' offsets are the
// bits of e % 4 (lower axis first). Triangle corners are edge numbers.
inline constexpr int kMaxTriangles = 5;  // the most any case needs (checked at start-up)

struct CubeCase {
    std::uint8_t triangleCount = 0;
    std::uint16_t edgeMask = 0;  // edges whose corners lie on different sides of the iso
    std::array<std::array<std::uint8_t, 3>, kMaxTriangles> triangles{};
};

// Table indexed by the case number: bit c set when corner c is inside.
const std::array<CubeCase, 256>& cubeCases();

int edgeAxis(int edge);
// The lower (0) or upper (1) corner of an edge.
int edgeCorner(int edge, int end);
// Face f = 2 * axis + side holds the corners whose `axis` offset equals `side`.
bool edgeOnFace(int edge, int face);

}  // namespace fm::mc

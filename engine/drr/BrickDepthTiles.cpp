#include "drr/BrickDepthTiles.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/Error.h"

namespace fm {

namespace {

// Widening of each range, relative: the walk computes alphas in the volume's frame, the tiles
// in the world, so the two may disagree by rounding (~1e-15); a wider range only walks more
// empty voxels.
constexpr double kSlack = 1e-9;

}  // namespace

std::optional<BrickDepthTiles> brickDepthTiles(const DrrVolume& v, const ProjectionGeometry& g,
                                               int col0, int col1, int row0, int row1, TileBlocks blocks) {
    if (v.bricksEmpty == 0 || col1 <= col0 || row1 <= row0) return std::nullopt;
    const DetectorGeometry& det = g.detector;
    const glm::dvec3 n = glm::cross(det.u, det.v);
    const double planeDistance = glm::dot(det.origin - g.source, n);
    if (!(std::abs(planeDistance) > 0.0)) return std::nullopt;

    // 1. The block corners (a lattice, the last corner of each axis at the box's end), projected:
    // pixel column, row and alpha (depth / the detector plane's depth). World positions step
    // along the lattice by whole blocks (an affine map).
    if (blocks == TileBlocks::HalfBricks && v.occupiedHalfBricks.empty())
        throw Error("DRR tiles: the volume has no half-bricks (too many, or no empty brick)");
    const double rays = double(col1 - col0) * double(row1 - row0);
    const bool halfBricks = blocks == TileBlocks::HalfBricks ||
                            (blocks == TileBlocks::Auto && !v.occupiedHalfBricks.empty() &&
                             rays >= kRaysPerHalfBrick * double(v.occupiedHalfBricks.size()));
    const int size = halfBricks ? v.brickSize / 2 : v.brickSize;
    const std::vector<glm::u16vec3>& occupied = halfBricks ? v.occupiedHalfBricks : v.occupiedBricks;
    const glm::ivec3 corners = (v.dims + (size - 1)) / size + 1;
    const glm::dmat3 localToWorld = glm::inverse(v.worldToLocal);
    auto edge = [&](int a, int index) {  // local coordinate of lattice plane `index` along a
        return std::min(index * size, v.dims[a]) * v.spacing[a];
    };
    const glm::dvec3 base = localToWorld * (-v.localShift) + v.origin - g.source;
    std::vector<glm::dvec3> projected(static_cast<std::size_t>(corners.x) * corners.y * corners.z);
    std::size_t at = 0;
    for (int k = 0; k < corners.z; ++k)
        for (int j = 0; j < corners.y; ++j) {
            const glm::dvec3 row = base + localToWorld[1] * edge(1, j) + localToWorld[2] * edge(2, k);
            for (int i = 0; i < corners.x; ++i, ++at) {
                const glm::dvec3 w = row + localToWorld[0] * edge(0, i);
                const double along = glm::dot(w, n);
                if (!(along * planeDistance > 0.0)) return std::nullopt;  // behind or beside the source
                const glm::dvec3 p = (planeDistance / along) * w + g.source - det.origin;
                projected[at] = {glm::dot(p, det.u) / det.spacing.x, glm::dot(p, det.v) / det.spacing.y,
                                 along / planeDistance};
            }
        }

    // 2. Each non-empty block widens the alpha range of every tile its corners' box touches
    // (one pixel of margin for rounding; the projection of a box lies inside its corners' box).
    BrickDepthTiles t;
    const int T = BrickDepthTiles::kTileSize;
    t.col0 = col0;
    t.row0 = row0;
    t.tilesX = (col1 - col0 + T - 1) / T;
    t.tilesY = (row1 - row0 + T - 1) / T;
    const std::size_t tiles = static_cast<std::size_t>(t.tilesX) * t.tilesY;
    t.alphaLo.assign(tiles, std::numeric_limits<double>::infinity());
    t.alphaHi.assign(tiles, -std::numeric_limits<double>::infinity());
    for (const glm::u16vec3& brick : occupied) {
        const int bi = brick.x, bj = brick.y, bk = brick.z;
        glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
        for (int c = 0; c < 8; ++c) {
            const glm::dvec3& p =
                projected[(bi + (c & 1)) + static_cast<std::size_t>(corners.x) *
                                               ((bj + ((c >> 1) & 1)) +
                                                static_cast<std::size_t>(corners.y) * (bk + (c >> 2)))];
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
        // Tiles whose pixel centres may lie in [lo - 1, hi + 1], clamped to the range.
        const int c0 = std::max(col0, static_cast<int>(std::floor(lo.x)) - 1);
        const int c1 = std::min(col1 - 1, static_cast<int>(std::ceil(hi.x)) + 1);
        const int r0 = std::max(row0, static_cast<int>(std::floor(lo.y)) - 1);
        const int r1 = std::min(row1 - 1, static_cast<int>(std::ceil(hi.y)) + 1);
        if (c0 > c1 || r0 > r1) continue;
        const double aLo = lo.z * (1.0 - kSlack), aHi = hi.z * (1.0 + kSlack);
        for (int tr = (r0 - row0) / T; tr <= (r1 - row0) / T; ++tr)
            for (int tc = (c0 - col0) / T; tc <= (c1 - col0) / T; ++tc) {
                const std::size_t i = static_cast<std::size_t>(tr) * t.tilesX + tc;
                t.alphaLo[i] = std::min(t.alphaLo[i], aLo);
                t.alphaHi[i] = std::max(t.alphaHi[i], aHi);
            }
    }
    return t;
}

}  // namespace fm

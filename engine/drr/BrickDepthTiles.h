#pragma once
// Empty-space skipping for the dense walk, per render: which part of each pixel's ray can meet
// a non-empty voxel. Every non-empty block (DrrVolume's occupied bricks, or half-bricks where a
// render has rays enough for them) is projected onto the detector; each
// tile of tileSize x tileSize pixels its projection may touch takes the block's depth range
// (distance from the source along the detector normal). A point's depth is proportional to its
// ray parameter alpha (every pixel lies in the detector plane), so a tile's depth range is an
// alpha range that holds every non-empty voxel the tile's rays cross: a ray walks only that range,
// and a ray of a tile no non-empty brick touches is not walked at all. The voxels left out are
// empty, so sums change only by the rounding of the crossing parameters.
// (A cropped bone leaves most of its box empty: on the wrist radius 60 % of the voxel steps lie
// outside the non-empty bricks.)
#include <optional>
#include <vector>

#include "drr/DrrVolume.h"
#include "geometry/ProjectionGeometry.h"

namespace fm {

struct BrickDepthTiles {
    static constexpr int kTileSize = 4;  // pixels: coarse enough to fill cheaply
    int col0 = 0, row0 = 0;              // pixel of tile (0, 0)'s first corner
    int tilesX = 0, tilesY = 0;
    std::vector<double> alphaLo, alphaHi;  // per tile; lo > hi: no non-empty brick

    std::size_t tileOf(int col, int row) const {
        return static_cast<std::size_t>((row - row0) / kTileSize) * tilesX +
               static_cast<std::size_t>((col - col0) / kTileSize);
    }
    // No non-empty brick can meet pixel (col, row)'s ray: it need not even be set up.
    bool empty(int col, int row) const {
        const std::size_t t = tileOf(col, row);
        return alphaLo[t] > alphaHi[t];
    }
    // Narrows [aMin, aMax] to the range of pixel (col, row)'s tile; false if nothing is left.
    bool clip(int col, int row, double& aMin, double& aMax) const {
        const std::size_t t = tileOf(col, row);
        if (alphaLo[t] > aMin) aMin = alphaLo[t];
        if (alphaHi[t] < aMax) aMax = alphaHi[t];
        return aMax > aMin;
    }
};

// Which blocks the tiles are built from (DrrVolume::occupiedBricks / occupiedHalfBricks).
enum class TileBlocks {
    // The half-bricks when the volume has them and the tiles' pixels are at least
    // kRaysPerHalfBrick per half-brick (the tiles project every block's corners per render: on the
    // wrist's coarse tracking levels, a few thousand rays, that cost more than it saved), else
    // the bricks.
    Auto,
    Bricks,
    HalfBricks,  // fm::Error when the volume has none (tests compare the two)
};
inline constexpr double kRaysPerHalfBrick = 4.0;

// The tiles for pixels [col0, col1) x [row0, row1) of `g`. nullopt when they would not help (no
// empty brick) or cannot be made (a block corner not strictly in front of the source).
std::optional<BrickDepthTiles> brickDepthTiles(const DrrVolume& v, const ProjectionGeometry& g,
                                               int col0, int col1, int row0, int row1,
                                               TileBlocks blocks = TileBlocks::Auto);

}  // namespace fm

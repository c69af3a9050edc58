// The per-tile alpha ranges of the dense walk's empty-space skipping (drr/BrickDepthTiles.h)
// against the definition: every point of a pixel's ray that lies in a non-zero voxel has its
// alpha inside the pixel's tile range. Checked by sampling the rays finely, on a volume whose
// non-zero voxels fill whole bricks (so the ranges are tight at the bricks' corners) and a speck,
// with tiles from the bricks and from the half-bricks.
#include <cmath>

#include <gtest/gtest.h>

#include "DrrTestUtil.h"
#include "core/Error.h"
#include "drr/BrickDepthTiles.h"
#include "drr/Drr.h"
#include "drr/DrrVolume.h"

namespace {

TEST(BrickDepthTiles, EveryNonEmptyVoxelOfARayIsInItsTileRange) {
    fm::Volume volume = fm::test::makeVolume({40, 36, 44}, {0.8, 0.9, 1.25}, 0.0f, {2.0, -1.0, 4.0},
                                             fm::test::rotation(23.0, {0.3, 1.0, 0.2}));
    auto at = [&](int i, int j, int k) -> float& {
        return volume.values[i + 40 * (j + 36 * std::size_t(k))];
    };
    for (int k = 8; k < 32; ++k)  // whole bricks [8, 24) x [8, 24) x [8, 32), a step in them
        for (int j = 8; j < 24; ++j)
            for (int i = 8; i < (k < 16 ? 24 : 16); ++i) at(i, j, k) = 1.0f + 0.01f * float(i + j);
    at(37, 2, 41) = 3.0f;
    fm::DrrValueOptions raw;
    raw.values = fm::DrrValues::Raw;
    raw.cropToContent = false;  // keep the empty border bricks
    const fm::DrrVolumePtr v = fm::prepareDrrVolume(volume, raw);
    ASSERT_GT(v->bricksEmpty, v->brickMixed.size() / 2);
    // The half-bricks (4 voxels) too: the volume is small enough to keep them.
    ASSERT_FALSE(v->occupiedHalfBricks.empty());
    ASSERT_LE(v->occupiedHalfBricks.size(), 8 * v->occupiedBricks.size());
    double meanSlack[2] = {0.0, 0.0};
    for (const bool halfBricks : {false, true}) {
        SCOPED_TRACE(halfBricks ? "half-bricks" : "bricks");
        int sampled = 0, skipped = 0;
        double slackSum = 0.0;
        for (double azimuth : {0.0, 41.0, 130.0, 215.0}) {
            const fm::ProjectionGeometry g =
                fm::test::orbitGeometry(volume.center(), azimuth, -17.0, 200.0, 150.0, 64, 1.0);
            const auto tiles = fm::brickDepthTiles(*v, g, 0, 64, 0, 64,
                                                   halfBricks ? fm::TileBlocks::HalfBricks : fm::TileBlocks::Bricks);
            ASSERT_TRUE(tiles);
            for (int row = 0; row < 64; ++row)
                for (int col = 0; col < 64; ++col) {
                    double lo = 0.0, hi = 1.0;
                    const bool walked = tiles->clip(col, row, lo, hi);
                    const glm::dvec3 pixel = g.detector.pixelCenter(col, row);
                    double first = 2.0, last = -1.0;
                    for (int s = 0; s <= 4000; ++s) {
                        const double alpha = s / 4000.0;
                        const glm::dvec3 ijk =
                            volume.worldToIndex(g.source + alpha * (pixel - g.source)) + 0.5;
                        const int i = int(std::floor(ijk.x)), j = int(std::floor(ijk.y)),
                                  k = int(std::floor(ijk.z));
                        if (i < 0 || j < 0 || k < 0 || i >= 40 || j >= 36 || k >= 44 || at(i, j, k) == 0.0f)
                            continue;
                        first = std::min(first, alpha);
                        last = std::max(last, alpha);
                    }
                    if (last < 0.0) {
                        skipped += !walked;
                        continue;
                    }
                    ASSERT_TRUE(walked) << azimuth << ": " << col << "," << row;
                    ASSERT_LE(lo, first) << azimuth << ": " << col << "," << row;
                    ASSERT_GE(hi, last) << azimuth << ": " << col << "," << row;
                    slackSum += (first - lo) + (hi - last);
                    ++sampled;
                }
        }
        EXPECT_GT(sampled, 2000);
        EXPECT_GT(skipped, 2000);  // rays beside the block are not walked at all
        // Tight: on average the range exceeds the non-empty part by about a brick's depth
        // (8 voxels ~ 8 mm of a 350 mm ray is alpha 0.023, at both ends together).
        meanSlack[halfBricks] = slackSum / sampled;
        EXPECT_LT(meanSlack[halfBricks], 0.1);
    }
    // Half-bricks hug the step and the speck closer than whole bricks do.
    EXPECT_LT(meanSlack[1], 0.8 * meanSlack[0]) << meanSlack[1] << " against " << meanSlack[0];
}

TEST(BrickDepthTiles, NoTilesWithoutEmptyBricksOrWithTheSourceInside) {
    fm::Volume volume = fm::test::makeVolume({20, 20, 20}, {1.0, 1.0, 1.0}, 1.0f);
    fm::DrrValueOptions raw;
    raw.values = fm::DrrValues::Raw;
    const fm::DrrVolumePtr full = fm::prepareDrrVolume(volume, raw);
    const fm::ProjectionGeometry g = fm::test::orbitGeometry(volume.center(), 0.0, 0.0, 200.0, 150.0, 32, 1.0);
    EXPECT_FALSE(fm::brickDepthTiles(*full, g, 0, 32, 0, 32));  // nothing to skip
    volume.values.assign(volume.values.size(), 0.0f);
    volume.values[5 + 20 * (5 + 20 * 5)] = 1.0f;
    fm::DrrValueOptions keep = raw;
    keep.cropToContent = false;
    const fm::DrrVolumePtr sparse = fm::prepareDrrVolume(volume, keep);
    EXPECT_TRUE(fm::brickDepthTiles(*sparse, g, 0, 32, 0, 32));
    // Bricks of an odd edge have no half-bricks: asked for them, the tiles refuse.
    fm::DrrValueOptions odd = keep;
    odd.brickSize = 3;
    const fm::DrrVolumePtr oddBricks = fm::prepareDrrVolume(volume, odd);
    ASSERT_TRUE(oddBricks->occupiedHalfBricks.empty());
    EXPECT_TRUE(fm::brickDepthTiles(*oddBricks, g, 0, 32, 0, 32));
    EXPECT_THROW(fm::brickDepthTiles(*oddBricks, g, 0, 32, 0, 32, fm::TileBlocks::HalfBricks), fm::Error);
    fm::ProjectionGeometry inside = g;
    inside.source = volume.center();  // brick corners behind the source
    EXPECT_FALSE(fm::brickDepthTiles(*sparse, inside, 0, 32, 0, 32));
}

}  // namespace

// renderDrrBySign: the positive and the negative values' line integrals from one walk, against
// exact chords (two disjoint boxes of opposite sign, sources outside and inside the volume) and
// against each part prepared and rendered alone, for every walk and both voxel types.
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "DrrTestUtil.h"
#include "core/Error.h"
#include "drr/DenseWalk.h"
#include "drr/Drr.h"

namespace {

fm::DrrValueOptions bySignRawValues() {
    fm::DrrValueOptions raw;
    raw.values = fm::DrrValues::Raw;
    return raw;
}

struct BySignWalk {
    const char* name;
    fm::DrrExactWalk walk;
    bool skipEmptySpace;
};
const BySignWalk kBySignWalks[] = {{"auto", fm::DrrExactWalk::Auto, true},
                           {"bricks", fm::DrrExactWalk::Bricks, true},
                           {"dense", fm::DrrExactWalk::Dense, true},
                           {"plain", fm::DrrExactWalk::Auto, false}};

fm::DrrRenderOptions bySignOptions(const BySignWalk& w) {
    fm::DrrRenderOptions o;
    o.walk = w.walk;
    o.skipEmptySpace = w.skipEmptySpace;
    return o;
}

// Box A holds +a, box B (disjoint) -b, nothing else: the positive part is a x chord(A), the
// negative b x chord(B), with the chords from the slab method in long double. Whole values
// (int16 voxels) and fractional ones (float voxels).
TEST(DrrBySign, TwoBoxesOfOppositeSignGiveEachItsExactChords) {
    for (const auto& [a, b] : {std::pair{3.0f, 5.0f}, std::pair{0.37f, 1.91f}}) {
        fm::Volume volume = fm::test::makeVolume({22, 16, 14}, {1.1, 0.9, 1.3}, 0.0f, {-7.0, 4.0, 1.0},
                                                 fm::test::rotation(19.0, {0.3, 1.0, -0.4}));
        const glm::ivec3 aLo{2, 3, 1}, aHi{9, 12, 11}, bLo{12, 2, 3}, bHi{19, 13, 12};
        for (int k = 0; k < volume.dims.z; ++k)
            for (int j = 0; j < volume.dims.y; ++j)
                for (int i = 0; i < volume.dims.x; ++i) {
                    const glm::ivec3 p{i, j, k};
                    if (glm::all(glm::greaterThanEqual(p, aLo)) && glm::all(glm::lessThanEqual(p, aHi)))
                        volume.at(i, j, k) = a;
                    if (glm::all(glm::greaterThanEqual(p, bLo)) && glm::all(glm::lessThanEqual(p, bHi)))
                        volume.at(i, j, k) = -b;
                }
        const fm::DrrVolumePtr v = fm::prepareDrrVolume(volume, bySignRawValues());
        EXPECT_EQ(fm::drrVolumeInfo(*v).voxelType, a == 3.0f ? fm::DrrVoxelType::Int16 : fm::DrrVoxelType::Float32);
        // Outside the volume, and inside it (between the boxes, so that rays leave both ways).
        const glm::dvec3 inside = volume.indexToWorld({10.5, 7.0, 6.0});
        // From inside, a detector sees one box or the other: both directions.
        int insideA = 0, insideB = 0;
        for (const auto& [azimuth, distance] :
             {std::pair{25.0, 160.0}, std::pair{20.0, 0.0}, std::pair{200.0, 0.0}}) {
            fm::ProjectionGeometry g =
                fm::test::orbitGeometry(volume.center(), azimuth, 14.0, 160.0, 140.0, 31, 1.7);
            if (distance == 0.0) {
                const glm::dvec3 shift = inside - g.source;
                g.source += shift;
                g.detector.origin += shift;
            }
            for (const BySignWalk& w : kBySignWalks) {
                const fm::DrrSignParts parts = fm::renderDrrBySign(*v, g, bySignOptions(w));
                int aMet = 0, bMet = 0, bothMet = 0;
                for (int row = 0; row < g.detector.size.y; ++row)
                    for (int col = 0; col < g.detector.size.x; ++col) {
                        const glm::dvec3 t = g.detector.pixelCenter(col, row);
                        const double chordA = double(fm::test::slabChord(volume, g.source, t, aLo, aHi));
                        const double chordB = double(fm::test::slabChord(volume, g.source, t, bLo, bHi));
                        aMet += chordA > 1.0;
                        bMet += chordB > 1.0;
                        bothMet += chordA > 1.0 && chordB > 1.0;
                        EXPECT_NEAR(parts.positive.at(col, row), a * chordA, 2e-5 * (1.0 + a * chordA))
                            << w.name << " " << azimuth << " pixel " << col << "," << row;
                        EXPECT_NEAR(parts.negative.at(col, row), b * chordB, 2e-5 * (1.0 + b * chordB))
                            << w.name << " " << azimuth << " pixel " << col << "," << row;
                    }
                if (distance > 0.0) {
                    EXPECT_GT(bothMet, 20) << "rays through both: " << w.name << " " << azimuth;
                } else {
                    insideA += aMet;
                    insideB += bMet;
                }
            }
        }
        EXPECT_GT(std::min(insideA, insideB), 80) << "from inside, rays through each box";
    }
}

// Random values of both signs with zeros and uniform regions (so that bricks of every kind
// occur): each part equals renderDrr of that part's own volume (max(v, 0), max(-v, 0)), and the
// parts' difference renderDrr of the whole, to the rounding of different summation orders.
TEST(DrrBySign, EachPartEqualsThatPartRenderedAlone) {
    for (const bool whole : {true, false}) {
        fm::Volume volume = fm::test::makeVolume({40, 33, 27}, {0.8, 1.0, 1.2}, 0.0f, {3.0, -2.0, 5.0},
                                                 fm::test::rotation(-31.0, {1.0, 0.2, 0.5}));
        std::mt19937 rng(11);
        std::uniform_int_distribution<int> value(-1900, 1100);
        for (int k = 0; k < volume.dims.z; ++k)
            for (int j = 0; j < volume.dims.y; ++j)
                for (int i = 0; i < volume.dims.x; ++i) {
                    // Air outside a slab, and in a block of it; a uniform block of -1500 in it.
                    float x = 0.0f;
                    if (i >= 16 && i < 32 && j >= 8 && j < 24 && k >= 8 && k < 24) x = -1500.0f;
                    else if (i < 16 && j >= 16 && k >= 8 && k < 24) x = 0.0f;
                    else if (k >= 3 && k < 24 && rng() % 5 != 0) x = float(value(rng));
                    volume.at(i, j, k) = whole ? x : x / 7.0f;
                }
        fm::Volume positive = volume, negative = volume;
        for (float& x : positive.values) x = std::max(x, 0.0f);
        for (float& x : negative.values) x = std::max(-x, 0.0f);
        const fm::DrrVolumePtr v = fm::prepareDrrVolume(volume, bySignRawValues()),
                               vPos = fm::prepareDrrVolume(positive, bySignRawValues()),
                               vNeg = fm::prepareDrrVolume(negative, bySignRawValues());
        const fm::DrrVolumeInfo info = fm::drrVolumeInfo(*v);
        EXPECT_GT(info.bricksEmpty, 0);
        EXPECT_GT(info.bricksUniform, 0);
        for (double azimuth : {0.0, 47.0, 133.0}) {
            const fm::ProjectionGeometry g =
                fm::test::orbitGeometry(volume.center(), azimuth, -21.0, 220.0, 180.0, 45, 1.3);
            for (const BySignWalk& w : kBySignWalks) {
                const fm::DrrSignParts parts = fm::renderDrrBySign(*v, g, bySignOptions(w));
                const fm::Image pos = fm::renderDrr(*vPos, g, bySignOptions(w)),
                                neg = fm::renderDrr(*vNeg, g, bySignOptions(w)),
                                all = fm::renderDrr(*v, g, bySignOptions(w));
                double largest = 0.0;
                for (std::size_t i = 0; i < all.pixels.size(); ++i) {
                    const double p = pos.pixels[i], n = neg.pixels[i];
                    largest = std::max(largest, std::min(p, n));
                    ASSERT_NEAR(parts.positive.pixels[i], p, 1e-6 * (1.0 + p)) << w.name << " " << azimuth << " " << i;
                    ASSERT_NEAR(parts.negative.pixels[i], n, 1e-6 * (1.0 + n)) << w.name << " " << azimuth << " " << i;
                    ASSERT_NEAR(parts.positive.pixels[i] - parts.negative.pixels[i], all.pixels[i], 1e-6 * (1.0 + p + n))
                        << w.name << " " << azimuth << " " << i;
                }
                EXPECT_GT(largest, 1000.0 / (whole ? 1.0 : 7.0)) << "rays meet much of both signs";
            }
        }
    }
}

// The walks themselves against arithmetic: rays built by hand along a row of signed values (one
// axis, then a staircase over two), scalar and 16 at once, sum and |value| sum as written out.
TEST(DrrBySign, TheWalksAddUpValueAndItsMagnitude) {
    // A padded row of 12 int16 values (index 0 and 11 are the zero padding).
    const std::vector<std::int16_t> values{0, 5, -3, 7, 0, -11, 2, -2, 9, -4, 1, 0};
    fm::DenseRay along;  // voxels 1..10, each 0.1 of alpha
    along.aBegin = 0.0;
    along.aEnd = 1.0;
    along.next[0] = 0.1;
    along.next[1] = along.next[2] = INFINITY;
    along.delta[0] = 0.1;
    along.offset[0] = 1;
    along.linear = 1;
    along.steps = 10;
    double sum = 0.0, absSum = 0.0;
    for (int i = 1; i <= 10; ++i) {
        sum += 0.1 * values[i];
        absSum += 0.1 * std::abs(values[i]);
    }
    // The same row read as a staircase: steps of +1 along x every 0.1 and "y" crossings (offset 0)
    // in between, which split segments without moving.
    fm::DenseRay stairs = along;
    stairs.next[1] = 0.05;
    stairs.delta[1] = 0.1;
    stairs.offset[1] = 0;
    stairs.steps = 20;
    for (const fm::DenseRay& ray : {along, stairs}) {
        const fm::WalkSums one = fm::walkDense<std::int16_t, true>(values.data(), 11, ray);
        EXPECT_NEAR(one.sum, sum, 1e-12);
        EXPECT_NEAR(one.absSum, absSum, 1e-12);
        EXPECT_EQ((fm::walkDense<std::int16_t, false>(values.data(), 11, ray).sum), one.sum);
        std::vector<fm::DenseRay> rays(13, ray);
        std::vector<fm::WalkSums> sums(13);
        fm::walkDense16<std::int16_t, true>(values.data(), 11, rays.data(), 13, sums.data());
        for (const fm::WalkSums& s : sums) {
            EXPECT_EQ(s.sum, one.sum);
            EXPECT_EQ(s.absSum, one.absSum);
        }
    }
}

TEST(DrrBySign, GivesLineIntegralsOnly) {
    fm::Volume volume = fm::test::makeVolume({4, 4, 4}, {1.0, 1.0, 1.0}, -2.0f);
    const fm::DrrVolumePtr v = fm::prepareDrrVolume(volume, bySignRawValues());
    fm::DrrRenderOptions intensity;
    intensity.output = fm::DrrOutput::Intensity;
    EXPECT_THROW(fm::renderDrrBySign(*v, fm::test::orbitGeometry(volume.center(), 0.0, 0.0, 50.0, 50.0, 8, 1.0),
                                     intensity),
                 fm::Error);
}

}  // namespace

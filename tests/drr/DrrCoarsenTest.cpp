// coarsenDrrVolume: block means of a prepared volume in the same frame. Truth: chord lengths
// through a volume of ones (block means of ones are ones) and the mass (film integral) of a
// random volume, which block means keep.
#include <random>

#include <gtest/gtest.h>

#include "DrrTestUtil.h"
#include "core/Error.h"
#include "drr/Drr.h"

namespace {

using fm::test::makeVolume;

fm::DrrValueOptions rawValuesInBricksOf2() {
    fm::DrrValueOptions raw;
    raw.values = fm::DrrValues::Raw;
    raw.brickSize = 2;
    return raw;
}

TEST(DrrCoarsen, BlockMeansOfOnesGiveTheSameChords) {
    // Dims divisible by the factors: the coarse box is the fine box, so every chord is the same.
    const fm::Volume volume = makeVolume({8, 12, 16}, {1.5, 2.0, 1.0}, 1.0f, {-3, 4, 5},
                                         fm::test::rotation(25, {1, 2, 3}));
    const fm::DrrVolumePtr fine = fm::prepareDrrVolume(volume, rawValuesInBricksOf2());
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const glm::dvec3 c = volume.center();
    for (int f : {1, 2, 4}) {
        const fm::DrrVolumePtr coarse = fm::coarsenDrrVolume(*fine, f, 2);
        const fm::DrrVolumeInfo info = fm::drrVolumeInfo(*coarse);
        EXPECT_EQ(info.dims, glm::ivec3(8 / f, 12 / f, 16 / f));
        EXPECT_EQ(info.spacing, glm::dvec3(1.5, 2.0, 1.0) * double(f));
        for (int n = 0; n < 500; ++n) {
            const glm::dvec3 source = c + 60.0 * glm::dvec3(unit(rng), unit(rng), unit(rng));
            const glm::dvec3 target = c + 10.0 * glm::dvec3(unit(rng), unit(rng), unit(rng));
            const double truth =
                static_cast<double>(fm::test::slabChord(volume, source, target));
            ASSERT_NEAR(fm::drrLineIntegral(*coarse, source, target), truth, 1e-8 + 1e-9 * truth)
                << "factor " << f << " ray " << n;
        }
    }
}

TEST(DrrCoarsen, KeepsTheMassOfEveryVoxel) {
    // Dims not divisible by 2: the last blocks reach beyond the box, where the volume is 0.
    fm::Volume volume = makeVolume({5, 4, 3}, {2.0, 1.5, 2.5}, 0.0f, {1, -2, 3},
                                   fm::test::rotation(40, {0, 1, 1}));
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> value(0.0f, 2.0f);
    double mass = 0.0;
    for (float& x : volume.values) mass += (x = value(rng));
    mass *= 2.0 * 1.5 * 2.5;
    fm::DrrValueOptions raw = rawValuesInBricksOf2();
    raw.cropToContent = false;
    const fm::DrrVolumePtr coarse = fm::coarsenDrrVolume(*fm::prepareDrrVolume(volume, raw), 2);
    EXPECT_EQ(fm::drrVolumeInfo(*coarse).dims, glm::ivec3(3, 2, 2));
    // Film integral / magnification^2 = mass (DrrAnalytic.OneBrightVoxelConservesMass...). A
    // block mean moves mass by up to a voxel in depth, which changes its magnification by
    // 2 * shift / distance: a distant source keeps that below 1e-4.
    constexpr double kPixelMm = 0.1;
    const double sod = 1e5, sdd = 2e5, magnification = sdd / sod;
    for (auto [az, el] : {std::pair{0.0, 0.0}, {37.0, 12.0}, {-120.0, 60.0}}) {
        const fm::ProjectionGeometry g =
            fm::test::orbitGeometry(volume.center(), az, el, sod, sdd - sod, 500, kPixelMm);
        const fm::Image image = fm::renderDrr(*coarse, g, {});
        double sum = 0.0;
        for (float p : image.pixels) sum += p;
        const double film = sum * kPixelMm * kPixelMm / (magnification * magnification);
        EXPECT_NEAR(film, mass, 1e-3 * mass) << "az " << az << " el " << el;
        for (int i = 0; i < 500; ++i) {  // the shadow lies inside the film
            ASSERT_EQ(image.at(i, 0), 0.0f);
            ASSERT_EQ(image.at(0, i), 0.0f);
        }
    }
}

TEST(DrrCoarsen, RefusesBadFactors) {
    const fm::DrrVolumePtr v =
        fm::prepareDrrVolume(makeVolume({4, 4, 4}, {1, 1, 1}, 1.0f), rawValuesInBricksOf2());
    EXPECT_THROW(fm::coarsenDrrVolume(*v, 0), fm::Error);
    EXPECT_THROW(fm::coarsenDrrVolume(*v, 17), fm::Error);
    EXPECT_THROW(fm::coarsenDrrVolume(*v, 2, -1), fm::Error);
}

}  // namespace

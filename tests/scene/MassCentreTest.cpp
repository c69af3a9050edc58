// The mass centre of an object, measured through its own projections, against the analytic
// centre of two blocks of different attenuation (far from the centre of their bounds).
#include <gtest/gtest.h>

#include "drr/Drr.h"
#include "scene/MassCentre.h"
#include "volume/Volume.h"

namespace {

// A 1 mm grid with a 4 mm cube of value 1 at voxels 2..5 and a 2 mm cube of value 3 at 30..31
// (x), 20..21 (y), 14..15 (z).
fm::DrrVolumePtr twoBlocks() {
    fm::Volume v = fm::Volume::allocate({40, 30, 20}, 0.0f);
    v.spacing = {1.0, 1.0, 1.0};
    v.origin = {10.0, -20.0, 300.0};
    for (int k = 2; k < 6; ++k)
        for (int j = 2; j < 6; ++j)
            for (int i = 2; i < 6; ++i) v.at(i, j, k) = 1.0f;
    for (int k = 14; k < 16; ++k)
        for (int j = 20; j < 22; ++j)
            for (int i = 30; i < 32; ++i) v.at(i, j, k) = 3.0f;
    fm::DrrValueOptions raw;
    raw.values = fm::DrrValues::Raw;
    return fm::prepareDrrVolume(v, raw);
}

TEST(MassCentre, IsTheAttenuationWeightedMeanOfTheObject) {
    const fm::VolumeXrayModel model(twoBlocks());
    // Voxel centres at origin + index: the cube 2..5 is centred at index 3.5, the other at 30.5,
    // 20.5, 14.5; masses 64 x 1 and 8 x 3 (value mm^3).
    const glm::dvec3 a = glm::dvec3(10.0, -20.0, 300.0) + glm::dvec3(3.5, 3.5, 3.5);
    const glm::dvec3 b = glm::dvec3(10.0, -20.0, 300.0) + glm::dvec3(30.5, 20.5, 14.5);
    const glm::dvec3 truth = (64.0 * a + 24.0 * b) / 88.0;
    const auto c = fm::massCentre(model, 2);
    ASSERT_TRUE(c);
    const fm::Box3 box = model.bounds();
    const glm::dvec3 boxCentre = 0.5 * (box.lower + box.upper);
    ASSERT_GT(glm::length(truth - boxCentre), 5.0);  // the box centre would be well off
    // Pixels of about 2.1 x 15 mm / 64 = 0.5 mm: a fraction of one.
    EXPECT_NEAR(c->point.x, truth.x, 0.3);
    EXPECT_NEAR(c->point.y, truth.y, 0.3);
    EXPECT_NEAR(c->point.z, truth.z, 0.3);
    // The mass only weighs objects against each other: the pixels sample the cubes' edges, the
    // 2 mm cube spans 4-6 of them (measured 84.2).
    EXPECT_NEAR(c->mass, 88.0, 88.0 * 0.06);
    // The same for any thread count.
    const auto one = fm::massCentre(model, 1);
    ASSERT_TRUE(one);
    EXPECT_EQ(one->point, c->point);
}

TEST(MassCentre, NothingForAnEmptyObject) {
    fm::Volume v = fm::Volume::allocate({8, 8, 8}, 0.0f);
    fm::DrrValueOptions raw;
    raw.values = fm::DrrValues::Raw;
    EXPECT_FALSE(fm::massCentre(fm::VolumeXrayModel(fm::prepareDrrVolume(v, raw))));
}

}  // namespace

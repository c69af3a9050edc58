#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "core/Error.h"
#include "volume/Volume.h"
#include "volume/VolumeStats.h"

namespace {

constexpr double kTol = 1e-12;  // pure double arithmetic on small numbers

TEST(Volume, IndexToWorldFollowsItkConvention) {
    fm::Volume v = fm::Volume::allocate({4, 5, 6});
    v.spacing = {2.0, 3.0, 0.5};
    v.origin = {10.0, -20.0, 5.0};
    // RAS-stored axes: i towards patient right, j anterior (as NIfTI files usually are).
    v.direction = glm::dmat3(glm::dvec3(-1, 0, 0), glm::dvec3(0, -1, 0), glm::dvec3(0, 0, 1));
    const glm::dvec3 w = v.indexToWorld({1, 2, 3});
    EXPECT_NEAR(w.x, 10.0 - 2.0, kTol);
    EXPECT_NEAR(w.y, -20.0 - 6.0, kTol);
    EXPECT_NEAR(w.z, 5.0 + 1.5, kTol);
    const glm::dvec3 back = v.worldToIndex(w);
    EXPECT_NEAR(back.x, 1.0, kTol);
    EXPECT_NEAR(back.y, 2.0, kTol);
    EXPECT_NEAR(back.z, 3.0, kTol);
    EXPECT_EQ(fm::orientationCode(v.direction), "RAS");
    EXPECT_EQ(fm::orientationCode(glm::dmat3(1.0)), "LPS");
}

TEST(Volume, StorageIsIFastest) {
    fm::Volume v = fm::Volume::allocate({3, 4, 5});
    EXPECT_EQ(v.index(1, 0, 0), 1u);
    EXPECT_EQ(v.index(0, 1, 0), 3u);
    EXPECT_EQ(v.index(0, 0, 1), 12u);
    EXPECT_EQ(v.voxelCount(), 60u);
}

TEST(Volume, RefusesAbsurdSizes) {
    EXPECT_THROW(fm::Volume::allocate({0, 10, 10}), fm::Error);
    EXPECT_THROW(fm::Volume::allocate({-1, 10, 10}), fm::Error);
    EXPECT_THROW(fm::Volume::allocate({100000, 100000, 100000}), fm::Error);
}

TEST(Volume, ValidateRejectsBadGeometry) {
    fm::Volume v = fm::Volume::allocate({2, 2, 2});
    EXPECT_NO_THROW(v.validate("test"));
    v.spacing.y = 0.0;
    EXPECT_THROW(v.validate("test"), fm::Error);
    v.spacing.y = std::nan("");
    EXPECT_THROW(v.validate("test"), fm::Error);
    v.spacing.y = 1.0;
    v.direction[0] = glm::dvec3(1, 1, 0);
    EXPECT_THROW(v.validate("test"), fm::Error);
}

TEST(VolumeStats, PercentilesOfKnownValues) {
    fm::Volume v = fm::Volume::allocate({101, 1, 1});
    for (int i = 0; i <= 100; ++i) v.at(100 - i, 0, 0) = static_cast<float>(i);
    const fm::VolumeStats s = fm::computeStats(v, {0, 1, 50, 99, 100});
    EXPECT_EQ(s.min, 0.0f);
    EXPECT_EQ(s.max, 100.0f);
    EXPECT_NEAR(s.mean, 50.0, kTol);
    ASSERT_EQ(s.percentiles.size(), 5u);
    EXPECT_EQ(s.percentiles[1], 1.0);
    EXPECT_EQ(s.percentiles[2], 50.0);
    EXPECT_EQ(s.percentiles[3], 99.0);
}

// The radix selection against a sorted copy (nearest rank), on values that stress the float
// key order: negatives and positives, many duplicates (CT air), tiny and huge magnitudes, and
// values whose upper 16 key bits are equal (they differ only in the lower bits).
TEST(VolumeStats, PercentilesEqualThoseOfASortedCopy) {
    fm::Volume v = fm::Volume::allocate({97, 31, 7});
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> hu(-1024.0f, 3000.0f);
    for (std::size_t n = 0; n < v.values.size(); ++n) {
        switch (rng() % 6) {
            case 0: v.values[n] = -1000.0f; break;
            case 1: v.values[n] = 1.0f + float(rng() % 1000) * 1e-7f; break;  // same upper bits
            case 2: v.values[n] = float(rng() % 3) * 1e-39f - 1e-39f; break;   // denormals, 0
            case 3: v.values[n] = (rng() % 2 ? 1.0f : -1.0f) * 3e37f * float(rng() % 9); break;
            default: v.values[n] = hu(rng);
        }
    }
    const std::vector<double> wanted = {0, 0.5, 1, 5, 33.3, 50, 95, 99, 99.9, 100};
    const fm::VolumeStats s = fm::computeStats(v, wanted);
    std::vector<float> sorted = v.values;
    std::sort(sorted.begin(), sorted.end());
    ASSERT_EQ(s.percentiles.size(), wanted.size());
    for (std::size_t p = 0; p < wanted.size(); ++p) {
        const double rank = wanted[p] / 100.0 * double(sorted.size() - 1);
        EXPECT_EQ(s.percentiles[p], sorted[static_cast<std::size_t>(std::llround(rank))])
            << wanted[p];
    }
    EXPECT_EQ(s.min, sorted.front());
    EXPECT_EQ(s.max, sorted.back());
}

TEST(VolumeStats, NonFiniteVoxelsAreCountedAndLeftOut) {
    // The same 0..100 ramp with NaN and +-inf voxels added: every figure is the ramp's.
    fm::Volume v = fm::Volume::allocate({105, 1, 1});
    for (int i = 0; i <= 100; ++i) v.at(i, 0, 0) = static_cast<float>(i);
    v.at(101, 0, 0) = std::numeric_limits<float>::quiet_NaN();
    v.at(102, 0, 0) = std::numeric_limits<float>::quiet_NaN();
    v.at(103, 0, 0) = std::numeric_limits<float>::infinity();
    v.at(104, 0, 0) = -std::numeric_limits<float>::infinity();
    // NaN first: std::minmax_element over raw values would report garbage here.
    std::swap(v.at(0, 0, 0), v.at(101, 0, 0));
    const fm::VolumeStats s = fm::computeStats(v, {0, 50, 100});
    EXPECT_EQ(s.nanCount, 2u);
    EXPECT_EQ(s.infiniteCount, 2u);
    EXPECT_EQ(s.min, 0.0f);
    EXPECT_EQ(s.max, 100.0f);
    EXPECT_NEAR(s.mean, 50.0, kTol);
    EXPECT_EQ(s.percentiles, (std::vector<double>{0.0, 50.0, 100.0}));
    // Nothing finite: refused, not a NaN statistic.
    fm::Volume allNan = fm::Volume::allocate({2, 1, 1});
    allNan.values.assign(2, std::numeric_limits<float>::quiet_NaN());
    EXPECT_THROW(fm::computeStats(allNan), fm::Error);
}

}  // namespace

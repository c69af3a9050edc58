// The readers on the real files in ../shared/data, checked against the facts its README lists.
#include <gtest/gtest.h>

#include "TestExpect.h"
#include "common/TestData.h"
#include "io/ReadVolume.h"
#include "io/VolumeWriter.h"
#include "volume/VolumeStats.h"

namespace {

namespace fs = std::filesystem;
using fm::test::expectVec;

// The README gives origins to 3 decimals.
constexpr double kReadmeOriginTol = 1e-3;
// Spacings are stored as float32 in NIfTI: 3.0 and 1.5 are exact, allow float rounding anyway.
constexpr double kSpacingTol = 1e-6;

TEST(RealData, NrrdHeadsqQuarter) {
    FM_REQUIRE_SHARED_DATA("vtk-headsq-quarter/quarter.nhdr");
    const fm::Volume v =
        fm::readVolume(fm::test::sharedDataDir() / "vtk-headsq-quarter/quarter.nhdr");
    EXPECT_EQ(v.dims, glm::ivec3(64, 64, 93));
    expectVec(v.spacing, {3.2, 3.2, 1.5}, kSpacingTol);
    EXPECT_EQ(fm::detectVolumeFormat(fm::test::sharedDataDir() / "vtk-headsq-quarter/quarter.nhdr"),
              "nrrd");
    const fm::VolumeStats s = fm::computeStats(v, {1, 50, 99});
    EXPECT_EQ(s.min, 0.0f);
    EXPECT_EQ(s.max, 3926.0f);
    ASSERT_EQ(s.percentiles.size(), 3u);
    EXPECT_EQ(s.percentiles[0], 0.0);
    EXPECT_EQ(s.percentiles[1], 135.0);
    EXPECT_EQ(s.percentiles[2], 2269.0);
}

TEST(RealData, NiftiExampleCtUsesSform) {
    FM_REQUIRE_SHARED_DATA("totalseg-example-ct/example_ct.nii.gz");
    const fm::Volume v =
        fm::readVolume(fm::test::sharedDataDir() / "totalseg-example-ct/example_ct.nii.gz");
    EXPECT_EQ(v.dims, glm::ivec3(122, 101, 112));
    expectVec(v.spacing, {3, 3, 3}, kSpacingTol);
    // sform origin (-177.956, 11.319, 94.302) in RAS; LPS negates x and y.
    expectVec(v.origin, {177.956, -11.319, 94.302}, kReadmeOriginTol);
    EXPECT_EQ(fm::orientationCode(v.direction), "RAS");
    const fm::VolumeStats s = fm::computeStats(v, {1, 50, 99});
    EXPECT_EQ(s.min, -1207.0f);
    EXPECT_EQ(s.max, 3382.0f);
    EXPECT_EQ(s.percentiles[0], -1012.0);
    EXPECT_EQ(s.percentiles[1], -101.0);
    EXPECT_EQ(s.percentiles[2], 307.0);
}

TEST(RealData, NiftiCroppedCtStoredLps) {
    FM_REQUIRE_SHARED_DATA("totalseg-example-ct/ct_cropped_aorta_report.nii.gz");
    const fm::Volume v = fm::readVolume(fm::test::sharedDataDir() /
                                        "totalseg-example-ct/ct_cropped_aorta_report.nii.gz");
    EXPECT_EQ(v.dims, glm::ivec3(120, 126, 164));
    expectVec(v.spacing, {1.5, 1.5, 1.5}, kSpacingTol);
    // Affine diag(-1.5, -1.5, 1.5) in RAS, origin (71.658, 255.658, 540.2): LPS axes.
    EXPECT_EQ(fm::orientationCode(v.direction), "LPS");
    expectVec(v.origin, {-71.658, -255.658, 540.2}, kReadmeOriginTol);
    const fm::VolumeStats s = fm::computeStats(v, {1, 50, 99});
    EXPECT_EQ(s.min, -1078.0f);
    EXPECT_EQ(s.max, 3343.0f);
    EXPECT_EQ(s.percentiles[0], -994.0);
    EXPECT_EQ(s.percentiles[1], -29.0);
    EXPECT_EQ(s.percentiles[2], 729.0);
}

// A real CT written by our writers and read back must be the same volume.
TEST(RealData, ExampleCtRoundTripsThroughWriters) {
    FM_REQUIRE_SHARED_DATA("totalseg-example-ct/example_ct.nii.gz");
    const fm::Volume v =
        fm::readVolume(fm::test::sharedDataDir() / "totalseg-example-ct/example_ct.nii.gz");
    const fs::path dir = fm::test::scratchDir("real_roundtrip");
    // NIfTI keeps geometry as float32: relative 1e-7 of ~180 mm.
    constexpr double kFloat32GeometryTol = 1e-4;
    for (const char* name : {"ct.mha", "ct.nii.gz"}) {
        fm::writeVolume(v, dir / name);
        const fm::Volume back = fm::readVolume(dir / name);
        SCOPED_TRACE(name);
        EXPECT_EQ(back.dims, v.dims);
        EXPECT_TRUE(back.values == v.values);
        expectVec(back.origin, v.origin, kFloat32GeometryTol);
        expectVec(back.spacing, v.spacing, kFloat32GeometryTol);
        EXPECT_EQ(fm::orientationCode(back.direction), "RAS");
    }
}

}  // namespace

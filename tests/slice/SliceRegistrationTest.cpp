#include <gtest/gtest.h>

#include <atomic>

#include "core/Error.h"
#include "slice/SliceEvaluation.h"
#include "slice/SlicePoseError.h"
#include "slice/SliceRegistration.h"
#include "slice/SliceTestUtil.h"

using namespace fm;

namespace {

struct Fixture {
    std::shared_ptr<const Volume> volume = fm::test::blobHead();
    SliceVolumePtr prepared = prepareSliceVolume(volume, true, 1);
    SliceSetup setup;
    Pose truth{{3, -2, 4}, 20, 10, 5};
    SampledSlice reference;
    std::vector<glm::dvec3> targets = foregroundTargetPoints(*volume, 500);
    Fixture() {
        setup.pixels = {48, 48};
        setup.spacingMm = {2, 2};
        reference = sampleSlice(*prepared, sliceGeometry(truth, setup, volume->center()),
                                SliceInterpolation::CubicBSpline);
    }
    SliceRegistrationSettings settings(SimilarityMeasure m) const {
        SliceRegistrationSettings s;
        s.similarity = m;
        s.levelFactors = {2, 1};
        s.threads = 2;
        return s;
    }
    double mtre(const Pose& p) const {
        return sliceTargetError(truth, p, setup, volume->center(), targets).meanMm;
    }
};

}  // namespace

TEST(SliceRegistration, FindsTheHiddenPoseWithNccAndMutualInformation) {
    const Fixture f;
    const Pose start{{6, -5, 1}, 25, 5, 9};
    ASSERT_GT(f.mtre(start), 5.0);
    for (SimilarityMeasure m : {SimilarityMeasure::Ncc, SimilarityMeasure::MutualInformation}) {
        const SliceRegistration reg(f.prepared, f.reference.image, &f.reference.mask, f.setup,
                                    f.volume->center(), f.settings(m));
        const RegistrationResult r = reg.run(start);
        // NCC is exact for a slice of the same volume; MI's plug-in estimate is biased a little.
        EXPECT_LT(f.mtre(r.pose()), m == SimilarityMeasure::Ncc ? 0.1 : 0.5)
            << toString(m) << " " << formatPose(r.pose());
        EXPECT_LE(r.evaluations, reg.totalBudget());
        EXPECT_LT(reg.cost(r.pose(), 1), reg.cost(start, 1));
    }
}

TEST(SliceRegistration, MutualInformationMatchesAcrossContrasts) {
    // The reference in another "contrast": intensities inverted and squared (monotonic on the
    // data range, but far from linear). MI finds the pose.
    const Fixture f;
    Image other = f.reference.image;
    for (std::size_t i = 0; i < other.pixels.size(); ++i)
        if (f.reference.mask.inside[i]) {
            const float x = 250.0f - other.pixels[i];
            other.pixels[i] = x * x / 250.0f;
        }
    const SliceRegistration reg(f.prepared, other, &f.reference.mask, f.setup, f.volume->center(),
                                f.settings(SimilarityMeasure::MutualInformation));
    const Pose start{{0, 1, 7}, 16, 14, 2};
    const RegistrationResult r = reg.run(start);
    EXPECT_LT(f.mtre(r.pose()), 1.0) << formatPose(r.pose());
}

TEST(SliceRegistration, DeterministicForASeedAndStoppable) {
    const Fixture f;
    SliceRegistrationSettings s = f.settings(SimilarityMeasure::Ncc);
    s.globalEvaluations = 60;
    s.polishEvaluations = 20;
    const SliceRegistration reg(f.prepared, f.reference.image, &f.reference.mask, f.setup,
                                f.volume->center(), s);
    const Pose start{{5, 0, 0}, 25, 10, 5};
    const RegistrationResult a = reg.run(start), b = reg.run(start);
    EXPECT_EQ(a.pose().toArray(), b.pose().toArray());
    EXPECT_EQ(a.costHistory, b.costHistory);
    s.threads = 1;  // and for another thread count
    const SliceRegistration single(f.prepared, f.reference.image, &f.reference.mask, f.setup,
                                   f.volume->center(), s);
    EXPECT_EQ(single.run(start).pose().toArray(), a.pose().toArray());
    std::atomic<bool> stop{true};
    const RegistrationResult stopped = reg.run(start, {}, &stop);
    EXPECT_TRUE(stopped.stopped);
    EXPECT_EQ(stopped.pose().toArray(), start.toArray());
}

TEST(SliceRegistration, BadInputIsRefused) {
    const Fixture f;
    const auto s = f.settings(SimilarityMeasure::Ncc);
    EXPECT_THROW(SliceRegistration(f.prepared, Image(10, 10), nullptr, f.setup, {}, s), Error);
    const SliceVolumePtr linearOnly = prepareSliceVolume(f.volume, false);
    EXPECT_THROW(SliceRegistration(linearOnly, f.reference.image, nullptr, f.setup, {}, s), Error);
    // A reference that holds no data (its plane missed the volume) cannot be registered to.
    const Mask none(48, 48, false);
    EXPECT_THROW(SliceRegistration(f.prepared, f.reference.image, &none, f.setup, {}, s), Error);
    // A candidate whose plane misses the volume costs 0 (no evidence), never NaN.
    const SliceRegistration reg(f.prepared, f.reference.image, &f.reference.mask, f.setup,
                                f.volume->center(), s);
    EXPECT_EQ(reg.cost({{0, 900, 0}, 0, 0, 0}, 1), 0.0);
}

TEST(SliceEvaluation, BinsStartsAndIsDeterministic) {
    const Fixture f;
    EvaluationSettings e;
    e.methods = {SearchMethod::CmaEs};
    e.bins = {{0, 2}, {2, 5}};
    e.startsPerBin = 2;
    SliceRegistrationSettings s = f.settings(SimilarityMeasure::Ncc);
    const auto a = runSliceEvaluation(f.prepared, f.reference.image, &f.reference.mask, f.setup,
                                      f.volume->center(), f.truth, f.targets, e, s);
    const auto b = runSliceEvaluation(f.prepared, f.reference.image, &f.reference.mask, f.setup,
                                      f.volume->center(), f.truth, f.targets, e, s);
    ASSERT_EQ(a.size(), 4u);
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_GE(a[i].startMtreMm, e.bins[a[i].bin].lowMm);
        EXPECT_LE(a[i].startMtreMm, e.bins[a[i].bin].highMm);
        EXPECT_EQ(a[i].final.meanMm, b[i].final.meanMm);
        EXPECT_EQ(a[i].success, a[i].final.meanMm < 1.0);
    }
    const auto methods = summarizeMethods(a, e);
    ASSERT_EQ(methods.size(), 1u);
    EXPECT_EQ(methods[0].successRate, 1.0);
    EXPECT_EQ(methods[0].captureRangeMm, 5.0);
}

TEST(SlicePoseError, OffsetAlongTheNormalIsPureOutOfPlaneError) {
    const Fixture f;
    const SliceGeometry g = sliceGeometry(f.truth, f.setup, f.volume->center());
    Pose moved = f.truth;
    moved.offset += 3.0 * g.normal();
    const TargetRegistrationError e =
        sliceTargetError(f.truth, moved, f.setup, f.volume->center(), f.targets);
    EXPECT_NEAR(e.meanMm, 3.0, 1e-9);
    EXPECT_NEAR(e.meanDepthMm, 3.0, 1e-9);
    EXPECT_NEAR(e.meanInPlaneMm, 0.0, 1e-9);
    Pose side = f.truth;
    side.offset += 2.0 * g.u;
    EXPECT_NEAR(sliceTargetError(f.truth, side, f.setup, f.volume->center(), f.targets).meanInPlaneMm,
                2.0, 1e-9);
    EXPECT_THROW(sliceTargetError(f.truth, side, f.setup, {}, {}), Error);
}

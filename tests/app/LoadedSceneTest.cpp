// How the app prepares a CT: HU detection for files that do not state their units, and the
// bone surface level, checked on real data facts from /work/shared/data/README.md.
#include <algorithm>

#include <gtest/gtest.h>

#include "common/TestData.h"
#include "scene/LoadedScene.h"
#include "source/VolumeSource.h"

namespace fm::test {
namespace {

TEST(LoadedScene, ANiftiCtWithoutUnitsIsTreatedAsHounsfield) {
    // README: example_ct.nii.gz holds HU (scl_slope unset), 1st percentile -1012.
    FM_REQUIRE_SHARED_DATA("totalseg-example-ct/example_ct.nii.gz");
    const Volume v =
        loadVolume((sharedDataDir() / "totalseg-example-ct/example_ct.nii.gz").string());
    EXPECT_TRUE(app::looksLikeHounsfield(v));
    EXPECT_EQ(app::appDrrValueOptions(v).values, DrrValues::Mu);
}

TEST(LoadedScene, TheVtkHeadIsNotHounsfield) {
    // README: values 0..3926, air about 0: not HU, integrated as stored.
    FM_REQUIRE_SHARED_DATA("vtk-headsq-quarter/quarter.nhdr");
    const Volume v = loadVolume((sharedDataDir() / "vtk-headsq-quarter/quarter.nhdr").string());
    EXPECT_FALSE(app::looksLikeHounsfield(v));
    EXPECT_EQ(app::appDrrValueOptions(v).values, DrrValues::Raw);
}

TEST(LoadedScene, BuildSceneReportsItsStagesAndFitsTheSliderRange) {
    std::vector<std::string> stages;
    std::vector<float> fractions;
    const auto scene = app::buildScene("phantom:knee", [&](const std::string& s, float f) {
        stages.push_back(s);
        fractions.push_back(f);
    });
    ASSERT_GE(stages.size(), 3u);
    EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end())) << "progress never goes back";
    EXPECT_EQ(fractions.back(), 1.0f);
    EXPECT_EQ(scene->isoValue, 300.0) << "the knee phantom is in HU: bone at 300 HU";
    EXPECT_GT(scene->mesh->triangleCount(), 0u);
    EXPECT_FALSE(scene->bonePoints.empty());
    // Offsets span half the largest extent, rounded up to 10 mm: the knee field is
    // 220 x 220 x 281 mm (docs/geometry.md), so 141 -> 150 mm.
    const glm::dvec3 e = scene->volume->extent();
    const double half = 0.5 * std::max({e.x, e.y, e.z});
    EXPECT_GE(scene->translationRangeMm, half);
    EXPECT_LT(scene->translationRangeMm, half + 10.0);
    // The box corners are the voxel-box corners: opposite corners span the extent (double
    // arithmetic on numbers of a few hundred mm: 1e-9 mm is far above rounding).
    constexpr double kCornerToleranceMm = 1e-9;
    EXPECT_NEAR(glm::length(scene->boxCorners[7] - scene->boxCorners[0]), glm::length(e),
                kCornerToleranceMm);
}

}  // namespace
}  // namespace fm::test

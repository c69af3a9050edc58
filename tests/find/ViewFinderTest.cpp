// Finding the 2011 scene's pose with no start (find/ViewFinder.h): a placed template is what the
// camera of its pose sees (the scan and the pose it hands on agree, the roll's sense included),
// and the proof: references drawn anywhere in the app's hard range (ReferenceDraw) of
// the knee phantom and of the real example_ct found from nothing within 1 mm mTRE.
#include <cstdio>
#include <cstdlib>
#include <string>

#include <gtest/gtest.h>

#include "common/TestData.h"
#include "drr/Drr.h"
#include "find/ViewFinder.h"
#include "io/ReadVolume.h"
#include "match/PoseError.h"
#include "match/ReferenceDraw.h"
#include "phantom/KneePhantom.h"
#include "search/RegistrationTargets.h"
#include "similarity/ImagePyramid.h"

namespace fm {
namespace {

// A placed template against the DRR rendered at its pose: the first-order model (a turn, scale
// and shift of the image) leaves the parallax's small distortion and the block means' blur.
constexpr double kPlacedMinNcc = 0.97;

TEST(ViewFinder, APlacedTemplateIsWhatItsPoseShows) {
    const Volume knee = makeKneePhantom();
    const DrrVolumePtr prepared = prepareDrrVolume(knee, {});
    const SceneSetup setup = defaultSceneSetup();
    ViewSpace space;
    space.elevationDeg = 10.0;
    const double pitch = setup.filmSizeMm.x / setup.filmPixels.x * 8.0;  // the 1/8 scan
    const ViewTemplates templates = renderViewTemplates(*prepared, setup, knee.center(), space, 10.0, pitch, 48, 0);
    ASSERT_EQ(templates.templates.size(), 36u * 3u);
    const int index = 3 * 21 + 2;  // azimuth 30, elevation 10
    ASSERT_DOUBLE_EQ(templates.templates[index].azimuthDeg, 30.0);
    ASSERT_DOUBLE_EQ(templates.templates[index].elevationDeg, 10.0);
    for (double roll : {17.0, -17.0}) {
        ViewPlacement placed;
        placed.templateIndex = index;
        placed.rollDeg = roll;
        placed.scale = 1.07;
        placed.shiftMm = {2.0 * pitch, -3.0 * pitch};
        const Pose pose = placementPose(templates.templates[index], placed, setup, knee.center());
        SCOPED_TRACE(formatPose(pose));
        // The pose is neither the template's view nor its offset-free turn: the CT is moved.
        EXPECT_GT(glm::length(pose.offset), 20.0);
        const Image seen = downsampleBy(renderDrr(*prepared, sceneGeometry(pose, setup, knee.center()), {}), 8);
        const ViewScanImage image{&seen, pitch, glm::dvec2(15.5)};
        // Among the shifts within 2 pixels the placed one is the best, and it correlates closely.
        const ViewPlacement same = rescoreViews(image, templates, {placed}, 2, 1).front();
        EXPECT_GT(same.ncc, kPlacedMinNcc);
        EXPECT_NEAR(same.shiftMm.x, placed.shiftMm.x, 1e-9);
        EXPECT_NEAR(same.shiftMm.y, placed.shiftMm.y, 1e-9);
        ViewPlacement mirrored = placed;
        mirrored.rollDeg = -roll;
        EXPECT_LT(rescoreViews(image, templates, {mirrored}, 2, 1).front().ncc, same.ncc - 0.02)
            << "the other sense of the turn fits as well";
    }
}

// The proof: `draws` seeded references of the app's hard range (6 parameters hidden,
// offsets +-40 mm, angles +-30 deg around a clinical view), each found from nothing
// (findScenePose, then nothing else) and judged by the mTRE over the bone against the truth.
// FM_VIEW_DRAWS=50 runs the count (docs/find.md has the table).
void findHardDraws(const Volume& volume, const char* name) {
    const char* env = std::getenv("FM_VIEW_DRAWS");
    const int draws = env ? std::atoi(env) : 6;  // Release only (tests/find/extra.cmake)
    ASSERT_GT(draws, 0) << "FM_VIEW_DRAWS must be a positive count";
    const DrrVolumePtr prepared = prepareDrrVolume(volume, {});
    const SceneSetup setup = defaultSceneSetup();
    const auto points = boneTargetPoints(volume);
    const auto targets = registrationTargets(volume);
    RegistrationSettings finish;  // `register`'s on a whole CT
    useWholeCtSpeedups(finish);
    int met = 0;
    for (int seed = 1; seed <= draws; ++seed) {
        const ReferenceDraw draw =
            drawReferencePose(points, volume.center(), setup, Pose{}, static_cast<std::uint64_t>(seed), Difficulty::Hard, 100.0);
        const Image reference = renderDrr(*prepared, sceneGeometry(draw.pose, setup, volume.center()), {});
        const FoundView found = findScenePose(prepared, setup, volume.center(), reference, finish, {});
        ASSERT_FALSE(found.candidates.empty());
        ASSERT_EQ(found.stages.size(), 4u);
        const Pose best = found.candidates.front().pose;
        const double mtre = targetRegistrationError(draw.pose, best, setup, volume.center(), targets).meanMm;
        met += mtre < 1.0;
        // Which of the scan's hypotheses (by its rank) the answer came from, and each stage's time.
        std::printf("%s draw %2d (%s) truth %s found %s: mTRE %.3f mm, %.2f s, hypothesis %d;", name, seed,
                    draw.view.c_str(), formatPose(draw.pose).c_str(), formatPose(best).c_str(), mtre,
                    findSeconds(found.stages), found.candidates.front().hypothesis);
        for (const FindStage& stage : found.stages) std::printf(" %s %.2f", stage.name.c_str(), stage.seconds);
        std::printf("\n");
    }
    std::printf("%s: %d of %d within 1 mm\n", name, met, draws);
    EXPECT_GE(met, static_cast<int>(std::ceil(0.95 * draws))) << name;
}

TEST(ViewFinderProof, KneePhantomHardDraws) { findHardDraws(makeKneePhantom(), "knee phantom"); }

TEST(ViewFinderProof, ExampleCtHardDraws) {
    FM_REQUIRE_SHARED_DATA("totalseg-example-ct/example_ct.nii.gz");
    findHardDraws(readVolume(test::sharedDataDir() / "totalseg-example-ct/example_ct.nii.gz"), "example_ct");
}

}  // namespace
}  // namespace fm

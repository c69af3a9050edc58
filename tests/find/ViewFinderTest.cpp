// Finding the 2011 scene's pose with no start (find/ViewFinder.h).
#include <cstdio>
#include <cstdlib>

#include <gtest/gtest.h>

#include "common/TestData.h"
#include "drr/Drr.h"
#include "find/ViewFinder.h"
#include "match/PoseError.h"
#include "match/ReferenceDraw.h"
#include "phantom/KneePhantom.h"
#include "search/RegistrationTargets.h"
#include "io/ReadVolume.h"

namespace fm {
namespace {

void drawAndFind(const Volume& volume, const char* name, int draws) {
    const DrrVolumePtr prepared = prepareDrrVolume(volume, {});
    const SceneSetup setup = defaultSceneSetup();
    const auto points = boneTargetPoints(volume);
    const auto targets = registrationTargets(volume);
    RegistrationSettings finish;
    finish.coarseVolumeRatio = 1.25;
    finish.dropLevelsFinerThanVoxels = true;
    int met = 0;
    for (int seed = 1; seed <= draws; ++seed) {
        const ReferenceDraw draw = drawReferencePose(points, volume.center(), setup, Pose{}, seed, Difficulty::Hard, 100.0);
        DrrRenderOptions o;
        const Image reference = renderDrr(*prepared, sceneGeometry(draw.pose, setup, volume.center()), o);
        const FoundView found = findScenePose(prepared, setup, volume.center(), reference, finish, {});
        const Pose best = found.candidates.front().pose;
        const double mtre = targetRegistrationError(draw.pose, best, setup, volume.center(), targets).meanMm;
        met += mtre < 1.0;
        std::printf("%s seed %2d truth %-40s found %-40s mTRE %8.3f  %.2f s\n", name, seed, formatPose(draw.pose).c_str(),
                    formatPose(best).c_str(), mtre, findSeconds(found.stages));
        for (const std::string& line : describeFindStages(found.stages)) std::printf("    %s\n", line.c_str());
    }
    std::printf("%s: %d of %d within 1 mm\n", name, met, draws);
}

TEST(ViewFinder, Experiment) {
    const char* n = std::getenv("FM_VIEW_DRAWS");
    if (!n) GTEST_SKIP();
    drawAndFind(makeKneePhantom(), "knee", std::atoi(n));
    drawAndFind(readVolume(test::sharedDataDir() / "totalseg-example-ct/example_ct.nii.gz"), "example_ct", std::atoi(n));
}

}  // namespace
}  // namespace fm

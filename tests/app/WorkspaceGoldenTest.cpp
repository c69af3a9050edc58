// The real X-ray workspace against golden PNGs (data/golden/, refreshed by
// scripts/refresh_goldens.sh): the JTML trial's frame 0160 and the wrist trial's frame 0099, and
// its 3D view: each object's surface drawn in its colour, and gone when hidden.
#include <gtest/gtest.h>

#include "GoldenImage.h"
#include "common/TestData.h"
#include "render/SceneRenderer.h"
#include "workspace/WorkspaceHeadless.h"

namespace fm::test {
namespace {

bool haveTrials() {
    return sharedDataBesideRepo() && std::filesystem::exists(sharedDataDir() / "jtml-kneel-tka-fluoro") &&
           std::filesystem::exists(sharedDataDir() / "autoscoper-bvr");
}

#define FM_REQUIRE_TRIALS()                                                                   \
    do {                                                                                      \
        FM_REQUIRE_SHARED_DATA("jtml-kneel-tka-fluoro");                                      \
        if (!haveTrials()) {                                                                  \
            if (underCI()) FAIL() << "under CI the shared data must be ../shared/data";       \
            GTEST_SKIP() << "the shipped trials need ../shared/data beside the repository";   \
        }                                                                                     \
    } while (0)

app::WorkspaceHeadlessOptions trialOptions(const char* trial) {
    app::WorkspaceHeadlessOptions o;
    o.source.trial = repoDir() / "data/trials" / trial;
    o.threads = 2;
    return o;
}

TEST(GoldenWorkspace, JtmlKneeFrame0160) {
    FM_REQUIRE_TRIALS();
    EXPECT_TRUE(matchesGolden(app::renderWorkspaceHeadless(trialOptions("jtml-knee.json")), "workspace_jtml"));
}

TEST(GoldenWorkspace, WristFrame0099SideBySide) {
    FM_REQUIRE_TRIALS();
    app::WorkspaceHeadlessOptions o = trialOptions("wrist.json");
    o.frame = 1;
    o.sideBySide = true;
    EXPECT_TRUE(matchesGolden(app::renderWorkspaceHeadless(o), "workspace_wrist"));
}

// Pixels of the 3D view within 40 of `colour` (the surfaces are shaded).
long pixelsNear(const std::vector<std::uint8_t>& rgba, const std::array<float, 3>& colour) {
    long n = 0;
    for (std::size_t i = 0; i + 3 < rgba.size(); i += 4) {
        bool near = true;
        for (int c = 0; c < 3; ++c) near = near && std::abs(int(rgba[i + c]) - int(255.0f * colour[c] * 0.8f)) < 60;
        n += near && rgba[i] > rgba[i + 1] + 80;  // red: the femur
    }
    return n;
}

TEST(GoldenWorkspace, TheThreeDViewShowsTheImplantsAndHidesTheHiddenOne) {
    FM_REQUIRE_TRIALS();
    long shown = 0, hidden = 0;
    app::renderWorkspaceHeadless(trialOptions("jtml-knee.json"), [&](app::WorkspaceApp& a) {
        a.state().view.zoom = 6.0f;  // close to the implants
        a.frame();
        shown = pixelsNear(a.sceneRenderer().readPixels(), a.state().objects[0].color);
        a.state().objects[0].visible = false;
        a.frame();
        hidden = pixelsNear(a.sceneRenderer().readPixels(), a.state().objects[0].color);
    });
    EXPECT_GT(shown, 200);
    EXPECT_LT(hidden, shown / 20);
}

}  // namespace
}  // namespace fm::test

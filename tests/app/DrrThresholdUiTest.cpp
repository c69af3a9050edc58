// The bone-only DRR control (issue 16): off by default (the images are the engine's plain
// DRRs); ticked, both panes show exactly the engine's DRRs of the volume prepared with the
// threshold, darker everywhere, with the soft-tissue-only rays gone; the level applies on
// release; it survives loading another CT; it is hidden in the slice mode.
#include <optional>

#include "AppFixture.h"
#include "drr/Drr.h"
#include "scene/DrrCache.h"
#include "scene/LoadedScene.h"

namespace fm::test {
namespace {

using DrrThresholdUi = HeadlessApp;

// The app's DRR of `pose`, prepared here from the scene's volume with `threshold`.
Image engineDrr(const app::LoadedScene& scene, const Pose& pose,
                std::optional<double> threshold) {
    DrrValueOptions values = app::appDrrValueOptions(*scene.volume);
    values.thresholdHU = threshold;
    const DrrVolumePtr prepared = prepareDrrVolume(*scene.volume, values);
    DrrRenderOptions options;
    options.threads = kTestDrrThreads;
    return renderDrr(*prepared, app::appGeometry(scene, pose), options);
}

TEST_F(DrrThresholdUi, OffByDefaultBoneOnlyWhenTickedAndBackWhenUnticked) {
    const app::DrrThreshold& t = app->state().drrThreshold;
    EXPECT_FALSE(t.enabled);
    EXPECT_TRUE(t.valuesInHu) << "the knee phantom is a CT in HU";
    EXPECT_EQ(t.level, float(app->scene()->isoValue)) << "starts at the bone level";
    const Pose user = app->state().userPose, reference = app->state().referencePose;
    const Image full = app->userDrr();
    ASSERT_EQ(full.pixels, engineDrr(*app->scene(), user, std::nullopt).pixels);

    script->clickWidget("checkbox:bone-only");
    script->idle(1);
    ASSERT_TRUE(t.enabled);
    const Image bone = app->userDrr();
    EXPECT_EQ(bone.pixels, engineDrr(*app->scene(), user, t.level).pixels);
    EXPECT_EQ(app->referenceDrr().pixels, engineDrr(*app->scene(), reference, t.level).pixels);
    // Only voxels are left out: no pixel gets brighter, and rays through soft tissue alone
    // (the leg's outline) are empty now.
    int darker = 0, emptied = 0;
    for (std::size_t i = 0; i < full.pixels.size(); ++i) {
        EXPECT_LE(bone.pixels[i], full.pixels[i] * (1.0f + 1e-5f) + 1e-6f) << "pixel " << i;
        darker += bone.pixels[i] < 0.9f * full.pixels[i];
        emptied += full.pixels[i] > 0.0f && bone.pixels[i] == 0.0f;
    }
    EXPECT_GT(darker, int(full.pixels.size()) / 10);
    EXPECT_GT(emptied, 100);
    EXPECT_EQ(app->state().userPose.toArray(), user.toArray()) << "the poses stay";
    EXPECT_EQ(app->state().referencePose.toArray(), reference.toArray());

    script->clickWidget("checkbox:bone-only");
    script->idle(1);
    EXPECT_EQ(app->userDrr().pixels, full.pixels) << "off again: the plain DRR, bit for bit";
}

TEST_F(DrrThresholdUi, TheLevelAppliesOnceTheDragEnds) {
    script->clickWidget("checkbox:bone-only");
    script->idle(1);
    const float before = app->state().drrThreshold.level;
    const auto generation = app->scene()->generation;
    const app::WidgetRect field = script->widget("drag:bone-threshold");
    script->drag(field.center(), field.center() + glm::vec2(30.0f, 0.0f), 5);
    script->idle(1);
    const float after = app->state().drrThreshold.level;
    EXPECT_GT(after, before) << "dragging right raises the level";
    EXPECT_NE(app->scene()->generation, generation);
    EXPECT_EQ(app->userDrr().pixels,
              engineDrr(*app->scene(), app->state().userPose, after).pixels);
    // Nothing more to prepare while nothing changes.
    const auto settled = app->scene()->generation;
    script->idle(3);
    EXPECT_EQ(app->scene()->generation, settled);
}

TEST_F(DrrThresholdUi, StaysOnForTheNextCtAtItsBoneLevel) {
    script->clickWidget("checkbox:bone-only");
    script->idle(1);
    app->state().volumePathField = "phantom:knee,flexion=30";
    script->clickWidget("button:open");
    app->waitForLoad();
    script->idle(2);
    ASSERT_EQ(app->state().load.loadedSpec, "phantom:knee,flexion=30") << app->state().load.error;
    const app::DrrThreshold& t = app->state().drrThreshold;
    EXPECT_TRUE(t.enabled);
    EXPECT_EQ(t.level, float(app->scene()->isoValue));
    EXPECT_EQ(app->userDrr().pixels,
              engineDrr(*app->scene(), app->state().userPose, t.level).pixels);
}

TEST_F(DrrThresholdUi, TheKneesBoneObjectsAreThresholdedToo) {
    // With the femur hidden the DRR is drawn from the knee's bone objects (Bones tab), the
    // soft tissue being the object "rest": bone-only must empty its rays there too.
    ASSERT_FALSE(app->state().bones.list.empty());
    app->state().bones.list[0].visible = false;
    script->idle(2);
    const Image plain = app->userDrr();
    script->clickWidget("checkbox:bone-only");
    script->idle(1);
    ASSERT_TRUE(app->state().drrThreshold.enabled);
    EXPECT_FALSE(app->state().bones.list[0].visible) << "the bone list stays as it was";
    const Image bone = app->userDrr();
    ASSERT_EQ(bone.pixels.size(), plain.pixels.size());
    int emptied = 0;
    for (std::size_t i = 0; i < plain.pixels.size(); ++i) {
        EXPECT_LE(bone.pixels[i], plain.pixels[i] * (1.0f + 1e-5f) + 1e-6f) << "pixel " << i;
        emptied += plain.pixels[i] > 0.0f && bone.pixels[i] == 0.0f;
    }
    EXPECT_GT(emptied, 100);
}

TEST_F(DrrThresholdUi, HiddenInTheSliceMode) {
    EXPECT_TRUE(app->ui().rect("checkbox:bone-only").has_value());
    script->clickWidget("radio:mode-slice");
    script->idle(2);
    EXPECT_FALSE(app->ui().rect("checkbox:bone-only").has_value());
}

}  // namespace
}  // namespace fm::test

// The 2D panes as the field's viewers: wheel zoom about the mouse, right/middle-drag pan, left
// drag window/level, the pixel readout (checked against the engine's own DRR), orientation
// letters, and the enlarged compare view.
#include <imgui.h>

#include <algorithm>
#include <cmath>

#include "AppFixture.h"
#include "drr/Drr.h"
#include "geometry/PatientDirection.h"
#include "scene/DrrCache.h"

namespace fm::test {
namespace {

using ImagePaneUi = HeadlessApp;

TEST_F(ImagePaneUi, ReadoutGivesThePixelAndItsValue) {
    const app::WidgetRect r = script->widget("image:user");
    // The centre of pixel (64, 128) of the 256 x 256 DRR.
    const glm::vec2 at(r.min.x + (64.5f / 256.0f) * (r.max.x - r.min.x),
                       r.min.y + (128.5f / 256.0f) * (r.max.y - r.min.y));
    script->moveTo(at);
    const app::PixelReadout& p = app->state().readout;
    ASSERT_TRUE(p.valid);
    EXPECT_EQ(p.pane, "image:user");
    const int width = app->userDrr().width;
    ASSERT_EQ(width, 256);
    EXPECT_EQ(p.col, 64);
    EXPECT_EQ(p.row, 128);
    // The value is the engine's DRR at that pixel (rendered here independently).
    DrrRenderOptions options;
    options.threads = kTestDrrThreads;
    const Image drr = renderDrr(*app->scene()->drrVolume,
                                app::appGeometry(*app->scene(), app->state().userPose), options);
    EXPECT_EQ(p.value, drr.at(p.col, p.row));
    EXPECT_TRUE(p.hasData) << "every DRR pixel holds a line integral";
    script->moveTo({-100.0f, -100.0f});
    EXPECT_FALSE(app->state().readout.valid) << "no pixel under the mouse";
}

TEST_F(ImagePaneUi, WheelZoomsAboutTheMouseAndRightDragPans) {
    const app::WidgetRect r = script->widget("image:reference");
    const glm::vec2 corner = r.min + 0.25f * (r.max - r.min);  // texture point (0.25, 0.25)
    script->wheel(corner, 5.0f);
    const app::ImageView& v = app->state().imageView;
    EXPECT_NEAR(v.zoom, std::pow(1.15f, 5.0f), 1e-4);
    // The point under the mouse stays under it: u = centre + (0.25 - 0.5) / zoom, to within
    // the half screen pixel by which ImGui rounds the widget's corner.
    const float halfPixel = 0.5f / (r.max.x - r.min.x);
    EXPECT_NEAR(v.centerU + (0.25f - 0.5f) / v.zoom, 0.25f, halfPixel);
    EXPECT_NEAR(v.centerV + (0.25f - 0.5f) / v.zoom, 0.25f, halfPixel);
    const float u = v.centerU;
    script->drag(r.center(), r.center() + glm::vec2(-20.0f, 0.0f), 4, 1);
    const float side = r.max.x - r.min.x;
    EXPECT_NEAR(app->state().imageView.centerU, u + 20.0f / side / v.zoom, 1e-4)
        << "dragging left shows what lies to the right";
    // The three images share the view.
    script->moveTo(script->widget("image:user").center());
    EXPECT_NEAR(app->state().readout.col, int(app->state().imageView.centerU * 256), 1);
}

TEST_F(ImagePaneUi, LeftDragSetsWindowAndLevel) {
    const float window = app->state().display.window, level = app->state().display.level;
    ASSERT_TRUE(app->state().display.autoWindow);
    const app::WidgetRect r = script->widget("image:user");
    script->drag(r.center(), r.center() + glm::vec2(40.0f, 0.0f), 4);
    EXPECT_FALSE(app->state().display.autoWindow);
    EXPECT_GT(app->state().display.window, window) << "right widens the window";
    EXPECT_FLOAT_EQ(app->state().display.level, level);
    script->drag(r.center(), r.center() + glm::vec2(0.0f, 30.0f), 3);
    EXPECT_GT(app->state().display.level, level) << "down raises the level";
}

// The auto window is the reference's whole range, kept from frame to frame and found again for
// a new reference.
TEST_F(ImagePaneUi, AutoWindowFollowsANewReference) {
    ASSERT_TRUE(app->state().display.autoWindow);
    auto expectWholeRange = [&] {
        const auto [lo, hi] = std::minmax_element(app->referenceDrr().pixels.begin(),
                                                  app->referenceDrr().pixels.end());
        EXPECT_FLOAT_EQ(app->state().display.window, *hi - *lo);
        EXPECT_FLOAT_EQ(app->state().display.level, 0.5f * (*hi + *lo));
    };
    expectWholeRange();
    const float window = app->state().display.window;
    app->state().requests.newReference = true;
    script->idle(2);
    ASSERT_NE(app->state().display.window, window) << "another reference, another range";
    expectWholeRange();
}

TEST_F(ImagePaneUi, OrientationLettersFollowThePose) {
    // The user starts at the AP view: superior at the top (engine/geometry's letters).
    EXPECT_EQ(app->state().userEdges.top, "S");
    EXPECT_EQ(app->state().userEdges.bottom, "I");
    const ImageEdgeLetters expected =
        imageEdgeLetters(app::appGeometry(*app->scene(), app->state().referencePose));
    EXPECT_EQ(app->state().referenceEdges.left, expected.left);
    EXPECT_EQ(app->state().referenceEdges.right, expected.right);
    app->state().userPose.azimuthDeg = 90.0;  // lateral: anterior / posterior at the sides
    script->idle(2);
    const std::string sides = app->state().userEdges.left + app->state().userEdges.right;
    EXPECT_TRUE(sides == "AP" || sides == "PA") << sides;
}

TEST_F(ImagePaneUi, CompareEnlargesAndEscapeCloses) {
    script->clickWidget("button:enlarge-compare");
    ASSERT_TRUE(app->state().compareEnlarged);
    script->idle(1);
    const app::WidgetRect big = script->widget("image:compare-large");
    const app::WidgetRect small = script->widget("image:compare");
    EXPECT_GT(big.max.x - big.min.x, 2.0f * (small.max.x - small.min.x));
    script->pressKey(ImGuiKey_Escape);
    EXPECT_FALSE(app->state().compareEnlarged);
}

}  // namespace
}  // namespace fm::test

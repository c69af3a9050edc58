// Rendering regression tests: the headless UI and the 3D view against golden PNGs in
// data/golden/ (refresh with scripts/refresh_goldens.sh after an intended change).
#include "AppFixture.h"
#include "GoldenImage.h"
#include "render/SceneRenderer.h"

namespace fm::test {
namespace {

using GoldenUi = HeadlessApp;

TEST_F(GoldenUi, DefaultState) {
    EXPECT_TRUE(matchesGolden(app->capture(), "ui_default"));
}

TEST_F(GoldenUi, AfterAScriptedSliderDrag) {
    const app::WidgetRect slider = script->widget("slider:azimuth");
    script->drag(slider.center(),
                 {slider.min.x + 0.3f * (slider.max.x - slider.min.x), slider.center().y}, 6);
    script->idle(1);
    ASSERT_LT(app->state().userPose.azimuthDeg, 0.0);
    EXPECT_TRUE(matchesGolden(app->capture(), "ui_after_drag"));
}

TEST_F(GoldenUi, AfterMatchWithHints) {
    app->state().userPose = parsePose("0,0,0,10,0,0");
    script->clickWidget("button:match");
    script->idle(1);
    ASSERT_TRUE(app->state().match.has_value());
    ASSERT_FALSE(app->state().match->matched);
    EXPECT_TRUE(matchesGolden(app->capture(), "ui_after_match"));
}

TEST_F(GoldenUi, HelpWindow) {
    script->clickWidget("button:help");
    script->idle(1);
    EXPECT_TRUE(matchesGolden(app->capture(), "ui_help"));
}

// One bone hidden: the Bones tab with the femur unticked, both DRRs and the 3D view without it.
TEST_F(GoldenUi, BonesTabWithTheFemurHidden) {
    script->clickWidget("tab:bones");
    script->clickWidget("checkbox:bone-femur");
    script->idle(1);
    ASSERT_FALSE(app->state().bones.list.at(0).visible);
    EXPECT_TRUE(matchesGolden(app->capture(), "ui_bones_femur_hidden"));
}

// The 3D view alone (bones in their colours, CT box and axes, source, film, cone) from two
// camera angles.
void expectSceneGolden(app::App& app, const app::View3d& view, const std::string& name) {
    app.state().view = view;
    app.frame();
    const auto& renderer = app.sceneRenderer();
    render::RgbaImage image{renderer.size().x, renderer.size().y, renderer.readPixels()};
    EXPECT_TRUE(matchesGolden(image, name));
}

TEST_F(GoldenUi, ThreeDViewFromTheFront) {
    app::View3d view;
    view.azimuthDeg = 35.0f;
    view.elevationDeg = 25.0f;
    view.zoom = 1.6f;
    expectSceneGolden(*app, view, "view3d_front");
}

TEST_F(GoldenUi, ThreeDViewFromAboveBehind) {
    app::View3d view;
    view.azimuthDeg = -140.0f;
    view.elevationDeg = 55.0f;
    view.zoom = 2.4f;
    expectSceneGolden(*app, view, "view3d_above_behind");
}

// The MRI slice mode on the knee phantom (self-contained): both panes show slices, the 3D view
// the plane cutting the box inside a translucent surface.
class GoldenSliceUi : public HeadlessApp {
  protected:
    void SetUp() override {
        app::AppOptions options = testAppOptions();
        options.mode = app::ImagingMode::Slice;
        options.userPose = parsePose("0,0,0,20,10,0");
        start(options);
    }
};

TEST_F(GoldenSliceUi, SliceMode) {
    ASSERT_EQ(app->state().mode, app::ImagingMode::Slice);
    EXPECT_TRUE(matchesGolden(app->capture(), "ui_slice_mode"));
}

TEST_F(GoldenSliceUi, ThreeDViewOfTheSlicePlane) {
    app::View3d view;
    view.azimuthDeg = 35.0f;
    view.elevationDeg = 25.0f;
    view.zoom = 1.3f;
    expectSceneGolden(*app, view, "view3d_slice");
}

}  // namespace
}  // namespace fm::test

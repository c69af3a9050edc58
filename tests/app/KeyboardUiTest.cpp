// The keyboard: select a parameter, nudge it by a step (fine with Shift), Enter presses Match,
// Escape closes Help; keys typed into a field stay the field's.
#include <imgui.h>

#include "AppFixture.h"

namespace fm::test {
namespace {

using KeyboardUi = HeadlessApp;

TEST_F(KeyboardUi, ArrowsSelectAndNudgeTheParameters) {
    app::AppState& s = app->state();
    ASSERT_EQ(s.selectedParameter, app::kOffsetX);
    script->pressKey(ImGuiKey_RightArrow);
    EXPECT_DOUBLE_EQ(s.userPose.offset.x, 1.0);
    script->pressKey(ImGuiKey_RightArrow, false, /*shift=*/true);
    EXPECT_DOUBLE_EQ(s.userPose.offset.x, 1.1) << "Shift: a fine step of 0.1 mm";
    script->pressKey(ImGuiKey_DownArrow);
    EXPECT_EQ(s.selectedParameter, app::kOffsetY);
    script->pressKey(ImGuiKey_LeftArrow);
    EXPECT_DOUBLE_EQ(s.userPose.offset.y, -1.0);
    EXPECT_DOUBLE_EQ(s.userPose.offset.x, 1.1) << "only the selected parameter moves";
    // Up from the first wraps to the last (rotation).
    script->pressKey(ImGuiKey_UpArrow);
    script->pressKey(ImGuiKey_UpArrow);
    EXPECT_EQ(s.selectedParameter, app::kRotation);
    script->pressKey(ImGuiKey_RightArrow);
    EXPECT_DOUBLE_EQ(s.userPose.rotationDeg, 1.0);
    // Clamped at the slider's end.
    s.userPose.rotationDeg = 89.5;
    script->pressKey(ImGuiKey_RightArrow);
    EXPECT_DOUBLE_EQ(s.userPose.rotationDeg, 90.0);
    // A click on a slider selects its parameter for the keys.
    script->clickWidget("input:elevation");
    script->pressKey(ImGuiKey_Escape);  // leave the field
    EXPECT_EQ(s.selectedParameter, app::kElevation);
}

TEST_F(KeyboardUi, TheWheelOverASliderPlacesAMillimetre) {
    app::AppState& s = app->state();
    const app::WidgetRect slider = script->widget("slider:z-offset");
    // A slider pixel spans more than a millimetre: a drag alone cannot place one.
    EXPECT_GT(2.0 * s.translationRangeMm / (slider.max.x - slider.min.x), 1.0);
    script->wheel(slider.center(), 1.0f);
    EXPECT_DOUBLE_EQ(s.userPose.offset.z, 1.0);
    EXPECT_EQ(s.selectedParameter, app::kOffsetZ) << "the wheel selects what it moves";
    script->wheel(slider.center(), -1.0f);
    script->wheel(slider.center(), -1.0f);
    EXPECT_DOUBLE_EQ(s.userPose.offset.z, -1.0);
    // With Shift: a tenth.
    app::FrameInput fine;
    fine.mousePos = slider.center();
    fine.wheel = 1.0f;
    fine.shift = true;
    backend->setFrameInput(fine);
    app->frame();
    EXPECT_DOUBLE_EQ(s.userPose.offset.z, -0.9);
    EXPECT_DOUBLE_EQ(s.userPose.offset.x, 0.0) << "only the slider under the mouse";
    // Clamped at the slider's end.
    s.userPose.offset.z = s.translationRangeMm - 0.5;
    script->wheel(slider.center(), 1.0f);
    EXPECT_DOUBLE_EQ(s.userPose.offset.z, s.translationRangeMm);
}

TEST_F(KeyboardUi, EnterPressesMatchButNotWhileTypingInAField) {
    script->pressKey(ImGuiKey_Enter);
    EXPECT_EQ(app->state().attempts, 1);
    ASSERT_TRUE(app->state().match.has_value());
    // Typing a value and confirming it with Enter is no attempt.
    script->clickWidget("input:azimuth");
    script->type("12");
    script->pressKey(ImGuiKey_Enter);
    EXPECT_DOUBLE_EQ(app->state().userPose.azimuthDeg, 12.0);
    EXPECT_EQ(app->state().attempts, 1);
    // Nor do the arrows nudge while a field has the keyboard.
    script->clickWidget("input:azimuth");
    script->pressKey(ImGuiKey_RightArrow);
    script->pressKey(ImGuiKey_Enter);
    EXPECT_DOUBLE_EQ(app->state().userPose.azimuthDeg, 12.0);
}

TEST_F(KeyboardUi, EscapeClosesHelp) {
    script->clickWidget("button:help");
    ASSERT_TRUE(app->state().showHelp);
    script->pressKey(ImGuiKey_Escape);
    EXPECT_FALSE(app->state().showHelp);
}

}  // namespace
}  // namespace fm::test

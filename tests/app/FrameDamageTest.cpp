// Redrawing only what changed: the damage rectangles on hand-made frames, and the kept frame of
// a live App compared pixel for pixel with a whole redraw of the same frame.
#include <gtest/gtest.h>

#include "AppFixture.h"
#include "ui/FrameDamage.h"

namespace fm::test {
namespace {

app::DrawnTriangle triangle(float x, float y, float size, ImU32 color = 0xffffffff) {
    app::DrawnTriangle t;
    const ImVec2 corners[3] = {{x, y}, {x + size, y}, {x, y + size}};
    for (int k = 0; k < 3; ++k) t.vertices[k] = ImDrawVert{corners[k], ImVec2(0, 0), color};
    t.scissor = {0, 0, 100, 100};
    t.reach = app::intersect({int(x) - 1, int(y) - 1, int(x + size) + 1, int(y + size) + 1},
                             t.scissor);
    return t;
}

app::FrameDrawing frameOf(std::vector<std::vector<app::DrawnTriangle>> lists) {
    app::FrameDrawing f;
    f.size = {100, 100};
    f.lists = std::move(lists);
    f.comparable = true;
    return f;
}

TEST(FrameDamage, TheSameFrameNeedsNoRedraw) {
    const auto f = frameOf({{triangle(10, 10, 5), triangle(50, 50, 5)}});
    EXPECT_TRUE(app::damagedRects(f, f).empty());
}

TEST(FrameDamage, AMovedTriangleDamagesWhereItWasAndWhereItIs) {
    const auto before = frameOf({{triangle(10, 10, 5), triangle(20, 20, 5), triangle(80, 80, 5)}});
    const auto now = frameOf({{triangle(10, 10, 5), triangle(30, 20, 5), triangle(80, 80, 5)}});
    const auto rects = app::damagedRects(before, now);
    ASSERT_EQ(rects.size(), 1u);
    EXPECT_EQ(rects[0], (app::PixelRect{19, 19, 36, 26}));  // old and new boxes, not the others
}

TEST(FrameDamage, ANewTextureVersionDamagesTheTrianglesShowingIt) {
    auto image = triangle(40, 40, 10);
    const auto before = frameOf({{triangle(10, 10, 5), image}});
    image.textureVersion = 7;
    const auto now = frameOf({{triangle(10, 10, 5), image}});
    const auto rects = app::damagedRects(before, now);
    ASSERT_EQ(rects.size(), 1u);
    EXPECT_EQ(rects[0], image.reach);
}

TEST(FrameDamage, AListThatAppearsOrGoesIsDamagedWhole) {
    const auto before = frameOf({{triangle(10, 10, 5)}});
    const auto now = frameOf({{triangle(10, 10, 5)}, {triangle(60, 60, 10)}});
    EXPECT_EQ(app::damagedRects(before, now), (std::vector<app::PixelRect>{{59, 59, 71, 71}}));
    EXPECT_EQ(app::damagedRects(now, before), (std::vector<app::PixelRect>{{59, 59, 71, 71}}));
}

TEST(FrameDamage, FramesThatCannotBeComparedAreDrawnWhole) {
    const auto f = frameOf({{triangle(10, 10, 5)}});
    auto other = f;
    other.comparable = false;
    const std::vector<app::PixelRect> whole{{0, 0, 100, 100}};
    EXPECT_EQ(app::damagedRects(f, other), whole);
    EXPECT_EQ(app::damagedRects(app::FrameDrawing{}, f), whole) << "nothing kept yet";
}

TEST(FrameDamage, OverlappingRectanglesMergeUntilDisjoint) {
    const auto rects = app::disjointRects({{0, 0, 10, 10}, {20, 0, 30, 10}, {5, 5, 25, 8}, {50, 50, 60, 60}, {3, 3, 3, 9}});
    EXPECT_EQ(rects, (std::vector<app::PixelRect>{{0, 0, 30, 10}, {50, 50, 60, 60}}));
}

TEST(FrameDamage, ScissorsFollowTheBackendsIntegerArithmetic) {
    // glScissor((int)min.x, (int)(fb_height - max.y), (int)(max.x - min.x), (int)(max.y - min.y))
    // x (int)10.5 = 10, width (int)20.25 = 20; GL y (int)(100 - 40.5) = 59, height (int)20.25 =
    // 20: GL rows 59..78 from the bottom are rows 21..40 from the top.
    EXPECT_EQ(app::commandScissor(ImVec4(10.5f, 20.25f, 30.75f, 40.5f), {100, 100}),
              (app::PixelRect{10, 21, 30, 41}));
    EXPECT_TRUE(app::commandScissor(ImVec4(10, 10, 10, 20), {100, 100}).empty());
    EXPECT_EQ(app::commandScissor(ImVec4(-5, -5, 200, 200), {100, 100}),
              (app::PixelRect{0, 0, 100, 100}));
}

// The App's frames redrawn in part look exactly like the same frames drawn whole: a drag of a
// pose slider and of the 3D view, typing, a tooltip and a tab switch.
TEST_F(HeadlessApp, FramesRedrawnInPartEqualWholeRedraws) {
    app->presenter().checkEveryFrame(true);
    const int framesBefore = app->presenter().stats().frames;
    const app::WidgetRect slider = script->widget("slider:azimuth");
    script->drag(slider.center(), {slider.max.x - 10.0f, slider.center().y}, 6);
    const app::WidgetRect view = script->widget("view:3d");
    script->drag(view.center(), view.center() + glm::vec2(40, 10), 3);
    script->clickWidget("input:elevation");
    script->type("12");
    script->pressKey(ImGuiKey_Enter);
    script->moveTo(script->widget("button:new-reference").center());
    script->idle(40);  // the tooltip shows after a delay
    script->clickWidget("button:new-reference");
    script->idle(2);
    const auto& stats = app->presenter().stats();
    const int frames = stats.frames - framesBefore;
    ASSERT_GT(frames, 60);
    EXPECT_EQ(stats.mismatchedFrames, 0);
    // Most frames redraw a small part: less than half the window's pixels on average.
    const auto size = backend->framebufferSize();
    EXPECT_LT(double(stats.drawnPixels) / (double(stats.frames) * size.x * size.y), 0.5);
}

}  // namespace
}  // namespace fm::test

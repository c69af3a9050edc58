// Where tooltips go (app/ui/TooltipPlacement.h): beside the mouse, on screen, never over the
// rectangle to avoid (the load progress bar).
#include <gtest/gtest.h>

#include "ui/TooltipPlacement.h"

namespace fm::test {
namespace {

using app::placeTooltip;
using app::ScreenRect;

const glm::vec2 kDisplay{960.0f, 600.0f};

bool onScreen(glm::vec2 p, glm::vec2 size) {
    return p.x >= 0 && p.y >= 0 && p.x + size.x <= kDisplay.x && p.y + size.y <= kDisplay.y;
}

TEST(TooltipPlacement, BelowRightOfTheMouseWhenThereIsRoom) {
    const glm::vec2 p = placeTooltip({100, 100}, {200, 40}, kDisplay, std::nullopt);
    EXPECT_EQ(p, glm::vec2(116, 124));
}

TEST(TooltipPlacement, AboveTheMouseAtTheBottomAndShiftedLeftAtTheRightEdge) {
    const glm::vec2 size{200, 40};
    const glm::vec2 p = placeTooltip({900, 590}, size, kDisplay, std::nullopt);
    EXPECT_EQ(p.y, 590 - 8 - 40.0f) << "above the mouse";
    EXPECT_EQ(p.x, kDisplay.x - size.x) << "flush with the right edge";
    EXPECT_TRUE(onScreen(p, size));
}

TEST(TooltipPlacement, NeverCoversTheRectangleToAvoid) {
    // A progress bar across the bottom-left pane, as the app draws it.
    const ScreenRect bar{{8, 520}, {312, 539}};
    const glm::vec2 size{300, 45};
    // Every mouse position over the left third of the screen: never over the bar, on screen.
    for (float y = 0; y <= kDisplay.y; y += 5)
        for (float x = 0; x <= 320; x += 16) {
            const glm::vec2 p = placeTooltip({x, y}, size, kDisplay, bar);
            EXPECT_FALSE((ScreenRect{p, p + size}.overlaps(bar))) << x << ", " << y;
            EXPECT_TRUE(onScreen(p, size)) << x << ", " << y;
        }
    // Just above the bar the tooltip (which would hang over it) goes to the nearer side: just
    // below the bar; higher up, just above it.
    EXPECT_EQ(placeTooltip({100, 505}, size, kDisplay, bar).y, bar.max.y + 4);
    EXPECT_EQ(placeTooltip({100, 470}, size, kDisplay, bar).y, bar.min.y - 4 - size.y);
}

TEST(TooltipPlacement, BesideTheRectangleWhenNeitherAboveNorBelowFits) {
    const ScreenRect tall{{100, 10}, {300, 590}};
    const glm::vec2 size{200, 300};
    const glm::vec2 p = placeTooltip({150, 200}, size, kDisplay, tall);
    EXPECT_FALSE((ScreenRect{p, p + size}.overlaps(tall)));
    EXPECT_EQ(p.x, 304.0f);
}

TEST(TooltipPlacement, RectanglesThatOnlyTouchDoNotOverlap) {
    EXPECT_FALSE((ScreenRect{{0, 0}, {10, 10}}.overlaps(ScreenRect{{10, 0}, {20, 10}})));
    EXPECT_TRUE((ScreenRect{{0, 0}, {10, 10}}.overlaps(ScreenRect{{9, 9}, {20, 20}})));
}

}  // namespace
}  // namespace fm::test

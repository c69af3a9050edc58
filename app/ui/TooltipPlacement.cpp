#include "ui/TooltipPlacement.h"

#include <algorithm>
#include <cmath>

namespace fm::app {
namespace {

// ImGui's offsets of a tooltip from the mouse (clear of the cursor's arrow).
constexpr glm::vec2 kBelowRight{16.0f, 24.0f};
constexpr float kAbove = 8.0f;
constexpr float kGap = 4.0f;  // between the tooltip and what it avoids

float clampTo(float v, float size, float extent) {
    return std::max(0.0f, std::min(v, extent - size));
}

bool fits(float start, float size, float extent) {
    return start >= 0.0f && start + size <= extent;
}

}  // namespace

glm::vec2 placeTooltip(glm::vec2 mouse, glm::vec2 size, glm::vec2 display,
                       const std::optional<ScreenRect>& avoid) {
    glm::vec2 p = mouse + kBelowRight;
    if (p.y + size.y > display.y) p.y = mouse.y - kAbove - size.y;
    p.x = clampTo(p.x, size.x, display.x);
    p.y = clampTo(p.y, size.y, display.y);
    if (!avoid || !ScreenRect{p, p + size}.overlaps(*avoid)) return p;

    // Off the rectangle vertically first (the tooltip stays near the mouse's column) ...
    const float above = avoid->min.y - kGap - size.y, below = avoid->max.y + kGap;
    const bool aboveFits = fits(above, size.y, display.y), belowFits = fits(below, size.y, display.y);
    if (aboveFits || belowFits) {
        const bool useAbove =
            aboveFits && (!belowFits || std::abs(above - p.y) <= std::abs(below - p.y));
        return {p.x, useAbove ? above : below};
    }
    // ... else beside it.
    const float right = avoid->max.x + kGap, left = avoid->min.x - kGap - size.x;
    if (fits(right, size.x, display.x)) return {right, p.y};
    if (fits(left, size.x, display.x)) return {left, p.y};
    return p;  // larger than the screen around the rectangle: nothing better exists
}

}  // namespace fm::app

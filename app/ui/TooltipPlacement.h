#pragma once
// Where a tooltip goes: beside the mouse as ImGui puts it, kept on screen, and never over a
// rectangle that must stay visible (the load progress bar, issue 16). Pure geometry (screen
// pixels, top-left origin), so it is tested without a window.
#include <optional>

#include <glm/glm.hpp>

namespace fm::app {

struct ScreenRect {
    glm::vec2 min{0.0f}, max{0.0f};
    bool overlaps(const ScreenRect& o) const {
        return min.x < o.max.x && o.min.x < max.x && min.y < o.max.y && o.min.y < max.y;
    }
};

// The top-left corner for a tooltip of `size` with the mouse at `mouse` on a `display`:
// below right of the mouse, above it when there is no room below, shifted left at the right
// edge. When that would cover `avoid`, the tooltip moves just above or below `avoid`
// (whichever fits and is nearer), else beside it.
glm::vec2 placeTooltip(glm::vec2 mouse, glm::vec2 size, glm::vec2 display,
                       const std::optional<ScreenRect>& avoid);

}  // namespace fm::app

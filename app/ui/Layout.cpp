#include "ui/Layout.h"

#include <algorithm>

namespace fm::app {

Layout computeLayout(glm::vec2 display) {
    const float w = std::max(display.x, 300.0f), h = std::max(display.y, 200.0f);
    const float column = w / 3.0f;
    // Top row: square images plus a title bar and a caption line, at most 55% of the height.
    const float top = std::min(h * 0.55f, column + 40.0f);
    Layout l;
    l.reference = {{0.0f, 0.0f}, {column, top}};
    l.user = {{column, 0.0f}, {column, top}};
    l.scene3d = {{2.0f * column, 0.0f}, {w - 2.0f * column, top}};
    l.parameters = {{0.0f, top}, {column, h - top}};
    l.compare = {{column, top}, {column, h - top}};
    l.match = {{2.0f * column, top}, {w - 2.0f * column, h - top}};
    return l;
}

}  // namespace fm::app

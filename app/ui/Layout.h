#pragma once
// Fixed pane layout for a display size: the same size gives the same rectangles, so windowed
// and headless frames look alike and scripted tests find the widgets.
//   top row:    Reference DRR | Your DRR | 3D view
//   bottom row: Parameters    | Compare  | Match
#include <glm/glm.hpp>

namespace fm::app {

struct Pane {
    glm::vec2 pos{0.0f};
    glm::vec2 size{0.0f};
};

struct Layout {
    Pane reference, user, scene3d;
    Pane parameters, compare, match;
};

Layout computeLayout(glm::vec2 display);

}  // namespace fm::app

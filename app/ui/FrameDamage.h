#pragma once
// Which pixels of an ImGui frame can differ from the last frame's, from the two frames' draw
// lists: a pixel's colour is made by the triangles that cover it, in order, so where the same
// triangles (same vertices, scissor, texture and texture pixels) are drawn in the same order the
// pixel is the same and need not be drawn again. No GL: FramePresenter draws the rectangles.
#include <cstdint>
#include <functional>
#include <vector>

#include <imgui.h>

#include <glm/glm.hpp>

namespace fm::app {

// Framebuffer pixels [x0, x1) x [y0, y1), row 0 at the top.
struct PixelRect {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    bool empty() const { return x1 <= x0 || y1 <= y0; }
    std::int64_t area() const { return empty() ? 0 : std::int64_t(x1 - x0) * (y1 - y0); }
    bool operator==(const PixelRect&) const = default;
};
PixelRect intersect(const PixelRect& a, const PixelRect& b);
PixelRect unite(const PixelRect& a, const PixelRect& b);  // the bounding box (empty ignored)

// One triangle as ImGui's OpenGL3 backend draws it.
struct DrawnTriangle {
    ImDrawVert vertices[3];
    PixelRect scissor;  // the pixels its command's scissor lets it touch
    ImTextureID texture = nullptr;
    std::uint64_t textureVersion = 0;
    PixelRect reach;  // the pixels it can change: its bounding box within the scissor
};
bool sameTriangle(const DrawnTriangle& a, const DrawnTriangle& b);

// A frame's triangles, draw list by draw list.
struct FrameDrawing {
    glm::ivec2 size{0};
    std::vector<std::vector<DrawnTriangle>> lists;
    // False when the frame cannot be compared (user callbacks, a display offset or a scale):
    // the next frame is then drawn whole.
    bool comparable = false;
};

// The pixels the backend's scissor gives a command: its own float-to-int arithmetic, so a
// rectangle made of those pixels is exactly what it draws.
PixelRect commandScissor(const ImVec4& clipRect, glm::ivec2 framebuffer);

using TextureVersionOf = std::function<std::uint64_t(ImTextureID)>;
FrameDrawing recordDrawing(const ImDrawData& data, glm::ivec2 framebuffer,
                           const TextureVersionOf& versionOf);

// Disjoint rectangles that cover every pixel whose colour can differ between `before` and `now`
// (the whole frame when they cannot be compared). Empty: the frames look the same.
std::vector<PixelRect> damagedRects(const FrameDrawing& before, const FrameDrawing& now);

// Overlapping rectangles merged into their bounding boxes until none overlap.
std::vector<PixelRect> disjointRects(std::vector<PixelRect> rects);

// Restricts every command of `data` to the (disjoint) rectangles: a command is repeated once per
// rectangle it reaches, its clip rectangle the pixels of both. Drawing the result changes exactly
// those pixels, as the whole frame would. Needs a comparable frame (no callbacks, no offset).
void clipDrawData(ImDrawData& data, glm::ivec2 framebuffer, const std::vector<PixelRect>& rects);

}  // namespace fm::app

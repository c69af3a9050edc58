#pragma once
// The end of every window frame, the same for the matching game (App) and the real X-ray
// workspace (WorkspaceApp): ImGui's draw lists drawn into a frame kept from one frame to the next
// (OSMesa's own buffer; for a window, a framebuffer copied to it), where only the rectangles
// whose drawing changed are cleared and drawn again (FrameDamage.h); then shown (a window) or
// finished (headless). On llvmpipe every pixel drawn costs CPU: a slider drag redraws its row and
// the images it changes, not the whole window.
#include <cstdint>
#include <vector>

#include "platform/Gl.h"
#include "platform/RenderBackend.h"
#include "render/Screenshot.h"
#include "ui/FrameDamage.h"

namespace fm::app {

class FramePresenter {
  public:
    FramePresenter() = default;
    ~FramePresenter();
    FramePresenter(const FramePresenter&) = delete;
    FramePresenter& operator=(const FramePresenter&) = delete;

    // After the UI code of a frame: ImGui::Render, draw what changed, present.
    void present(RenderBackend& backend);

    struct Stats {
        int frames = 0;
        std::int64_t lastDrawnPixels = 0;  // pixels cleared and drawn in the last frame
        std::int64_t drawnPixels = 0;      // ... summed over all frames
        int mismatchedFrames = 0;          // with checkEveryFrame: differed from a whole redraw
    };
    const Stats& stats() const { return stats_; }
    // Tests: also draw every frame whole (into the kept frame's target, which is then restored)
    // and count the frames whose partial redraw differs from it.
    void checkEveryFrame(bool on) { check_ = on; }
    // The next frame is drawn whole (e.g. after GL state outside ImGui's draw lists changed).
    void invalidate() { last_ = {}; }

  private:
    struct Target {
        GLuint fbo = 0, color = 0;
        void resize(glm::ivec2 size);
        void release();
    };
    void draw(ImDrawData& data, glm::ivec2 size, const std::vector<PixelRect>& rects);
    // The pixels of `data` drawn whole, the kept frame left as it was.
    std::vector<std::uint8_t> drawWholeForComparison(ImDrawData& data, glm::ivec2 size);

    Target kept_, saved_;  // saved_: the kept frame while the check draws over it
    glm::ivec2 size_{0}, savedSize_{0};
    FrameDrawing last_;
    Stats stats_;
    bool check_ = false;
};

// What the last frame showed, row 0 at the top (screenshots, golden images).
render::RgbaImage captureFrame(const RenderBackend& backend);

}  // namespace fm::app

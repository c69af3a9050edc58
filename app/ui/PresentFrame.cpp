#include "ui/PresentFrame.h"

#include <imgui.h>
#include <imgui_impl_opengl3.h>

#include "render/TextureVersions.h"

namespace fm::app {
namespace {

void bindAndClear(GLuint fbo, glm::ivec2 size, const std::vector<PixelRect>& rects) {
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glViewport(0, 0, size.x, size.y);
    glClearColor(0.06f, 0.06f, 0.07f, 1.0f);
    glEnable(GL_SCISSOR_TEST);
    for (const PixelRect& r : rects) {  // GL rows count from the bottom
        glScissor(r.x0, size.y - r.y1, r.x1 - r.x0, r.y1 - r.y0);
        glClear(GL_COLOR_BUFFER_BIT);
    }
    glDisable(GL_SCISSOR_TEST);
}

std::vector<std::uint8_t> readPixels(GLuint fbo, glm::ivec2 size) {
    std::vector<std::uint8_t> pixels(std::size_t(size.x) * size.y * 4);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, size.x, size.y, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
    return pixels;
}

// An exact copy (same size, colour only, no filtering).
void blit(GLuint from, GLuint to, glm::ivec2 size) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, from);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, to);
    glBlitFramebuffer(0, 0, size.x, size.y, 0, 0, size.x, size.y, GL_COLOR_BUFFER_BIT, GL_NEAREST);
}

}  // namespace

void FramePresenter::Target::resize(glm::ivec2 size) {
    if (!fbo) {
        glGenFramebuffers(1, &fbo);
        glGenRenderbuffers(1, &color);
    }
    glBindRenderbuffer(GL_RENDERBUFFER, color);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, size.x, size.y);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color);
}

void FramePresenter::Target::release() {
    if (fbo) glDeleteFramebuffers(1, &fbo);
    if (color) glDeleteRenderbuffers(1, &color);
    fbo = color = 0;
}

FramePresenter::~FramePresenter() {
    kept_.release();
    saved_.release();
}

void FramePresenter::present(RenderBackend& backend) {
    ImGui::Render();
    ImDrawData& data = *ImGui::GetDrawData();
    const glm::ivec2 size = backend.framebufferSize();
    if (size != size_) {  // new storage: nothing kept
        size_ = size;
        // OSMesa draws into memory that stays as drawn: the frame is kept there, no copy.
        if (!backend.keepsDrawnFrame()) kept_.resize(size);
        last_ = {};
    }
    FrameDrawing now = recordDrawing(data, size, [](ImTextureID id) {
        return render::textureVersion(unsigned(reinterpret_cast<std::uintptr_t>(id)));
    });
    const std::vector<PixelRect> rects =
        damagedRects(last_, now);  // the whole frame when last_ is empty
    std::vector<std::uint8_t> whole;
    if (check_ && now.comparable) whole = drawWholeForComparison(data, size);
    draw(data, size, rects);
    if (!whole.empty() && readPixels(kept_.fbo, size) != whole) ++stats_.mismatchedFrames;

    if (kept_.fbo) {  // a window's back buffer is not kept after a swap: copy the kept frame
        blit(kept_.fbo, 0, size);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    backend.present();
    last_ = std::move(now);
    ++stats_.frames;
}

void FramePresenter::draw(ImDrawData& data, glm::ivec2 size, const std::vector<PixelRect>& rects) {
    stats_.lastDrawnPixels = 0;
    for (const PixelRect& r : rects) stats_.lastDrawnPixels += r.area();
    stats_.drawnPixels += stats_.lastDrawnPixels;
    if (rects.empty()) return;
    bindAndClear(kept_.fbo, size, rects);
    const bool whole = rects.size() == 1 && rects[0] == PixelRect{0, 0, size.x, size.y};
    // A frame that cannot be compared (callbacks, offsets) is drawn as it is, whole.
    if (!whole) clipDrawData(data, size, rects);
    ImGui_ImplOpenGL3_RenderDrawData(&data);
}

std::vector<std::uint8_t> FramePresenter::drawWholeForComparison(ImDrawData& data,
                                                                 glm::ivec2 size) {
    // Drawn into the kept frame's own target, saved before and restored after: llvmpipe can round
    // a blended edge pixel of OSMesa's own buffer and of a renderbuffer differently (seen on a
    // Sapphire Rapids host: 3 pixels off by one), which is no fault of the partial redraw.
    if (!saved_.fbo || savedSize_ != size) {
        saved_.resize(size);
        savedSize_ = size;
    }
    blit(kept_.fbo, saved_.fbo, size);
    bindAndClear(kept_.fbo, size, {{0, 0, size.x, size.y}});
    ImGui_ImplOpenGL3_RenderDrawData(&data);
    std::vector<std::uint8_t> pixels = readPixels(kept_.fbo, size);
    blit(saved_.fbo, kept_.fbo, size);
    return pixels;
}

render::RgbaImage captureFrame(const RenderBackend& backend) {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    const glm::ivec2 fb = backend.framebufferSize();
    return render::readFramebuffer(fb.x, fb.y);
}

}  // namespace fm::app

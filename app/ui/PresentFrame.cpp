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
    wholeFrame_.release();
}

void FramePresenter::present(RenderBackend& backend) {
    ImGui::Render();
    ImDrawData& data = *ImGui::GetDrawData();
    const glm::ivec2 size = backend.framebufferSize();
    if (size != size_) {  // new storage: nothing kept
        size_ = size;
        // OSMesa draws into memory that stays as drawn: the frame is kept there, no copy.
        if (!backend.keepsDrawnFrame()) kept_.resize(size);
        if (check_) wholeFrame_.resize(size);
        last_ = {};
    }
    FrameDrawing now = recordDrawing(data, size, [](ImTextureID id) {
        return render::textureVersion(unsigned(reinterpret_cast<std::uintptr_t>(id)));
    });
    const std::vector<PixelRect> rects =
        damagedRects(last_, now);  // the whole frame when last_ is empty
    if (check_ && now.comparable) {
        if (!wholeFrame_.fbo) wholeFrame_.resize(size);
        checkAgainstWholeFrame(data, size);
    }
    draw(data, size, rects);
    if (check_ && now.comparable &&
        readPixels(kept_.fbo, size) != readPixels(wholeFrame_.fbo, size))
        ++stats_.mismatchedFrames;

    if (kept_.fbo) {  // a window's back buffer is not kept after a swap: copy the kept frame
        glBindFramebuffer(GL_READ_FRAMEBUFFER, kept_.fbo);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
        glBlitFramebuffer(0, 0, size.x, size.y, 0, 0, size.x, size.y, GL_COLOR_BUFFER_BIT,
                          GL_NEAREST);
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

void FramePresenter::checkAgainstWholeFrame(ImDrawData& data, glm::ivec2 size) {
    bindAndClear(wholeFrame_.fbo, size, {{0, 0, size.x, size.y}});
    ImGui_ImplOpenGL3_RenderDrawData(&data);
}

render::RgbaImage captureFrame(const RenderBackend& backend) {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    const glm::ivec2 fb = backend.framebufferSize();
    return render::readFramebuffer(fb.x, fb.y);
}

}  // namespace fm::app

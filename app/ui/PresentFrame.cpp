#include "ui/PresentFrame.h"

#include <imgui.h>
#include <imgui_impl_opengl3.h>

#include "platform/Gl.h"

namespace fm::app {

void presentImGuiFrame(RenderBackend& backend) {
    ImGui::Render();
    const glm::ivec2 fb = backend.framebufferSize();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, fb.x, fb.y);
    glClearColor(0.06f, 0.06f, 0.07f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    backend.present();
}

render::RgbaImage captureFrame(const RenderBackend& backend) {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    const glm::ivec2 fb = backend.framebufferSize();
    return render::readFramebuffer(fb.x, fb.y);
}

}  // namespace fm::app

// Window backend: GLFW with a GL 3.3 core context; ImGui's GLFW platform code from libimgui.a.
#include <imgui.h>
#include <imgui_impl_glfw.h>

#include "platform/Gl.h"
// After glad: GLFW must not include a system GL header.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cstdio>
#include <mutex>

#include "platform/RenderBackend.h"

namespace fm::app {
namespace {

std::string lastGlfwError;

void onGlfwError(int code, const char* description) {
    lastGlfwError = "GLFW error " + std::to_string(code) + ": " + description;
}

class GlfwWindowBackend final : public RenderBackend {
  public:
    explicit GlfwWindowBackend(GLFWwindow* window) : window_(window) {
        glfwSetWindowUserPointer(window_, this);
        glfwSetDropCallback(window_, [](GLFWwindow* w, int count, const char** paths) {
            auto* self = static_cast<GlfwWindowBackend*>(glfwGetWindowUserPointer(w));
            for (int i = 0; i < count; ++i) self->dropped_.emplace_back(paths[i]);
        });
    }
    ~GlfwWindowBackend() override {
        glfwDestroyWindow(window_);
        glfwTerminate();
    }

    std::string describe() const override {
        return std::string("GLFW window, GL ") +
               reinterpret_cast<const char*>(glGetString(GL_VERSION)) + ", " +
               reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    }
    bool headless() const override { return false; }
    glm::ivec2 framebufferSize() const override {
        int w = 0, h = 0;
        glfwGetFramebufferSize(window_, &w, &h);
        return {w, h};
    }
    bool shouldClose() const override { return glfwWindowShouldClose(window_); }

    void initImGui() override { ImGui_ImplGlfw_InitForOpenGL(window_, true); }
    void shutdownImGui() override { ImGui_ImplGlfw_Shutdown(); }
    void setActivity(Activity activity) override { activity_ = activity; }
    void drawContinuously(bool on) override { continuous_ = on; }
    void newFrame() override {
        // Any event (mouse, key, resize, expose, drop) wakes the loop at once.
        switch (continuous_ ? EventWait::Poll : waits_.next(activity_, woken_)) {
            case EventWait::Poll:
                glfwPollEvents();
                woken_ = false;
                break;
            case EventWait::Timeout: {
                const double before = glfwGetTime();
                glfwWaitEventsTimeout(1.0 / kBackgroundHz);
                woken_ = glfwGetTime() - before < 0.9 / kBackgroundHz;  // returned early: an event
                break;
            }
            case EventWait::Forever:
                glfwWaitEvents();
                woken_ = true;
                break;
        }
        ImGui_ImplGlfw_NewFrame();
    }
    void present() override { glfwSwapBuffers(window_); }
    void wake() override { glfwPostEmptyEvent(); }

    std::vector<std::string> takeDroppedPaths() override {
        std::vector<std::string> out;
        out.swap(dropped_);
        return out;
    }

  private:
    GLFWwindow* window_;
    std::vector<std::string> dropped_;
    Activity activity_ = Activity::Busy;
    EventWaitPolicy waits_;
    bool woken_ = false;
    bool continuous_ = false;
};

}  // namespace

std::unique_ptr<RenderBackend> createGlfwWindowBackend(glm::ivec2 size, const std::string& title,
                                                       std::string& error) {
    glfwSetErrorCallback(onGlfwError);
    if (!glfwInit()) {
        error = lastGlfwError.empty() ? "glfwInit failed" : lastGlfwError;
        return nullptr;
    }
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    GLFWwindow* window = glfwCreateWindow(size.x, size.y, title.c_str(), nullptr, nullptr);
    if (!window) {
        error = lastGlfwError.empty() ? "could not create a GL 3.3 core window" : lastGlfwError;
        glfwTerminate();
        return nullptr;
    }
    glfwMakeContextCurrent(window);
    glfwSwapInterval(1);
    if (!gladLoadGL(reinterpret_cast<GLADloadfunc>(glfwGetProcAddress))) {
        error = "could not load the GL 3.3 core functions in the window";
        glfwDestroyWindow(window);
        glfwTerminate();
        return nullptr;
    }
    return std::make_unique<GlfwWindowBackend>(window);
}

}  // namespace fm::app

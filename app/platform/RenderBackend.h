#pragma once
// Where frames go: a GLFW window or an offscreen OSMesa buffer, chosen at start. Everything
// above this interface (UI, GL drawing) is the same code for both.
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "platform/EventWait.h"

namespace fm::app {

// Input for one headless frame (scripted UI tests): ImGui 1.86 takes the mouse and keys as
// state, so a click is three frames (hover, press, release).
struct FrameInput {
    glm::vec2 mousePos{-1e6f, -1e6f};  // far outside = no mouse
    bool mouseDown[3] = {false, false, false};
    float wheel = 0.0f;
    std::string text;       // characters typed this frame
    std::vector<int> keys;  // ImGuiKey_* held down this frame (Enter, Backspace, ...)
    bool ctrl = false;
    bool shift = false;
    std::vector<std::string> dropped;  // paths dropped onto the "window" this frame
};

class RenderBackend {
  public:
    virtual ~RenderBackend() = default;

    // "GLFW window" or "OSMesa (headless)", plus the GL version/renderer.
    virtual std::string describe() const = 0;
    virtual bool headless() const = 0;
    virtual glm::ivec2 framebufferSize() const = 0;
    virtual bool shouldClose() const = 0;

    // After ImGui::CreateContext: hook ImGui's platform side (GLFW callbacks or key map).
    virtual void initImGui() = 0;
    virtual void shutdownImGui() = 0;
    // Before ImGui::NewFrame: events, display size, time step, input.
    virtual void newFrame() = 0;
    // After drawing: show (swap buffers) or finish the offscreen image.
    virtual void present() = 0;

    // What the app is doing after this frame: a window waits for input accordingly (EventWait.h:
    // an idle app sleeps until the next event). Headless backends draw when asked.
    virtual void setActivity(Activity) {}
    // Never sleep between frames (a run of a counted number of frames: no event would come).
    virtual void drawContinuously(bool) {}
    // The default framebuffer holds what was drawn into it until drawn over (single-buffered,
    // no swap): a frame may then redraw only what changed straight into it.
    virtual bool keepsDrawnFrame() const { return false; }
    // From any thread: ends a wait for events now (a worker's result is ready to be shown).
    virtual void wake() {}
    // Files or folders dropped onto the window since the last call.
    virtual std::vector<std::string> takeDroppedPaths() { return {}; }
    // Headless only: the input the next frame sees.
    virtual void setFrameInput(const FrameInput&) {}
};

// A GLFW window with a GL 3.3 core context. Returns null with `error` set when no window can be
// made (no DISPLAY: glfwInit fails).
std::unique_ptr<RenderBackend> createGlfwWindowBackend(glm::ivec2 size, const std::string& title,
                                                       std::string& error);
// An offscreen OSMesa (llvmpipe) context of the given size. Throws fm::Error on failure.
std::unique_ptr<RenderBackend> createOsmesaBackend(glm::ivec2 size);

}  // namespace fm::app

#pragma once
// Drives the real ImGui UI of a headless App with mouse and keys over frames (ImGui 1.86 reads
// input as state: a click is hover, press, release). Used by the scripted UI tests and by the
// drag measurement of `fluoromatch screenshot --measure-drag`.
#include <string>

#include <glm/glm.hpp>

#include "ui/ScriptableApp.h"

namespace fm::app {

class UiScript {
  public:
    explicit UiScript(ScriptableApp& app) : app_(app) {}

    void idle(int frames = 1);
    void moveTo(glm::vec2 position);  // one frame
    void click(glm::vec2 position);   // three frames
    void clickWidget(const std::string& id);
    // Press at `from`, move to `to` in `steps` frames, release (steps + 2 frames). `button`:
    // 0 left, 1 right, 2 middle.
    void drag(glm::vec2 from, glm::vec2 to, int steps, int button = 0);
    void type(const std::string& text);              // one frame
    // Down one frame, then up one frame.
    void pressKey(int imguiKey, bool ctrl = false, bool shift = false);
    void drop(const std::string& path);              // a file dropped onto the window
    void wheel(glm::vec2 position, float amount);    // one frame

    // Centre / rectangle of a widget recorded by the UI in the last frame; throws fm::Error if
    // the UI did not draw it.
    WidgetRect widget(const std::string& id) const;

  private:
    void frame();
    ScriptableApp& app_;
    FrameInput input_;
};

}  // namespace fm::app

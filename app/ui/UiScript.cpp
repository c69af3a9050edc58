#include "ui/UiScript.h"

#include <imgui.h>

#include "core/Error.h"

namespace fm::app {

void UiScript::frame() {
    app_.backend().setFrameInput(input_);
    app_.frame();
    input_.wheel = 0.0f;
    input_.text.clear();
    input_.keys.clear();
    input_.dropped.clear();
}

void UiScript::idle(int frames) {
    for (int i = 0; i < frames; ++i) frame();
}

void UiScript::moveTo(glm::vec2 position) {
    input_.mousePos = position;
    frame();
}

void UiScript::click(glm::vec2 position) {
    input_.mousePos = position;
    frame();
    input_.mouseDown[0] = true;
    frame();
    input_.mouseDown[0] = false;
    frame();
}

void UiScript::clickWidget(const std::string& id) {
    const WidgetRect w = widget(id);
    if (!w.visible) throw Error("UI script: " + id + " is clipped by its pane (scrolled out of view): a click would miss it");
    click(w.center());
}

void UiScript::drag(glm::vec2 from, glm::vec2 to, int steps, int button) {
    input_.mousePos = from;
    frame();
    input_.mouseDown[button] = true;
    frame();
    for (int i = 1; i <= steps; ++i) {
        input_.mousePos = from + (to - from) * (float(i) / float(steps));
        frame();
    }
    input_.mouseDown[button] = false;
    frame();
}

void UiScript::type(const std::string& text) {
    input_.text = text;
    frame();
}

void UiScript::pressKey(int imguiKey, bool ctrl, bool shift) {
    input_.keys = {imguiKey};
    input_.ctrl = ctrl;
    input_.shift = shift;
    frame();
    input_.ctrl = false;
    input_.shift = false;
    frame();
}

void UiScript::drop(const std::string& path) {
    input_.dropped = {path};
    frame();
}

void UiScript::wheel(glm::vec2 position, float amount) {
    input_.mousePos = position;
    input_.wheel = amount;
    frame();
}

WidgetRect UiScript::widget(const std::string& id) const {
    auto r = app_.widgetRect(id);
    if (!r) throw Error("the UI did not draw a widget \"" + id + "\"");
    return *r;
}

}  // namespace fm::app

#pragma once
// The end of every window frame, the same for the matching game (App) and the real X-ray
// workspace (WorkspaceApp): ImGui's draw lists onto the cleared default framebuffer, then shown
// (a window) or finished (headless); and reading that frame back.
#include "platform/RenderBackend.h"
#include "render/Screenshot.h"

namespace fm::app {

// After the UI code of a frame: ImGui::Render, clear, draw, present.
void presentImGuiFrame(RenderBackend& backend);
// What the last frame showed, row 0 at the top (screenshots, golden images).
render::RgbaImage captureFrame(const RenderBackend& backend);

}  // namespace fm::app

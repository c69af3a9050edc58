#pragma once
// A square 2D image as the field's viewers show it (shared by the game's panes and the real
// X-ray workspace): wheel zooms about the mouse, right or middle drag pans, left drag sets window
// (horizontal) and level (vertical) as in 3D Slicer, the pixel under the mouse is read out, and
// the patient directions are printed at the edges. Only ImGui calls.
#include <string>

#include "core/Image.h"
#include "geometry/PatientDirection.h"
#include "similarity/Mask.h"
#include "state/AppState.h"

namespace fm::app {

struct ImagePaneResult {
    bool hovered = false;  // the mouse is over the image (col, row: its pixel)
    bool clicked = false;  // ... and the left button went down this frame
    int col = 0, row = 0;
};

// Draws `texture` (0: nothing) in a square of `side` pixels at the cursor, as one ImGui item
// named `id`, editing `view` (zoom, pan), `display` (window/level) and `readout` (the pixel of
// `image` under the mouse; `dataMask`, may be null, marks the pixels that hold data).
ImagePaneResult imagePane(const std::string& id, unsigned texture, const Image* image,
                          const Mask* dataMask, const ImageEdgeLetters& edges, float side,
                          ImageView& view, DisplaySettings& display, PixelReadout& readout);

}  // namespace fm::app

#pragma once
// Frame times while a parameter slider is dragged, with and without the coarse preview: the
// figures behind "render coarser while dragging, exact on release".
#include <string>

#include <glm/glm.hpp>

#include "ui/App.h"

namespace fm::app {

struct DragTimes {
    int frames = 0;
    double meanFrameMs = 0.0, medianFrameMs = 0.0, maxFrameMs = 0.0;  // whole frames
    double meanDrrMs = 0.0;  // user DRR renders during the drag
    int drrRenders = 0;
    double releaseFrameMs = 0.0;  // the frame after release (exact render when previewing)
};

// Drags the azimuth slider from one end to the other over `frames` frames of a headless App
// (already loaded), with the coarse preview on or off, and returns the times.
DragTimes measureSliderDrag(App& app, int frames, bool coarsePreview);

std::string formatDragTimes(const DragTimes& t);

}  // namespace fm::app

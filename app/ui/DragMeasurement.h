#pragma once
// Frame times and input latency while a parameter slider is dragged, with and without the
// coarse preview, the user's DRR on the UI thread or on its worker: the figures behind "render
// coarser while dragging, exact on release" and "a frame never waits for the DRR".
#include <string>

#include <glm/glm.hpp>

#include "ui/App.h"

namespace fm::app {

struct Spread {
    double mean = 0.0, median = 0.0, max = 0.0;
};
Spread spreadOf(std::vector<double> values);  // zeros when empty

struct DragTimes {
    int frames = 0;
    Spread frameMs;         // whole frames while dragging
    Spread latencyMs;       // each user DRR shown: from the input read to the end of its frame
    int drrsShown = 0;      // user DRRs shown while dragging
    double meanDrrMs = 0.0;  // render time of the user DRRs shown
    double cpuMsPerFrame = 0.0;  // the process's CPU time (all threads) per drag frame
    double releaseFrameMs = 0.0;  // the frame after release
    double releaseLatencyMs = 0.0;  // from the release to the exact DRR on screen
};

// Drags the azimuth slider from one end to the other over `frames` frames of a headless App
// (already loaded), with the coarse preview on or off and the user DRR on its worker or not, and
// returns the times.
DragTimes measureSliderDrag(App& app, int frames, bool coarsePreview, bool offThread);

std::string formatDragTimes(const DragTimes& t);

}  // namespace fm::app

#pragma once
// The whole UI drawn through OSMesa with no display, deterministically: fixed time step, fixed
// font, the load finished before the shot. Used by `fluoromatch screenshot`, by `fluoromatch
// app` without a display, and by the golden-image tests.
#include <filesystem>
#include <functional>
#include <string>

#include <glm/glm.hpp>

#include "render/Screenshot.h"
#include "ui/App.h"

namespace fm::app {

struct HeadlessOptions {
    AppOptions app;
    glm::ivec2 size{1280, 800};
    int settleFrames = 3;     // frames drawn after the load so the layout is stable
    bool pressMatch = false;  // press Match before the shot (shows verdict and hints)
    bool showHelp = false;
    CompareMode compare = CompareMode::Difference;
};

// Throws fm::Error when a pose given in `options` lies outside the sliders' reach for a volume
// whose translation range is `translationRangeMm`.
void checkGivenPoses(const AppOptions& options, double translationRangeMm);

// Draws the UI headless and returns the last frame. `script` (optional) runs after the load
// with the live App, e.g. to drive the UI. Throws fm::Error (with the reader's message) when the
// volume cannot be loaded, or when a given pose is out of the sliders' reach.
render::RgbaImage renderHeadless(const HeadlessOptions& options,
                                 const std::function<void(App&)>& script = {});

// renderHeadless + writePng; prints one line saying what was written.
void writeHeadlessScreenshot(const HeadlessOptions& options, const std::filesystem::path& out);

}  // namespace fm::app

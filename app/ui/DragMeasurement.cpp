#include "ui/DragMeasurement.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

#include <sys/resource.h>

#include "ui/UiScript.h"

namespace fm::app {
namespace {

// CPU time of all the process's threads (UI, DRR, llvmpipe): unlike the frame time, it does not
// count time the cores spent on other processes.
double processCpuMs() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    const auto ms = [](const timeval& t) { return double(t.tv_sec) * 1e3 + double(t.tv_usec) * 1e-3; };
    return ms(usage.ru_utime) + ms(usage.ru_stime);
}

// One frame; the latency and render time of the user DRR it showed, if it showed one.
void frameAndCollect(App& app, std::vector<double>& latencies, std::vector<double>& renders) {
    const int shownBefore = app.state().timings.userDrrsShown;
    app.frame();
    if (app.state().timings.userDrrsShown == shownBefore) return;
    latencies.push_back(app.state().timings.userDrrLatencyMs);
    renders.push_back(app.state().timings.userDrrMs);
}

}  // namespace

Spread spreadOf(std::vector<double> values) {
    Spread s;
    if (values.empty()) return s;
    for (double v : values) s.mean += v / double(values.size());
    std::sort(values.begin(), values.end());
    s.median = values[values.size() / 2];
    s.max = values.back();
    return s;
}

DragTimes measureSliderDrag(App& app, int frames, bool coarsePreview, bool offThread) {
    app.state().coarseWhileDragging = coarsePreview;
    app.setUserDrrOffThread(offThread);
    UiScript script(app);
    script.idle(1);
    const WidgetRect slider = script.widget("slider:azimuth");
    const float y = slider.center().y;
    const glm::vec2 from(slider.min.x + 4.0f, y), to(slider.max.x - 4.0f, y);
    FrameInput input;
    input.mousePos = from;
    app.backend().setFrameInput(input);
    app.frame();
    input.mouseDown[0] = true;
    app.backend().setFrameInput(input);
    app.frame();

    std::vector<double> times, latencies, renders;
    const double cpuBefore = processCpuMs();
    for (int i = 1; i <= frames; ++i) {
        input.mousePos = from + (to - from) * (float(i) / float(frames));
        app.backend().setFrameInput(input);
        frameAndCollect(app, latencies, renders);
        times.push_back(app.state().timings.frameMs);
    }
    DragTimes t;
    t.frames = frames;
    t.cpuMsPerFrame = (processCpuMs() - cpuBefore) / frames;
    t.frameMs = spreadOf(times);
    t.latencyMs = spreadOf(latencies);
    t.drrsShown = int(latencies.size());
    t.meanDrrMs = spreadOf(renders).mean;

    input.mouseDown[0] = false;
    app.backend().setFrameInput(input);
    latencies.clear();
    frameAndCollect(app, latencies, renders);
    t.releaseFrameMs = app.state().timings.frameMs;
    // Off the UI thread the exact DRR comes a few frames later: draw until it is on screen.
    for (int i = 0; i < 1000 && (app.userDrrPending() || app.state().timings.userDrrCoarse); ++i)
        frameAndCollect(app, latencies, renders);
    t.releaseLatencyMs = latencies.empty() ? 0.0 : latencies.back();

    app.state().coarseWhileDragging = true;
    app.setUserDrrOffThread(false);
    return t;
}

std::string formatDragTimes(const DragTimes& t) {
    char text[512];
    std::snprintf(text, sizeof(text),
                  "%d frames: frame mean %.1f / median %.1f / max %.1f ms (%.1f fps), CPU %.1f ms "
                  "per frame; %d user DRRs shown (%.1f ms each), input latency mean %.1f / median "
                  "%.1f / max %.1f ms; release frame %.1f ms, exact DRR on screen %.1f ms after "
                  "release",
                  t.frames, t.frameMs.mean, t.frameMs.median, t.frameMs.max,
                  t.frameMs.mean > 0 ? 1000.0 / t.frameMs.mean : 0.0, t.cpuMsPerFrame, t.drrsShown,
                  t.meanDrrMs, t.latencyMs.mean, t.latencyMs.median, t.latencyMs.max,
                  t.releaseFrameMs, t.releaseLatencyMs);
    return text;
}

}  // namespace fm::app

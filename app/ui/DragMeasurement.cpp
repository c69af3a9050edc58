#include "ui/DragMeasurement.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

#include "ui/UiScript.h"

namespace fm::app {

DragTimes measureSliderDrag(App& app, int frames, bool coarsePreview) {
    app.state().coarseWhileDragging = coarsePreview;
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

    std::vector<double> times;
    double drrMs = 0.0;
    const int rendersBefore = app.coarseUserRenders() + app.exactUserRenders();
    for (int i = 1; i <= frames; ++i) {
        input.mousePos = from + (to - from) * (float(i) / float(frames));
        app.backend().setFrameInput(input);
        app.frame();
        times.push_back(app.state().timings.frameMs);
        drrMs += app.state().timings.userDrrMs;
    }
    DragTimes t;
    t.frames = frames;
    t.drrRenders = app.coarseUserRenders() + app.exactUserRenders() - rendersBefore;
    input.mouseDown[0] = false;
    app.backend().setFrameInput(input);
    app.frame();
    t.releaseFrameMs = app.state().timings.frameMs;

    for (double v : times) t.meanFrameMs += v / double(times.size());
    std::vector<double> sorted = times;
    std::sort(sorted.begin(), sorted.end());
    t.medianFrameMs = sorted[sorted.size() / 2];
    t.maxFrameMs = sorted.back();
    t.meanDrrMs = drrMs / double(times.size());
    app.state().coarseWhileDragging = true;
    return t;
}

std::string formatDragTimes(const DragTimes& t) {
    char text[256];
    std::snprintf(text, sizeof(text),
                  "%d frames: frame mean %.1f ms, median %.1f ms, max %.1f ms (%.1f fps); "
                  "user DRR %.1f ms per frame, %d renders; release frame %.1f ms",
                  t.frames, t.meanFrameMs, t.medianFrameMs, t.maxFrameMs,
                  t.meanFrameMs > 0 ? 1000.0 / t.meanFrameMs : 0.0, t.meanDrrMs, t.drrRenders,
                  t.releaseFrameMs);
    return text;
}

}  // namespace fm::app

#include "workspace/WorkspaceHeadless.h"

#include <cstdio>

#include "core/Error.h"
#include "platform/RenderBackend.h"

namespace fm::app {

render::RgbaImage renderWorkspaceHeadless(const WorkspaceHeadlessOptions& options,
                                          const std::function<void(WorkspaceApp&)>& script) {
    auto model = WorkspaceModel::open(options.source, options.threads);
    if (options.frame < 0 || options.frame >= model->frameCount())
        throw Error("--frame " + std::to_string(options.frame) + ": the workspace has frames 0.." +
                    std::to_string(model->frameCount() - 1));
    auto backend = createOsmesaBackend(options.size);
    WorkspaceOptions o;
    o.showTimings = options.showTimings;
    WorkspaceApp app(*backend, model, o);
    app.state().sideBySide = options.sideBySide;
    app.state().modelImage = options.drr ? ModelImage::Drr : ModelImage::Outline;
    if (options.frame != 0) app.state().requests.frame = options.frame;
    for (int i = 0; i < options.settleFrames; ++i) app.frame();
    if (!app.state().error.empty()) throw Error(app.state().error);
    if (script) {
        script(app);
        app.frame();
    }
    return app.capture();
}

void writeWorkspaceScreenshot(const WorkspaceHeadlessOptions& options, const std::filesystem::path& out) {
    const render::RgbaImage image = renderWorkspaceHeadless(options);
    render::writePng(out, image);
    std::printf("wrote %s (%d x %d, headless OSMesa)\n", out.string().c_str(), image.width, image.height);
}

}  // namespace fm::app

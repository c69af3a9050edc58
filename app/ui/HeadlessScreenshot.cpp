#include "ui/HeadlessScreenshot.h"

#include <cstdio>

#include "core/Error.h"

namespace fm::app {

void checkGivenPoses(const AppOptions& options, double translationRangeMm) {
    if (options.userPose) checkPoseWithinSliders(*options.userPose, translationRangeMm, "--pose");
    if (options.referencePose)
        checkPoseWithinSliders(*options.referencePose, translationRangeMm, "--reference-pose");
}

render::RgbaImage renderHeadless(const HeadlessOptions& options,
                                 const std::function<void(App&)>& script) {
    auto backend = createOsmesaBackend(options.size);
    App app(*backend, options.app);
    app.waitForLoad();
    if (!app.scene())
        throw Error(app.state().load.error.empty() ? "no volume loaded" : app.state().load.error);
    checkGivenPoses(options.app, app.state().translationRangeMm);
    // The labels asked for must give bones: a picture without them would hide the failure.
    if (!options.app.labelsSpec.empty() && !app.state().labels.error.empty())
        throw Error(app.state().labels.error);
    app.state().display.compare = options.compare;
    app.state().showHelp = options.showHelp;
    if (options.pressMatch) app.state().requests.match = true;
    for (int i = 0; i < options.settleFrames; ++i) app.frame();
    if (script) {
        script(app);
        app.frame();
    }
    return app.capture();
}

void writeHeadlessScreenshot(const HeadlessOptions& options, const std::filesystem::path& out) {
    const render::RgbaImage image = renderHeadless(options);
    render::writePng(out, image);
    std::printf("wrote %s (%d x %d, headless OSMesa)\n", out.string().c_str(), image.width,
                image.height);
}

}  // namespace fm::app

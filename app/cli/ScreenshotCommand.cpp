// `fluoromatch screenshot`: the whole UI rendered through OSMesa with no display,
// deterministically (the same drawing code as the window; only the GL context differs).
#include <cstdio>
#include <sstream>

#include "cli/CommandRegistry.h"
#include "cli/ModeOptions.h"
#include "cli/NumberChecks.h"
#include "cli/ValueChecks.h"
#include "cli/WorkspaceOptions.h"
#include "core/Error.h"
#include "geometry/Pose.h"
#include "source/VolumeSource.h"
#include "ui/DragMeasurement.h"
#include "spectral/Spectrum.h"
#include "ui/HeadlessScreenshot.h"
#include "workspace/WorkspaceHeadless.h"

namespace {

struct ScreenshotArgs {
    std::string out = "ui.png";
    std::string size = "1280x800";
    std::string volume = fm::kDefaultVolumeSpec;
    std::string pose, referencePose, view, compare = "difference";
    std::string labels, labelTable;
    std::string spectrum;  // the reference as a realistic radiograph
    std::uint64_t seed = 1;
    bool match = false, help = false, timings = false;
    int threads = 0;
    int measureDrag = 0;
    std::string dragModes = "ui-exact,ui-coarse,worker-exact,worker-coarse";
    fm::cli::WorkspaceArgs workspace;
    bool sideBySide = false, drr = false;
};

fm::app::View3d parseView(const std::string& text) {
    fm::app::View3d view;
    double az = 0, el = 0, zoom = 1;
    char c1 = 0, c2 = 0, extra = 0;
    std::istringstream in(text);
    if (!(in >> az >> c1 >> el >> c2 >> zoom) || c1 != ',' || c2 != ',' || (in >> extra))
        throw fm::Error("--view \"" + text + "\": expected az,el,zoom (degrees, degrees, factor)");
    if (!(el >= -89.0 && el <= 89.0))
        throw fm::Error("--view elevation must be within -89..89 degrees");
    if (!(zoom >= 0.2 && zoom <= 8.0)) throw fm::Error("--view zoom must be within 0.2..8");
    if (!(az >= -360.0 && az <= 360.0)) throw fm::Error("--view azimuth must be within -360..360");
    view.azimuthDeg = float(az);
    view.elevationDeg = float(el);
    view.zoom = float(zoom);
    return view;
}

fm::app::CompareMode parseCompare(const std::string& text) {
    if (text == "difference") return fm::app::CompareMode::Difference;
    if (text == "overlay") return fm::app::CompareMode::Overlay;
    if (text == "checkerboard") return fm::app::CompareMode::Checkerboard;
    throw fm::Error("--compare \"" + text + "\": expected difference, overlay or checkerboard");
}

void runWorkspaceScreenshot(const ScreenshotArgs& args) {
    fm::app::WorkspaceHeadlessOptions options;
    options.source = fm::cli::workspaceSource(args.workspace);
    options.size = fm::cli::parseImageSize(args.size, 8192);
    options.threads = args.threads;
    options.frame = options.source.trial.empty() ? 0 : args.workspace.frame;
    options.sideBySide = args.sideBySide;
    options.drr = args.drr;
    options.showTimings = args.timings;
    fm::app::writeWorkspaceScreenshot(options, args.out);
}

void runScreenshot(const ScreenshotArgs& args) {
    if (fm::cli::wantsWorkspace(args.workspace)) return runWorkspaceScreenshot(args);
    fm::app::HeadlessOptions options;
    options.size = fm::cli::parseImageSize(args.size, 8192);
    options.app.volumeSpec = args.volume;
    options.app.labelsSpec = args.labels;
    options.app.labelTable = args.labelTable;
    options.app.seed = args.seed;
    options.app.drrThreads = args.threads;
    if (!args.pose.empty()) options.app.userPose = fm::parsePose(args.pose);
    if (!args.referencePose.empty()) options.app.referencePose = fm::parsePose(args.referencePose);
    if (!args.view.empty()) options.app.view = parseView(args.view);
    if (!args.spectrum.empty()) {
        fm::parseSpectrumSpec(args.spectrum);  // refused now, not after loading
        options.app.spectrum = args.spectrum;
    }
    options.compare = parseCompare(args.compare);
    options.pressMatch = args.match;
    options.showHelp = args.help;
    options.app.showTimings = args.timings;
    if (args.measureDrag > 0) {
        // Frame times and input latency of a slider drag: exact-only against
        // coarse-while-dragging, the user DRR on the UI thread against on its worker.
        std::istringstream modes(args.dragModes);
        for (std::string mode; std::getline(modes, mode, ',');)
            if (mode != "ui-exact" && mode != "ui-coarse" && mode != "worker-exact" &&
                mode != "worker-coarse")
                throw fm::Error("--drag-modes \"" + mode +
                                "\": expected ui-exact, ui-coarse, worker-exact or worker-coarse");
        auto backend = fm::app::createOsmesaBackend(options.size);
        std::printf("backend: %s\n", backend->describe().c_str());
        fm::app::App app(*backend, options.app);
        app.waitForLoad();
        if (!app.scene()) throw fm::Error(app.state().load.error);
        fm::app::checkGivenPoses(options.app, app.state().translationRangeMm);
        for (int i = 0; i < 3; ++i) app.frame();
        // The user DRR on the UI thread (each frame waits for it), then on its worker.
        for (const bool offThread : {false, true})
            for (const bool coarse : {false, true}) {
                const std::string name = std::string(offThread ? "worker-" : "ui-") +
                                         (coarse ? "coarse" : "exact");
                if (("," + args.dragModes + ",").find("," + name + ",") == std::string::npos)
                    continue;
                const auto t = fm::app::measureSliderDrag(app, args.measureDrag, coarse, offThread);
                std::printf("drag, %s, %s:\n  %s\n",
                            coarse ? "coarse while dragging" : "exact DRR every frame",
                            offThread ? "DRR on its worker" : "DRR on the UI thread",
                            fm::app::formatDragTimes(t).c_str());
            }
        std::printf("user DRR alone: exact %.1f ms, coarse (film /%d) %.1f ms\n",
                    app.state().timings.lastExactMs, app.state().timings.coarseFactor,
                    app.state().timings.lastCoarseMs);
        return;
    }
    fm::app::writeHeadlessScreenshot(options, args.out);
}

FM_REGISTER_COMMAND("screenshot", 2, [](CLI::App& cli) {
    auto* cmd = cli.add_subcommand("screenshot",
                                   "Render the whole app UI headless (OSMesa) to a "
                                   "PNG, deterministically");
    auto a = std::make_shared<ScreenshotArgs>();
    cmd->add_option("--out", a->out, "PNG to write")->capture_default_str();
    cmd->add_option("--size", a->size, "WIDTHxHEIGHT in pixels")->capture_default_str();
    cmd->add_option("--volume", a->volume, "CT file, DICOM folder or phantom:NAME")
        ->capture_default_str();
    cmd->add_option("--labels", a->labels,
                    "label map of the CT (or phantom:knee, components[:HU]): its bones in the "
                    "Bones tab");
    cmd->add_option("--label-table", a->labelTable, "names of the labels to show as bones")
        ->needs(cmd->get_option("--labels"));
    cmd->add_option("--pose", a->pose, "your pose x,y,z,az,el,rot (mm, deg); default centred")
        ->check(fm::cli::kPoseText);
    cmd->add_option("--reference-pose", a->referencePose,
                    "the hidden reference pose x,y,z,az,el,rot; default: picked by --seed")
        ->check(fm::cli::kPoseText);
    cmd->add_option("--view", a->view, "3D view camera az,el,zoom (deg, deg, factor)");
    cmd->add_option("--spectrum", a->spectrum,
                    "the reference as a realistic radiograph at this spectrum (as drr --spectrum: "
                    "kVp[,filter=MM][,bin=KEV]); a CT in HU");
    cmd->add_option("--seed", a->seed, "seed of the reference choice")
        ->capture_default_str()
        ->check(fm::cli::kSeedNumber);
    cmd->add_option("--compare", a->compare, "difference, overlay or checkerboard")
        ->capture_default_str();
    cmd->add_flag("--match", a->match, "press Match before the shot (verdict and hints)");
    cmd->add_flag("--help-window", a->help, "show the Help window");
    cmd->add_flag("--timings", a->timings,
                  "show the render timings (they vary run to run: the image is then not "
                  "reproducible)");
    cmd->add_option("--threads", a->threads, "DRR threads (0 = all cores)")
        ->check(CLI::NonNegativeNumber);
    cmd->add_option("--measure-drag", a->measureDrag,
                    "instead of a screenshot: drag the azimuth slider over N frames and report "
                    "frame times and input latency, exact DRRs vs coarse while dragging, the DRR "
                    "on the UI thread vs on its worker")
        ->check(CLI::NonNegativeNumber);
    cmd->add_option("--drag-modes", a->dragModes,
                    "with --measure-drag: which drags, a comma list of ui-exact, ui-coarse, "
                    "worker-exact, worker-coarse (worker-coarse is what the window does)")
        ->capture_default_str();
    fm::cli::addWorkspaceOptions(cmd, a->workspace, false);
    cmd->add_flag("--side-by-side", a->sideBySide, "workspace: the model beside each radiograph, not over it");
    cmd->add_flag("--drr", a->drr, "workspace: the models' DRRs instead of their outlines");
    cmd->callback([a, cmd] {
        static const std::vector<fm::cli::CommandMode> modes = [] {
            fm::cli::WorkspaceArgs scratch;
            return std::vector<fm::cli::CommandMode>{
                {"screenshot", "the matching game on a CT",
                 {"out", "size", "volume", "labels", "label-table", "pose", "reference-pose", "view", "spectrum",
                  "seed", "compare", "match", "help-window", "timings", "threads", "measure-drag",
                  "drag-modes"}},
                {"screenshot --trial/--reference", "the real X-ray workspace",
                 fm::cli::optionNames(
                     [&](CLI::App* c) { fm::cli::addWorkspaceOptions(c, scratch, false); },
                     {"out", "size", "side-by-side", "drr", "timings", "threads"})}};
        }();
        fm::cli::refuseOptionsOutside(*cmd, modes[fm::cli::wantsWorkspace(a->workspace) ? 1 : 0], modes);
        runScreenshot(*a);
    });
    return cmd;
});

}  // namespace

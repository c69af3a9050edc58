// `fluoromatch app`: the matching window (the default command). Without a display it says so
// and writes a headless screenshot instead, so `fluoromatch` never fails for lack of a screen.
#include <chrono>
#include <cstdio>
#include <iostream>

#include "cli/CommandRegistry.h"
#include "cli/ModeOptions.h"
#include "cli/WorkspaceOptions.h"
#include "core/Error.h"
#include "platform/RenderBackend.h"
#include "source/VolumeSource.h"
#include "spectral/Spectrum.h"
#include "state/RecentFiles.h"
#include "ui/App.h"
#include "ui/AppShell.h"
#include "ui/HeadlessScreenshot.h"
#include "workspace/WorkspaceApp.h"
#include "workspace/WorkspaceHeadless.h"

namespace {

struct AppArgs {
    std::string volume = fm::kDefaultVolumeSpec;
    std::string labels, labelTable;
    int frames = 0;
    bool requireWindow = false;
    std::string fallbackOut = "fluoromatch-screenshot.png";
    fm::cli::WorkspaceArgs workspace;
    int threads = 0;
    std::string spectrum;  // the reference as a realistic radiograph
};

// The game's options in a window; the shell opens a CT asked from inside with them.
fm::app::AppOptions windowGameOptions(const AppArgs& args) {
    fm::app::AppOptions options;
    options.volumeSpec = args.volume;
    options.labelsSpec = args.labels;
    options.labelTable = args.labelTable;
    options.spectrum = args.spectrum;
    options.userDrrOffThread = true;  // a window's frame never waits for the user's DRR
    options.seed =
        static_cast<std::uint64_t>(std::chrono::system_clock::now().time_since_epoch().count());
    return options;
}

// What the window's shell switches with (ui/AppShell.h): the Recent list in the user's config.
fm::app::AppShell::Options shellOptions(const AppArgs& args) {
    fm::app::AppShell::Options o;
    o.game = windowGameOptions(args);
    o.game.labelsSpec.clear();  // the labels belong to the CT given at start
    o.game.labelTable.clear();
    o.threads = args.threads;
    o.recentFile = fm::app::defaultRecentFile();
    return o;
}

// The real X-ray workspace (--trial or --reference): opened before any window, so bad input is
// a message and a non-zero exit.
void runWorkspace(const AppArgs& args) {
    const fm::app::WorkspaceSource source = fm::cli::workspaceSource(args.workspace);
    const bool trial = !source.trial.empty();
    auto model = fm::app::WorkspaceModel::open(source, args.threads);
    for (const std::string& w : model->trial().trial.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
    const int frame = trial ? args.workspace.frame : 0;
    if (frame >= model->frameCount())
        throw fm::Error("--frame " + std::to_string(frame) + ": the trial has frames 0.." +
                        std::to_string(model->frameCount() - 1));
    std::string error;
    auto backend = fm::app::createGlfwWindowBackend({1280, 800}, "fluoromatch", error);
    if (!backend) {
        if (args.requireWindow) throw fm::Error("no window could be opened: " + error);
        std::printf("fluoromatch: no display (%s); writing a headless screenshot instead\n", error.c_str());
        fm::app::WorkspaceHeadlessOptions headless;
        headless.source = source;
        headless.threads = args.threads;
        headless.frame = frame;
        fm::app::writeWorkspaceScreenshot(headless, args.fallbackOut);
        return;
    }
    std::printf("window: %s\n", backend->describe().c_str());
    backend->drawContinuously(args.frames > 0);  // a counted run: no event would wake it
    auto app = std::make_unique<fm::app::WorkspaceApp>(*backend, model);
    app->state().requests.frame = frame;
    fm::app::AppShell shell(*backend, std::move(app), shellOptions(args));
    int frames = 0;
    while (!backend->shouldClose() && (args.frames <= 0 || frames < args.frames)) {
        shell.frame();
        ++frames;
    }
    std::printf("drew %d frames; workspace: %s\n", frames, model->title().c_str());
}

void runApp(const AppArgs& args) {
    if (fm::cli::wantsWorkspace(args.workspace)) return runWorkspace(args);
    std::string error;
    auto backend = fm::app::createGlfwWindowBackend({1280, 800}, "fluoromatch", error);
    if (!backend) {
        if (args.requireWindow) throw fm::Error("no window could be opened: " + error);
        std::printf("fluoromatch: no display (%s); writing a headless screenshot instead\n",
                    error.c_str());
        fm::app::HeadlessOptions headless;
        headless.app.volumeSpec = args.volume;
        headless.app.labelsSpec = args.labels;
        headless.app.labelTable = args.labelTable;
        headless.app.spectrum = args.spectrum;
        headless.app.showTimings = false;  // reproducible image
        fm::app::writeHeadlessScreenshot(headless, args.fallbackOut);
        return;
    }
    std::printf("window: %s\n", backend->describe().c_str());
    backend->drawContinuously(args.frames > 0);  // a counted run: no event would wake it
    fm::app::AppShell shell(*backend, std::make_unique<fm::app::App>(*backend, windowGameOptions(args)),
                            shellOptions(args));
    int frames = 0;
    double totalMs = 0.0;
    while (!backend->shouldClose() && (args.frames <= 0 || frames < args.frames)) {
        shell.frame();
        if (fm::app::App* game = shell.game()) totalMs += game->state().timings.frameMs;
        ++frames;
    }
    const fm::app::App* game = shell.game();
    std::printf("drew %d frames (mean %.1f ms per frame); %s\n", frames, frames ? totalMs / frames : 0.0,
                !game ? "the workspace open at the end"
                : game->scene() ? ("scene: " + game->scene()->spec).c_str()
                                : "scene: not loaded yet");
}

FM_REGISTER_COMMAND("app", 1, [](CLI::App& cli) {
    auto* cmd = cli.add_subcommand("app",
                                   "The matching app: reference DRR, your DRR, six "
                                   "parameters, 3D view (default command)");
    auto args = std::make_shared<AppArgs>();
    cmd->add_option("--volume", args->volume,
                    "CT file, DICOM folder or phantom:NAME to open at start")
        ->capture_default_str();
    cmd->add_option("--labels", args->labels,
                    "label map of the CT (any volume file, on its grid or resampled by nearest "
                    "neighbour), phantom:knee or components[:HU]: its bones in the Bones tab");
    cmd->add_option("--label-table", args->labelTable,
                    "names of the labels to show as bones: JSON {\"name\": label} or CSV lines "
                    "label,name")
        ->needs(cmd->get_option("--labels"));
    cmd->add_option("--spectrum", args->spectrum,
                    "the reference as a realistic radiograph at this spectrum (as drr --spectrum: "
                    "kVp[,filter=MM][,bin=KEV]); a CT in HU")
        ->check([](const std::string& text) {
            try {
                fm::parseSpectrumSpec(text);
            } catch (const fm::Error& e) {
                return std::string(e.what());
            }
            return std::string();
        });
    cmd->add_option("--frames", args->frames,
                    "exit after N frames (smoke tests); 0 = run until "
                    "the window is closed")
        ->check(CLI::NonNegativeNumber);
    cmd->add_flag("--require-window", args->requireWindow,
                  "fail instead of falling back to a headless screenshot without a display");
    cmd->add_option("--headless-out", args->fallbackOut,
                    "where the headless screenshot goes when there is no display")
        ->capture_default_str();
    fm::cli::addWorkspaceOptions(cmd, args->workspace);
    cmd->add_option("--threads", args->threads, "Threads of the workspace's images and Solve (0 = all cores)")
        ->check(CLI::NonNegativeNumber);
    cmd->callback([args, cmd] {
        // The game (a CT) or the workspace (--trial / --reference): each takes its own options.
        static const std::vector<fm::cli::CommandMode> modes = [] {
            fm::cli::WorkspaceArgs scratch;
            return std::vector<fm::cli::CommandMode>{
                {"app", "the matching game on a CT",
                 {"volume", "labels", "label-table", "spectrum", "frames", "require-window", "headless-out",
                  "threads"}},
                {"app --trial/--reference", "the real X-ray workspace",
                 fm::cli::optionNames([&](CLI::App* c) { fm::cli::addWorkspaceOptions(c, scratch); },
                                      {"frames", "require-window", "headless-out", "threads"})}};
        }();
        fm::cli::refuseOptionsOutside(*cmd, modes[fm::cli::wantsWorkspace(args->workspace) ? 1 : 0], modes);
        runApp(*args);
    });
    return cmd;
});

}  // namespace

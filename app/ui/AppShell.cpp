#include "ui/AppShell.h"

#include <cstdio>

#include "core/Error.h"
#include "state/RecentFiles.h"

namespace fm::app {

WorkspaceSource workspaceSourceOf(const OpenRequest& r) {
    WorkspaceSource s;
    if (r.kind == OpenRequest::Kind::Trial) {
        s.trial = r.trial;
        return s;
    }
    if (r.kind != OpenRequest::Kind::Radiograph) throw Error("a CT opens in the matching game");
    s.reference = r.reference;
    s.camera = r.camera;
    for (const std::string& m : r.models) s.models.emplace_back(m);
    if (!r.start.empty()) s.starts = {r.start};
    return s;
}

AppShell::AppShell(RenderBackend& backend, std::unique_ptr<ScriptableApp> first, Options options)
    : backend_(backend), current_(std::move(first)), options_(std::move(options)) {
    if (!current_) throw Error("the window needs an app");
    std::string warning;
    recent_ = readRecent(options_.recentFile, &warning);
    if (!warning.empty()) std::fprintf(stderr, "warning: %s\n", warning.c_str());
    current_->setRecent(recent_);
}

void AppShell::frame() {
    current_->frame();
    if (std::optional<OpenRequest> r = current_->takeOpenRequest()) open(*r);
}

void AppShell::open(const OpenRequest& request) {
    // 1. Read what is asked before anything changes: a failure leaves the app as it is.
    std::shared_ptr<WorkspaceModel> model;
    try {
        if (request.kind != OpenRequest::Kind::Volume)
            model = WorkspaceModel::open(workspaceSourceOf(request), options_.threads);
    } catch (const std::exception& e) {
        current_->openFailed(e.what());
        return;
    }
    // 2. The old app goes first (one ImGui context and its GL objects at a time), then the new.
    current_.reset();
    if (model) {
        current_ = std::make_unique<WorkspaceApp>(backend_, std::move(model), options_.workspace);
    } else {
        AppOptions game = options_.game;
        game.volumeSpec = request.volume;  // loaded in the background, progress on screen
        current_ = std::make_unique<App>(backend_, game);
    }
    // 3. Remembered; a list that cannot be written is said, never in the way.
    try {
        recent_ = rememberRecent(options_.recentFile, request);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "warning: the Recent list was not saved: %s\n", e.what());
    }
    current_->setRecent(recent_);
}

}  // namespace fm::app

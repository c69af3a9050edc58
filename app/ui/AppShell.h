#pragma once
// The window's app, whichever it is: the matching game (App) or the real X-ray workspace
// (WorkspaceApp), and the switch between them when the user opens a trial, a radiograph or a CT
// from inside (the Open window, a dropped file, Recent). What is asked is opened first (a
// workspace's files are read before anything changes), so a failure leaves the app as it was
// and says why in its Open window; then the old app goes (its ImGui context and GL objects)
// and the new one is made on the same backend. Every opened request joins the Recent list.
#include <filesystem>
#include <memory>

#include "ui/App.h"
#include "ui/ScriptableApp.h"
#include "workspace/WorkspaceApp.h"

namespace fm::app {

class AppShell : public ScriptableApp {
  public:
    struct Options {
        AppOptions game;                // the game a CT opens (its volumeSpec: the CT asked)
        WorkspaceOptions workspace;
        int threads = 0;                // the workspace's images and Solve
        std::filesystem::path recentFile;  // "" keeps no list between runs
    };
    AppShell(RenderBackend& backend, std::unique_ptr<ScriptableApp> first, Options options);

    void frame() override;
    RenderBackend& backend() override { return backend_; }
    std::optional<WidgetRect> widgetRect(const std::string& id) const override { return current_->widgetRect(id); }

    ScriptableApp& current() { return *current_; }
    App* game() { return dynamic_cast<App*>(current_.get()); }
    WorkspaceApp* workspace() { return dynamic_cast<WorkspaceApp*>(current_.get()); }
    const std::vector<OpenRequest>& recent() const { return recent_; }

  private:
    void open(const OpenRequest& request);

    RenderBackend& backend_;
    std::unique_ptr<ScriptableApp> current_;
    Options options_;
    std::vector<OpenRequest> recent_;
};

// The workspace source of a trial or radiograph request (fm::Error for a CT).
WorkspaceSource workspaceSourceOf(const OpenRequest& request);

}  // namespace fm::app

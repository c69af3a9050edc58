#pragma once
// What a scripted UI run (UiScript) drives: a frame loop over a backend whose widgets are
// recorded by name. The matching game (App) and the real X-ray workspace (WorkspaceApp) are both.
#include <optional>
#include <string>
#include <vector>

#include "platform/RenderBackend.h"
#include "state/OpenRequest.h"
#include "ui/Ui.h"

namespace fm::app {

class ScriptableApp {
  public:
    virtual ~ScriptableApp() = default;
    virtual RenderBackend& backend() = 0;
    // One whole frame: input, UI, requests, images, draw, present.
    virtual void frame() = 0;
    // The screen rectangle of a widget drawn in the last frame, by its recorded name.
    virtual std::optional<WidgetRect> widgetRect(const std::string& id) const = 0;

    // Opening from inside the app (ui/AppShell.h): what the user asked the shell to open (taken
    // once), why it could not be opened, and the Recent list to offer.
    virtual std::optional<OpenRequest> takeOpenRequest() { return std::nullopt; }
    virtual void openFailed(const std::string& /*why*/) {}
    virtual void setRecent(std::vector<OpenRequest> /*recent*/) {}
};

}  // namespace fm::app

#pragma once
// The Open window, shared by the matching game and the real X-ray workspace: a CT, a trial, or
// one radiograph with its calibration, models and start, typed as paths, and the Recent list.
// It only fills an OpenRequest: the window's shell (ui/AppShell.h) opens it.
#include <functional>
#include <optional>
#include <string>

#include "state/OpenRequest.h"

namespace fm::app {

// Draws the window when panel.shown; returns the request of an Open or Recent click.
// `record(id)` names the last widget for scripted runs (ids "input:open-volume",
// "button:open-volume", "input:open-trial",
// "button:open-trial", "input:open-reference", "input:open-camera", "input:open-models",
// "input:open-start", "button:open-radiograph", "button:recent-0", ..., "button:close-open").
std::optional<OpenRequest> drawOpenWindow(OpenPanel& panel,
                                          const std::function<void(const std::string&)>& record);

// "a.stl, b.stl" -> {"a.stl", "b.stl"} (blank items dropped).
std::vector<std::string> splitModelList(const std::string& text);

}  // namespace fm::app

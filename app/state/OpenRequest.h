#pragma once
// What the user asks to open from inside the app (the Open window, a dropped file, a Recent
// entry): a CT for the matching game, or a trial or one radiograph for the real X-ray
// workspace. The window's shell (ui/AppShell.h) opens it in the app that shows it.
#include <string>
#include <vector>

namespace fm::app {

struct OpenRequest {
    enum class Kind { Volume, Trial, Radiograph };
    Kind kind = Kind::Volume;
    std::string volume;             // Volume: file, DICOM folder or phantom:NAME
    std::string trial;              // Trial: .json or Autoscoper .cfg
    std::string reference, camera;  // Radiograph: the image and its calibration
    std::vector<std::string> models;
    std::string start;  // Radiograph: .jts / .tra or six numbers (empty: placed by the cameras)

    bool operator==(const OpenRequest&) const = default;
};

// One line for the Recent list: "trial wrist.json", "radiograph AT_K1_V1_0160.tif (2 models)".
std::string describe(const OpenRequest& request);

// The Open window's fields (plain data, drawn by ui/OpenWindow.h).
struct OpenPanel {
    bool shown = false;
    std::string volume, trial, reference, camera, models, start;  // models: comma-separated
    std::vector<OpenRequest> recent;                      // newest first
    std::string error;                                    // why the last open failed
};

}  // namespace fm::app

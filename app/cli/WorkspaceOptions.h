#pragma once
// The options that open the app's real X-ray workspace, shared by `fluoromatch app` and
// `fluoromatch screenshot`: --trial T, or --reference IMG --camera CALIB --model M [--model M2]
// [--start POSES] [--mask M] [--out POSES] [--frame K] [--mu MU] with register's preparation
// flags (RadiographOptions).
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/RadiographOptions.h"
#include "workspace/WorkspaceModel.h"

namespace fm::cli {

struct WorkspaceArgs {
    std::string trial, reference, camera, out;
    std::vector<std::string> models, starts, masks;
    int frame = 0;
    double mu = 0.0;
    std::string traForm;  // --tra-form for .tra starts: "", matrix or xyzypr
    RadiographOptions prep;
};

// `withOut`: also --out (screenshot has its own --out, the PNG).
void addWorkspaceOptions(CLI::App* cmd, WorkspaceArgs& args, bool withOut = true);
// Whether the options ask for the workspace (--trial or --reference).
bool wantsWorkspace(const WorkspaceArgs& args);
// The source they describe (the radiograph's header read for the preparation's full scale).
// Throws fm::Error naming the option or the file.
app::WorkspaceSource workspaceSource(const WorkspaceArgs& args);

}  // namespace fm::cli

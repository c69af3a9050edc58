#pragma once
// The real X-ray workspace drawn through OSMesa with no display, deterministically (fixed time
// step and font, as the game's HeadlessScreenshot): `fluoromatch screenshot --trial T` (or
// --reference ...), `fluoromatch app` without a display, and the golden-image tests.
#include <filesystem>
#include <functional>

#include <glm/glm.hpp>

#include "render/Screenshot.h"
#include "workspace/WorkspaceApp.h"
#include "workspace/WorkspaceModel.h"

namespace fm::app {

struct WorkspaceHeadlessOptions {
    WorkspaceSource source;
    glm::ivec2 size{1280, 800};
    int threads = 0;
    int frame = 0;  // the frame shown (trials)
    bool sideBySide = false;
    bool drr = false;  // DRRs instead of outlines
    bool showTimings = false;
    int settleFrames = 3;
};

// Opens the source (fm::Error naming the file and the field when it cannot), draws the
// workspace, runs `script` (optional) with the live app, and returns the last frame.
render::RgbaImage renderWorkspaceHeadless(const WorkspaceHeadlessOptions& options,
                                          const std::function<void(WorkspaceApp&)>& script = {});

// renderWorkspaceHeadless + writePng; prints one line saying what was written.
void writeWorkspaceScreenshot(const WorkspaceHeadlessOptions& options, const std::filesystem::path& out);

}  // namespace fm::app

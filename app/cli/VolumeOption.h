#pragma once
// The --volume option every command that reads a CT shares: one wording, one default.
#include <string>

#include <CLI/CLI.hpp>

#include "source/VolumeSource.h"

namespace fm::cli {

inline constexpr const char* kVolumeOptionHelp =
    "CT file (.nii[.gz], .mha/.mhd, .nrrd/.nhdr, .vtk), DICOM folder, TIFF stack with its voxel "
    "size (stack.tif?spacing=sx,sy,sz), or phantom:NAME";

// Adds --volume (or a positional "volume" when `positional`), defaulting to the knee phantom
// unless `spec` already holds another default.
inline CLI::Option* addVolumeOption(CLI::App* cmd, std::string& spec, bool positional = false) {
    if (spec.empty()) spec = kDefaultVolumeSpec;
    return cmd->add_option(positional ? "volume" : "--volume", spec, kVolumeOptionHelp)
        ->capture_default_str();
}

}  // namespace fm::cli

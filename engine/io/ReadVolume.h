#pragma once
// Reading a CT from disk: picks the reader from the path (folder = DICOM series; .nii/.nii.gz,
// .mha/.mhd, .nrrd/.nhdr, .vtk) and, failing that, from the file's first bytes.
// Every reader throws fm::Error with a message naming the file and what is wrong.
#include <filesystem>

#include "volume/Volume.h"

namespace fm {

Volume readVolume(const std::filesystem::path& path);

}  // namespace fm

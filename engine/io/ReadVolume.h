#pragma once
// Reading a CT from disk: picks the reader from the path (folder = DICOM series; .nii/.nii.gz,
// .mha/.mhd, .nrrd/.nhdr, .vtk) and, failing that, from the file's first bytes.
// Every reader throws fm::Error with a message naming the file and what is wrong.
#include <filesystem>
#include <string>

#include "volume/Volume.h"

namespace fm {

// NIfTI, MetaImage, NRRD and VTK carry no value units: meta.units stays Unknown for them
// (MetaImage may set modality "CT"). The CLI and later code treat CT values as HU.
Volume readVolume(const std::filesystem::path& path);

// Which reader readVolume would use: "dicom", "nifti", "metaimage", "nrrd" or "vtk".
// Throws fm::Error naming the file when it is missing or of no known format.
std::string detectVolumeFormat(const std::filesystem::path& path);

}  // namespace fm

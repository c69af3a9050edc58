#pragma once
// Reading a CT from disk: picks the reader from the path (folder = DICOM series; .nii/.nii.gz,
// .mha/.mhd, .nrrd/.nhdr, .vtk, .tif/.tiff stacks) and, failing that, from the file's first
// bytes.
// Every reader throws fm::Error with a message naming the file and what is wrong.
#include <filesystem>
#include <optional>
#include <string>

#include <glm/glm.hpp>

#include "volume/Volume.h"

namespace fm {

// NIfTI, MetaImage, NRRD and VTK carry no value units: meta.units stays Unknown for them
// (MetaImage may set modality "CT"). The CLI and later code treat CT values as HU.
struct VolumeReadOptions {
    // Voxel size (mm) for files that carry none: TIFF stacks (required for them, refused for
    // every other format, which holds its own). See io/TiffVolume.h for the stack's frame.
    std::optional<glm::dvec3> spacing;
};
Volume readVolume(const std::filesystem::path& path, const VolumeReadOptions& options = {});

// Which reader readVolume would use: "dicom", "nifti", "metaimage", "nrrd", "vtk" or "tiff".
// Throws fm::Error naming the file when it is missing or of no known format.
std::string detectVolumeFormat(const std::filesystem::path& path);

}  // namespace fm

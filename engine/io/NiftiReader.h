#pragma once
// NIfTI-1 and NIfTI-2 (.nii, .nii.gz, .hdr/.img pairs), parsed here without libnifti.
// Geometry follows the standard: the sform when sform_code > 0, else the qform (quaternion)
// when qform_code > 0, else pixdim only (then, like ITK/nibabel/Slicer, the axes are taken as
// RAS). NIfTI world coordinates are RAS; they are converted to our LPS frame.
// NIfTI does not say what the values mean: units stay ValueUnit::Unknown and modality "".
// (CT NIfTIs in practice hold HU; the CLI and later code treat the values as HU.)
#include <filesystem>

#include "volume/Volume.h"

namespace fm {

Volume readNifti(const std::filesystem::path& path);

}  // namespace fm

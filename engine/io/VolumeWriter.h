#pragma once
// Writing float volumes and 2D images so that ITK, plastimatch and 3D Slicer open them:
// MetaImage (.mha, float32, data inside, optionally zlib-compressed; LPS like ITK) and
// NIfTI-1 (.nii or .nii.gz, float32, sform and qform both written, LPS converted to RAS).
// Every write goes to a temporary file first: a failed write never destroys an existing file.
#include <filesystem>

#include "core/Image.h"
#include "volume/Volume.h"

namespace fm {

void writeMetaImage(const Volume& volume, const std::filesystem::path& path, bool compress = true);
// gzip-compressed when the name ends in .gz.
void writeNifti(const Volume& volume, const std::filesystem::path& path);
// By extension: .mha, .nii, .nii.gz. fm::Error for anything else.
void writeVolume(const Volume& volume, const std::filesystem::path& path);

// A 2D image as a one-slice volume: spacing (detector pitch x, y, 1), origin 0, identity axes.
Volume imageAsVolume(const Image& image);
// By extension: .mha, .nii, .nii.gz, or .png (8-bit, the image's min..max mapped to 0..255).
void writeImage(const Image& image, const std::filesystem::path& path);

}  // namespace fm

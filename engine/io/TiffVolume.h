#pragma once
// A volume from a multi-page TIFF stack (Autoscoper's bone crops: one page per CT slice, no
// spacing in the file). The voxel size must be given. Frame: voxel (i, j, k) = (column, row,
// page) is placed in the LPS world with identity direction and origin 0 (its centre at
// (sx i, sy j, sz k) mm) unless the caller moves it; pose/AutoscoperVolumeFrame.h converts to
// Autoscoper's corner frame.
#include <filesystem>

#include <glm/glm.hpp>

#include "volume/Volume.h"

namespace fm::io {

// fm::Error naming the file for a non-positive or non-finite spacing and everything readTiff
// refuses (libtiff's warnings about pixel data included). Its benign warnings are appended to
// meta.description. meta.units stays Unknown (the stored integers are not HU).
Volume readTiffVolume(const std::filesystem::path& path, const glm::dvec3& spacing);

}  // namespace fm::io

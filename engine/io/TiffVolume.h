#pragma once
// A volume from a multi-page TIFF stack (Autoscoper's bone crops: one page per CT slice, no
// spacing in the file). The voxel size must be given. Frame: voxel (i, j, k) = (column, row,
// page) is placed in the LPS world with identity direction and origin 0 (its centre at
// (sx i, sy j, sz k) mm) unless the caller moves it; pose/AutoscoperVolumeFrame.h converts to
// Autoscoper's corner frame.
#include <cstdint>
#include <filesystem>
#include <vector>

#include <glm/glm.hpp>

#include "volume/Volume.h"

namespace fm::io {

// fm::Error naming the file for a non-positive or non-finite spacing and everything readTiff
// refuses (libtiff's warnings about pixel data included). Its benign warnings are appended to
// meta.description. meta.units stays Unknown (the stored integers are not HU).
Volume readTiffVolume(const std::filesystem::path& path, const glm::dvec3& spacing);

// The bytes of a multi-page 16-bit TIFF stack of `volume` (one page per k, rows j, columns i),
// as Autoscoper's bone crops are: each value plus `offset`, rounded and clamped to 0..65535.
// Its geometry is not in the file (readTiffVolume's frame, with the same spacing given).
std::vector<std::uint8_t> encodeTiffStack16(const Volume& volume, double offset);

}  // namespace fm::io

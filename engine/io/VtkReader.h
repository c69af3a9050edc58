#pragma once
// Legacy VTK files (.vtk) holding a DATASET STRUCTURED_POINTS with one scalar per point,
// BINARY (big-endian, as the format requires) or ASCII. SPACING or ASPECT_RATIO, ORIGIN and
// the optional DIRECTION (VTK 9) are read; VTK has no patient frame, so the coordinates are
// taken as LPS (as ITK does).
#include <filesystem>

#include "volume/Volume.h"

namespace fm {

Volume readLegacyVtk(const std::filesystem::path& path);

}  // namespace fm

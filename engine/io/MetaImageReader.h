#pragma once
// MetaImage (ITK's .mha with the data inside, .mhd with the data in separate files).
// Supports binary and ASCII data, zlib compression (CompressedData = True), both byte orders,
// every scalar MET_ type, TransformMatrix/Rotation/Orientation/Direction, Offset/Position/
// Origin, and ElementDataFile = LOCAL, a file name, LIST, or a "pattern min max step" list.
// MetaImage coordinates are ITK's LPS already. Only one channel per voxel.
#include <filesystem>

#include "volume/Volume.h"

namespace fm {

Volume readMetaImage(const std::filesystem::path& path);

}  // namespace fm

#pragma once
// What the user names with --volume: a path, or a generated phantom ("phantom:knee",
// "phantom:sphere", ...). The default scene is "phantom:knee". A file that carries no voxel
// size (a TIFF stack) takes it after the path: "bone.tif?spacing=0.39625,0.39625,0.625" (mm).
#include <string>

#include "volume/Volume.h"

namespace fm {

inline constexpr const char* kDefaultVolumeSpec = "phantom:knee";

Volume loadVolume(const std::string& spec);

}  // namespace fm

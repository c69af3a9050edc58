#pragma once
// What the user names with --volume: a path, or a generated phantom ("phantom:knee",
// "phantom:sphere", ...). The default scene is "phantom:knee".
#include <string>

#include "volume/Volume.h"

namespace fm {

inline constexpr const char* kDefaultVolumeSpec = "phantom:knee";

Volume loadVolume(const std::string& spec);

}  // namespace fm

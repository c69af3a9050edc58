#pragma once
// A binary label image (a silhouette drawn or rendered for one model, 0 / 255 or 0 / 65535) as a
// mask: what the silhouette IoU of a pose is measured against (register --mask, trial masks).
#include <filesystem>

#include <glm/glm.hpp>

#include "similarity/Mask.h"

namespace fm {

// Pixels above half the full scale. Throws fm::Error naming the file when it cannot be read or
// its size is not `size` (the radiograph's).
Mask readLabelMask(const std::filesystem::path& path, glm::ivec2 size);

}  // namespace fm

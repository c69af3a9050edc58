#pragma once
// 8-bit greyscale PNG of an image, for looking at DRRs and X-rays: values low..high map
// linearly to 0..255 (clamped; NaN becomes 0). Row 0 is the top row of the PNG.
#include <filesystem>

#include "core/Image.h"

namespace fm {

void writePng(const Image& image, const std::filesystem::path& path, float low, float high);

}  // namespace fm

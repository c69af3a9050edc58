#pragma once
// 8-bit greyscale PNG of an image, for looking at DRRs and X-rays: values low..high map
// linearly to 0..255 (clamped; NaN becomes 0). Row 0 is the top row of the PNG.
#include <cstdint>
#include <filesystem>
#include <vector>

#include "core/Image.h"

namespace fm {

void writePng(const Image& image, const std::filesystem::path& path, float low, float high);

// PNG file bytes of 8-bit pixels (`channels` 1..4, rows top first, `rowBytes` apart), encoded in
// memory so the caller writes them through io::writeFileAtomically (checked, atomic).
std::vector<std::uint8_t> encodePng(const std::uint8_t* pixels, int width, int height,
                                    int channels, int rowBytes);

}  // namespace fm

#pragma once
// A radiograph (one X-ray frame) from disk as an fm::Image of its stored values, by extension:
// TIFF through libtiff (io/TiffReader.h), PNG through libpng (io/PngReader.h), JPEG through
// libjpeg-turbo (io/JpegReader.h), BMP through stb_image after a size check (io/BmpReader.h);
// colour converted to one grey channel by stb's luminance, 16-bit PNG kept 16-bit. Values are
// not rescaled: 0..255 for 8-bit, 0..65535 for 16-bit files. Row 0 is the image's top row.
// Spacing is 1 (unknown); the camera calibration gives the geometry.
#include <filesystem>
#include <string>
#include <vector>

#include "core/Image.h"

namespace fm {

struct RadiographFile {
    Image image;
    int bitsPerSample = 8;
    std::string format;                 // "TIFF (LZW)", "PNG", ...
    std::vector<std::string> warnings;  // libtiff's benign ones (unknown tags and the like)
};

// A multi-page TIFF is refused unless `page` (0-based) names the page. fm::Error names the
// file for everything unreadable, truncated or corrupt, for images beyond io::kMaxTiffSide per
// side or io::kMaxTiffPixels pixels (checked from the header, before decoding), and for other
// extensions.
RadiographFile readRadiograph(const std::filesystem::path& path, int page = -1);

}  // namespace fm

#include "io/PngWriter.h"

#include <stb/stb_image_write.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "core/Error.h"
#include "io/AtomicFile.h"
#include "io/ByteSource.h"

namespace fm {

void writePng(const Image& image, const std::filesystem::path& path, float low, float high) {
    const std::string what = "PNG " + io::quoted(path);
    if (image.width <= 0 || image.height <= 0 ||
        image.pixels.size() != static_cast<std::size_t>(image.width) * image.height)
        throw Error(what + ": the image is empty or its pixel count does not match its size");
    if (!std::isfinite(low) || !std::isfinite(high) || !(high > low))
        throw Error(what + ": the grey window must be finite with high > low");
    std::vector<std::uint8_t> grey(image.pixels.size());
    const double range = static_cast<double>(high) - low;
    for (std::size_t n = 0; n < grey.size(); ++n) {
        const float v = image.pixels[n];
        if (std::isnan(v)) {
            grey[n] = 0;
            continue;
        }
        // Fraction first, then 255: the window's midpoint maps to 127.5 exactly, rounding to 128.
        const double g = std::round((static_cast<double>(v) - low) / range * 255.0);
        grey[n] = static_cast<std::uint8_t>(g < 0.0 ? 0.0 : g > 255.0 ? 255.0 : g);
    }
    io::writeViaTemporary(path, [&](const std::filesystem::path& temp) {
        return stbi_write_png(temp.string().c_str(), image.width, image.height, 1, grey.data(),
                              image.width) != 0;
    });
}

}  // namespace fm

#include "io/PngWriter.h"

#include <stb/stb_image_write.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "core/Error.h"
#include "io/AtomicFile.h"
#include "io/ByteSource.h"
#include "io/ImageFileWriter.h"

namespace fm {

std::vector<std::uint8_t> encodePng(const std::uint8_t* pixels, int width, int height,
                                    int channels, int rowBytes) {
    // In memory: stb's file writer does not check its fwrite/fclose, so a full disk would pass.
    std::vector<std::uint8_t> png;
    const auto append = [](void* context, void* data, int size) {
        auto* out = static_cast<std::vector<std::uint8_t>*>(context);
        const auto* bytes = static_cast<const std::uint8_t*>(data);
        out->insert(out->end(), bytes, bytes + size);
    };
    if (width <= 0 || height <= 0 || channels < 1 || channels > 4 ||
        !stbi_write_png_to_func(append, &png, width, height, channels, pixels, rowBytes))
        throw Error("PNG encoding failed (" + std::to_string(width) + " x " +
                    std::to_string(height) + ")");
    return png;
}

void writePng(const Image& image, const std::filesystem::path& path, float low, float high) {
    const std::string what = "PNG " + io::quoted(path);
    if (image.width <= 0 || image.height <= 0 ||
        image.pixels.size() != static_cast<std::size_t>(image.width) * image.height)
        throw Error(what + ": the image is empty or its pixel count does not match its size");
    if (!std::isfinite(low) || !std::isfinite(high) || !(high > low))
        throw Error(what + ": the grey window must be finite with high > low");
    const std::vector<std::uint8_t> grey = windowToGrey8(image, low, high);
    io::writeFileAtomically(path, encodePng(grey.data(), image.width, image.height, 1, image.width));
}

}  // namespace fm

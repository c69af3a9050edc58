#include "render/Screenshot.h"

#include <stb_image.h>

#include <cstring>

#include "core/Error.h"
#include "io/AtomicFile.h"
#include "io/ByteSource.h"
#include "io/PngWriter.h"
#include "platform/Gl.h"

namespace fm::render {

RgbaImage readFramebuffer(int width, int height) {
    RgbaImage image{width, height, std::vector<std::uint8_t>(std::size_t(width) * height * 4)};
    std::vector<std::uint8_t> bottomUp(image.pixels.size());
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, bottomUp.data());
    const std::size_t row = std::size_t(width) * 4;
    for (int y = 0; y < height; ++y)  // GL rows are bottom-up
        std::memcpy(&image.pixels[y * row], &bottomUp[(height - 1 - y) * row], row);
    for (std::size_t i = 3; i < image.pixels.size(); i += 4) image.pixels[i] = 255;  // opaque
    return image;
}

void writePng(const std::filesystem::path& path, const RgbaImage& image) {
    if (path.has_parent_path()) {
        std::error_code ec;
        std::filesystem::create_directories(path.parent_path(), ec);
    }
    if (image.width <= 0 || image.height <= 0 ||
        image.pixels.size() != std::size_t(image.width) * image.height * 4)
        throw Error("cannot write PNG " + io::quoted(path) + ": the image is empty");
    io::writeFileAtomically(path, encodePng(image.pixels.data(), image.width, image.height, 4,
                                            image.width * 4));
}

RgbaImage readPng(const std::filesystem::path& path) {
    int w = 0, h = 0, channels = 0;
    unsigned char* data = stbi_load(path.string().c_str(), &w, &h, &channels, 4);
    if (!data)
        throw Error("cannot read PNG " + path.string() + ": " +
                    (stbi_failure_reason() ? stbi_failure_reason() : "unknown reason"));
    RgbaImage image{w, h, std::vector<std::uint8_t>(data, data + std::size_t(w) * h * 4)};
    stbi_image_free(data);
    return image;
}

}  // namespace fm::render

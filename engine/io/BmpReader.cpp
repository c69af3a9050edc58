#include "io/BmpReader.h"

#include <stb/stb_image.h>

#include <cstdlib>
#include <memory>
#include <string>

#include "core/Error.h"
#include "io/ByteSource.h"

namespace fm::io {

namespace {

std::uint32_t little32(const Bytes& b, std::size_t at) {
    return std::uint32_t{b[at]} | std::uint32_t{b[at + 1]} << 8 | std::uint32_t{b[at + 2]} << 16 |
           std::uint32_t{b[at + 3]} << 24;
}
std::uint16_t little16(const Bytes& b, std::size_t at) {
    return static_cast<std::uint16_t>(b[at] | b[at + 1] << 8);
}

}  // namespace

GreyImage readBmp(const std::filesystem::path& path) {
    const std::string name = quoted(path);
    const std::uintmax_t size = fileSize(path);
    const Bytes head = readFilePrefix(path, 54);
    if (head.size() < 26 || head[0] != 'B' || head[1] != 'M')
        throw Error(name + ": not a BMP file (no BM signature)");
    const std::uint64_t offset = little32(head, 10), headerSize = little32(head, 14);
    std::int64_t width = 0, height = 0;
    unsigned bits = 0, compression = 0;
    if (headerSize == 12) {
        width = little16(head, 18), height = little16(head, 20);  // unsigned in the OS/2 header
        bits = little16(head, 24);
    } else {
        if (head.size() < 34) throw Error(name + ": truncated BMP (the header is cut short)");
        width = static_cast<std::int32_t>(little32(head, 18)),
        height = static_cast<std::int32_t>(little32(head, 22));
        bits = little16(head, 28), compression = little32(head, 30);
    }
    if (compression != 0 && compression != 3)
        throw Error(name + ": BMP compression " + std::to_string(compression) +
                    " (RLE or embedded JPEG/PNG) is not read; uncompressed BMPs are");
    if (bits != 1 && bits != 4 && bits != 8 && bits != 16 && bits != 24 && bits != 32)
        throw Error(name + ": " + std::to_string(bits) + " bits per pixel: not a BMP layout");
    const std::int64_t rows = height < 0 ? -height : height;
    checkGreyImageSize(path, width < 0 ? 0 : static_cast<std::uint64_t>(width),
                       static_cast<std::uint64_t>(rows));
    const std::uint64_t stride = (static_cast<std::uint64_t>(width) * bits + 31) / 32 * 4;
    const std::uint64_t needed = offset + stride * static_cast<std::uint64_t>(rows);
    if (needed > size)
        throw Error(name + ": truncated BMP (" + std::to_string(width) + " x " +
                    std::to_string(rows) + " pixels need " + std::to_string(needed) +
                    " bytes, the file holds " + std::to_string(size) + ")");
    const Bytes bytes = readFileRange(path, 0, static_cast<std::size_t>(needed));
    int w = 0, h = 0, channels = 0;
    std::unique_ptr<stbi_uc, void (*)(void*)> data(
        stbi_load_from_memory(bytes.data(), static_cast<int>(bytes.size()), &w, &h, &channels, 1),
        stbi_image_free);
    if (!data)
        throw Error(name + ": cannot decode the BMP (" + std::string(stbi_failure_reason()) + ")");
    if (w != width || h != rows)
        throw Error(name + ": the BMP decoded to a size other than its header's");
    GreyImage g;
    g.image = Image(w, h);
    std::copy(data.get(), data.get() + g.image.pixels.size(), g.image.pixels.begin());
    return g;
}

}  // namespace fm::io

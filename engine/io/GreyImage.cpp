#include "io/GreyImage.h"

#include <string>

#include "core/Error.h"
#include "io/ByteSource.h"
#include "io/TiffReader.h"

namespace fm::io {

void checkGreyImageSize(const std::filesystem::path& path, std::uint64_t width,
                        std::uint64_t height) {
    const auto side = static_cast<std::uint64_t>(kMaxTiffSide);
    if (width < 1 || height < 1 || width > side || height > side)
        throw Error(quoted(path) + ": image size " + std::to_string(width) + " x " +
                    std::to_string(height) + " is outside 1.." + std::to_string(kMaxTiffSide));
    if (width * height > kMaxTiffPixels)
        throw Error(quoted(path) + ": image size " + std::to_string(width) + " x " +
                    std::to_string(height) + " is more than " + std::to_string(kMaxTiffPixels) +
                    " pixels: too large");
}

GreyImage GreyRows::finish(int bitsPerSample) {
    if (!complete())
        throw Error("internal: an image was finished before all its rows were decoded");
    GreyImage g;
    g.bitsPerSample = bitsPerSample;
    g.image.width = static_cast<int>(width);
    g.image.height = static_cast<int>(height);
    g.image.pixels = std::move(pixels);
    return g;
}

}  // namespace fm::io

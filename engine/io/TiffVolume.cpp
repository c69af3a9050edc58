#include "io/TiffVolume.h"

#include <algorithm>
#include <cmath>

#include "core/Error.h"
#include "io/TiffReader.h"

namespace fm::io {

Volume readTiffVolume(const std::filesystem::path& path, const glm::dvec3& spacing) {
    for (int a = 0; a < 3; ++a)
        if (!(std::isfinite(spacing[a]) && spacing[a] > 0.0))
            throw Error(path.string() + ": \"spacing\" must be three positive voxel sizes in mm");
    TiffContent tiff = readTiff(path);
    const TiffPage& first = tiff.pages[0];
    Volume v = Volume::allocate({first.width, first.height, static_cast<int>(tiff.pages.size())});
    const std::size_t slice = static_cast<std::size_t>(first.width) * first.height;
    for (std::size_t k = 0; k < tiff.pages.size(); ++k)
        std::copy(tiff.pages[k].values.begin(), tiff.pages[k].values.end(),
                  v.values.begin() + static_cast<std::ptrdiff_t>(k * slice));
    v.spacing = spacing;
    v.meta.source = path.string();
    v.meta.description = "TIFF stack (" + tiff.compression + ", " + std::to_string(first.bitsPerSample) +
                         "-bit), voxel size given by the user";
    // libtiff's benign warnings (its warnings about data are errors, in readTiff) stay visible.
    for (const std::string& w : tiff.warnings) v.meta.description += "; libtiff warning: " + w;
    v.validate(path.string());
    return v;
}

std::vector<std::uint8_t> encodeTiffStack16(const Volume& volume, double offset) {
    const std::uint32_t w = static_cast<std::uint32_t>(volume.dims.x), h = static_cast<std::uint32_t>(volume.dims.y);
    const std::uint32_t pages = static_cast<std::uint32_t>(volume.dims.z);
    const std::uint64_t pageBytes = std::uint64_t{w} * h * 2;
    constexpr std::uint32_t kEntries = 10, kIfdBytes = 2 + kEntries * 12 + 4;
    if (volume.voxelCount() == 0 || 8 + pages * (kIfdBytes + pageBytes) > 0xFFFFFF00u)
        throw Error("TIFF stack encoding: the volume is empty or larger than 4 GiB");
    std::vector<std::uint8_t> out;
    out.reserve(8 + pages * (kIfdBytes + pageBytes));
    const auto put16 = [&](std::uint32_t v) {
        out.push_back(static_cast<std::uint8_t>(v & 0xFF));
        out.push_back(static_cast<std::uint8_t>((v >> 8) & 0xFF));
    };
    const auto put32 = [&](std::uint32_t v) {
        for (int b = 0; b < 4; ++b) out.push_back(static_cast<std::uint8_t>((v >> (8 * b)) & 0xFF));
    };
    out.push_back('I');
    out.push_back('I');
    put16(42);
    put32(8);  // the first IFD follows the header; each page is IFD then pixels
    for (std::uint32_t k = 0; k < pages; ++k) {
        const std::uint32_t ifd = static_cast<std::uint32_t>(out.size());
        const std::uint32_t data = ifd + kIfdBytes;
        const std::uint32_t next = k + 1 < pages ? data + static_cast<std::uint32_t>(pageBytes) : 0;
        put16(kEntries);
        const auto entry = [&](std::uint32_t tag, std::uint32_t type, std::uint32_t value) {
            put16(tag);
            put16(type);
            put32(1);
            if (type == 3) {  // SHORT, left-justified
                put16(value);
                put16(0);
            } else {
                put32(value);
            }
        };
        entry(256, 4, w);                                          // ImageWidth
        entry(257, 4, h);                                          // ImageLength
        entry(258, 3, 16);                                         // BitsPerSample
        entry(259, 3, 1);                                          // Compression: none
        entry(262, 3, 1);                                          // BlackIsZero
        entry(273, 4, data);                                       // StripOffsets
        entry(277, 3, 1);                                          // SamplesPerPixel
        entry(278, 4, h);                                          // RowsPerStrip
        entry(279, 4, static_cast<std::uint32_t>(pageBytes));      // StripByteCounts
        entry(339, 3, 1);                                          // SampleFormat: unsigned
        put32(next);
        for (std::uint32_t j = 0; j < h; ++j)
            for (std::uint32_t i = 0; i < w; ++i) {
                const double v = volume.at(static_cast<int>(i), static_cast<int>(j), static_cast<int>(k));
                put16(static_cast<std::uint32_t>(std::clamp(std::isnan(v) ? 0.0 : std::round(v + offset), 0.0, 65535.0)));
            }
    }
    return out;
}

}  // namespace fm::io

#include "io/ImageFileWriter.h"

#include <stb/stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "core/Error.h"
#include "io/AtomicFile.h"
#include "io/ByteSource.h"
#include "io/HeaderText.h"
#include "io/PngWriter.h"
#include "io/VolumeWriter.h"

namespace fm {

namespace {

constexpr const char* kFormats = ".png, .jpg, .jpeg, .tif, .tiff, .mha, .nii or .nii.gz";

void checkImage(const Image& image, const std::string& what) {
    if (image.width <= 0 || image.height <= 0 ||
        image.pixels.size() != static_cast<std::size_t>(image.width) * image.height)
        throw Error(what + ": the image is empty or its pixel count does not match its size");
}

// Little-endian TIFF writing helpers.
void put16(std::vector<std::uint8_t>& out, std::uint16_t v) {
    out.push_back(static_cast<std::uint8_t>(v & 0xFF));
    out.push_back(static_cast<std::uint8_t>(v >> 8));
}
void put32(std::vector<std::uint8_t>& out, std::uint32_t v) {
    for (int b = 0; b < 4; ++b) out.push_back(static_cast<std::uint8_t>((v >> (8 * b)) & 0xFF));
}

// Baseline TIFF (TIFF 6.0, section 4: grey scale), one uncompressed strip.
std::vector<std::uint8_t> encodeTiff(const std::uint8_t* data, std::size_t bytes, int width,
                                     int height, int bitsPerSample, int sampleFormat) {
    if (width <= 0 || height <= 0 || bytes > 0xFFFFFF00u)
        throw Error("TIFF encoding: the image is empty or larger than 4 GiB");
    constexpr std::uint16_t kShort = 3, kLong = 4, kRational = 5;
    constexpr int kEntries = 12;
    constexpr std::uint32_t kIfdOffset = 8;
    constexpr std::uint32_t kIfdBytes = 2 + kEntries * 12 + 4;
    constexpr std::uint32_t kResolutionOffset = kIfdOffset + kIfdBytes;  // two rationals
    constexpr std::uint32_t kDataOffset = kResolutionOffset + 16;
    std::vector<std::uint8_t> out;
    out.reserve(kDataOffset + bytes);
    out.push_back('I');
    out.push_back('I');
    put16(out, 42);
    put32(out, kIfdOffset);
    put16(out, kEntries);
    const auto entry = [&](std::uint16_t tag, std::uint16_t type, std::uint32_t value) {
        put16(out, tag);
        put16(out, type);
        put32(out, 1);
        if (type == kShort) {  // left-justified in the 4-byte value field
            put16(out, static_cast<std::uint16_t>(value));
            put16(out, 0);
        } else {
            put32(out, value);
        }
    };
    // Tags in ascending order, as TIFF requires.
    entry(256, kLong, static_cast<std::uint32_t>(width));   // ImageWidth
    entry(257, kLong, static_cast<std::uint32_t>(height));  // ImageLength
    entry(258, kShort, static_cast<std::uint32_t>(bitsPerSample));
    entry(259, kShort, 1);                                   // Compression: none
    entry(262, kShort, 1);                                   // Photometric: BlackIsZero
    entry(273, kLong, kDataOffset);                          // StripOffsets
    entry(277, kShort, 1);                                   // SamplesPerPixel
    entry(278, kLong, static_cast<std::uint32_t>(height));   // RowsPerStrip: one strip
    entry(279, kLong, static_cast<std::uint32_t>(bytes));    // StripByteCounts
    entry(282, kRational, kResolutionOffset);                // XResolution
    entry(283, kRational, kResolutionOffset + 8);            // YResolution
    entry(339, kShort, static_cast<std::uint32_t>(sampleFormat));
    put32(out, 0);  // no further IFD
    for (int r = 0; r < 2; ++r) {  // 72/1 pixels per (ResolutionUnit default) inch
        put32(out, 72);
        put32(out, 1);
    }
    out.insert(out.end(), data, data + bytes);
    return out;
}

void writeVolumeFormat(const Image& image, const std::filesystem::path& path) {
    writeImage(image, path);  // io/VolumeWriter: .mha, .nii, .nii.gz by extension
}

}  // namespace

ImageFileFormat imageFileFormat(const std::filesystem::path& path, const std::string& option) {
    const std::string name = io::toLower(path.filename().string());
    if (io::endsWith(name, ".png")) return ImageFileFormat::Png;
    if (io::endsWith(name, ".jpg") || io::endsWith(name, ".jpeg")) return ImageFileFormat::Jpeg;
    if (io::endsWith(name, ".tif") || io::endsWith(name, ".tiff")) return ImageFileFormat::Tiff;
    if (io::endsWith(name, ".mha") || io::endsWith(name, ".nii") || io::endsWith(name, ".nii.gz"))
        return ImageFileFormat::Volume;
    if (path.extension().empty() && io::writesThrough(path)) return ImageFileFormat::Png;
    throw Error(option + " " + io::quoted(path) + ": unknown image format; the name must end in " +
                kFormats);
}

std::vector<std::uint8_t> windowToGrey8(const Image& image, float low, float high) {
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
    return grey;
}

std::vector<std::uint8_t> encodeTiffGrey8(const std::vector<std::uint8_t>& pixels, int width,
                                          int height) {
    if (pixels.size() != static_cast<std::size_t>(width) * height)
        throw Error("TIFF encoding: the pixel count does not match the size");
    return encodeTiff(pixels.data(), pixels.size(), width, height, 8, 1);
}

std::vector<std::uint8_t> encodeTiffFloat(const Image& image) {
    checkImage(image, "TIFF encoding");
    std::vector<std::uint8_t> bytes(image.pixels.size() * 4);
    std::memcpy(bytes.data(), image.pixels.data(), bytes.size());
    if (!io::hostIsLittleEndian())  // the header says "II": little-endian samples
        for (std::size_t n = 0; n < bytes.size(); n += 4) {
            std::swap(bytes[n], bytes[n + 3]);
            std::swap(bytes[n + 1], bytes[n + 2]);
        }
    return encodeTiff(bytes.data(), bytes.size(), image.width, image.height, 32, 3);
}

std::vector<std::uint8_t> encodeTiffGrey16(const Image& image, double scale) {
    checkImage(image, "TIFF encoding");
    std::vector<std::uint8_t> bytes(image.pixels.size() * 2);
    for (std::size_t n = 0; n < image.pixels.size(); ++n) {
        const double v = std::isnan(image.pixels[n]) ? 0.0 : std::round(double(image.pixels[n]) * scale);
        const auto sample = static_cast<std::uint16_t>(std::clamp(v, 0.0, 65535.0));
        bytes[2 * n] = static_cast<std::uint8_t>(sample & 0xFF);  // "II": little-endian samples
        bytes[2 * n + 1] = static_cast<std::uint8_t>(sample >> 8);
    }
    return encodeTiff(bytes.data(), bytes.size(), image.width, image.height, 16, 1);
}

std::vector<std::uint8_t> encodeJpegGrey8(const std::vector<std::uint8_t>& pixels, int width,
                                          int height, int quality) {
    // In memory: stb's file writer does not check its fwrite/fclose.
    std::vector<std::uint8_t> jpeg;
    const auto append = [](void* context, void* data, int size) {
        auto* out = static_cast<std::vector<std::uint8_t>*>(context);
        const auto* bytes = static_cast<const std::uint8_t*>(data);
        out->insert(out->end(), bytes, bytes + size);
    };
    if (width <= 0 || height <= 0 || pixels.size() != static_cast<std::size_t>(width) * height ||
        quality < 1 || quality > 100 ||
        !stbi_write_jpg_to_func(append, &jpeg, width, height, 1, pixels.data(), quality))
        throw Error("JPEG encoding failed (" + std::to_string(width) + " x " +
                    std::to_string(height) + ")");
    return jpeg;
}

void writeViewImage(const Image& image, const std::filesystem::path& path, float low, float high,
                    const std::string& option) {
    const ImageFileFormat format = imageFileFormat(path, option);
    const std::string what = option + " " + io::quoted(path);
    checkImage(image, what);
    if (format == ImageFileFormat::Volume) return writeVolumeFormat(image, path);
    if (!std::isfinite(low) || !std::isfinite(high) || !(high > low))
        throw Error(what + ": the grey window must be finite with high > low");
    const std::vector<std::uint8_t> grey = windowToGrey8(image, low, high);
    switch (format) {
        case ImageFileFormat::Png:
            return io::writeFileAtomically(
                path, encodePng(grey.data(), image.width, image.height, 1, image.width));
        case ImageFileFormat::Jpeg:
            return io::writeFileAtomically(path,
                                           encodeJpegGrey8(grey, image.width, image.height));
        default:
            return io::writeFileAtomically(path,
                                           encodeTiffGrey8(grey, image.width, image.height));
    }
}

void checkExactImagePath(const std::filesystem::path& path, const std::string& option) {
    const ImageFileFormat format = imageFileFormat(path, option);
    if (format == ImageFileFormat::Png || format == ImageFileFormat::Jpeg)
        throw Error(option + " " + io::quoted(path) +
                    ": 8-bit PNG/JPEG cannot hold the exact values; use .tif, .mha or .nii");
}

void writeExactImage(const Image& image, const std::filesystem::path& path,
                     const std::string& option) {
    checkExactImagePath(path, option);
    checkImage(image, option + " " + io::quoted(path));
    if (imageFileFormat(path, option) == ImageFileFormat::Tiff)
        return io::writeFileAtomically(path, encodeTiffFloat(image));
    writeVolumeFormat(image, path);
}

}  // namespace fm

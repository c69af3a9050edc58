#include "radiograph/Radiograph.h"

#include <cctype>

#include "core/Error.h"
#include "io/BmpReader.h"
#include "io/ByteSource.h"
#include "io/JpegReader.h"
#include "io/PngReader.h"
#include "io/TiffReader.h"

namespace fm {

namespace {

std::string lowerExtension(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

RadiographFile fromGrey(io::GreyImage grey, const char* format) {
    RadiographFile r;
    r.image = std::move(grey.image);
    r.bitsPerSample = grey.bitsPerSample;
    r.format = format;
    return r;
}

RadiographFile readTiffRadiograph(const std::filesystem::path& path, int page) {
    io::TiffContent tiff = io::readTiff(path);
    const int pages = static_cast<int>(tiff.pages.size());
    if (page < 0 && pages > 1)
        throw Error(path.string() + ": holds " + std::to_string(pages) +
                    " pages; a radiograph is one page (name the page)");
    const int index = page < 0 ? 0 : page;
    if (index >= pages)
        throw Error(path.string() + ": page " + std::to_string(index + 1) +
                    " requested, the file holds " + std::to_string(pages));
    io::TiffPage& p = tiff.pages[static_cast<std::size_t>(index)];
    RadiographFile r;
    r.image.width = p.width;
    r.image.height = p.height;
    r.image.pixels = std::move(p.values);
    r.bitsPerSample = p.bitsPerSample;
    r.format = "TIFF (" + tiff.compression + ")";
    r.warnings = std::move(tiff.warnings);
    return r;
}

}  // namespace

RadiographFile readRadiograph(const std::filesystem::path& path, int page) {
    const std::string ext = lowerExtension(path);
    if (io::hasTiffExtension(path)) return readTiffRadiograph(path, page);
    if (ext == ".png") return fromGrey(io::readPng(path), "PNG");
    if (ext == ".jpg" || ext == ".jpeg") return fromGrey(io::readJpeg(path), "JPEG");
    if (ext == ".bmp") return fromGrey(io::readBmp(path), "BMP");
    throw Error(io::quoted(path) + ": unknown radiograph format '" + ext +
                "' (read: .tif/.tiff, .png, .jpg/.jpeg, .bmp)");
}

}  // namespace fm

#include "radiograph/Radiograph.h"

#include <algorithm>
#include <cctype>

#include <stb/stb_image.h>

#include "core/Error.h"
#include "io/TiffReader.h"

namespace fm {

namespace {

std::string lowerExtension(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

RadiographFile readWithStb(const std::filesystem::path& path) {
    const std::string name = path.string();
    int w = 0, h = 0, channels = 0;
    if (!stbi_info(name.c_str(), &w, &h, &channels))
        throw Error(name + ": not a readable image (" + std::string(stbi_failure_reason()) + ")");
    if (w < 1 || h < 1 || w > io::kMaxTiffSide || h > io::kMaxTiffSide)
        throw Error(name + ": image size " + std::to_string(w) + " x " + std::to_string(h) +
                    " is outside 1.." + std::to_string(io::kMaxTiffSide));
    RadiographFile r;
    const bool sixteen = stbi_is_16_bit(name.c_str()) != 0;
    r.bitsPerSample = sixteen ? 16 : 8;
    r.image = Image(w, h);
    if (sixteen) {
        stbi_us* data = stbi_load_16(name.c_str(), &w, &h, &channels, 1);
        if (!data) throw Error(name + ": cannot decode the image (" + std::string(stbi_failure_reason()) + ")");
        std::copy(data, data + r.image.pixels.size(), r.image.pixels.begin());
        stbi_image_free(data);
    } else {
        stbi_uc* data = stbi_load(name.c_str(), &w, &h, &channels, 1);
        if (!data) throw Error(name + ": cannot decode the image (" + std::string(stbi_failure_reason()) + ")");
        std::copy(data, data + r.image.pixels.size(), r.image.pixels.begin());
        stbi_image_free(data);
    }
    const std::string ext = lowerExtension(path);
    r.format = ext == ".png" ? "PNG" : (ext == ".jpg" || ext == ".jpeg") ? "JPEG" : "image (stb)";
    return r;
}

}  // namespace

RadiographFile readRadiograph(const std::filesystem::path& path, int page) {
    const std::string ext = lowerExtension(path);
    if (ext != ".tif" && ext != ".tiff") return readWithStb(path);
    io::TiffContent tiff = io::readTiff(path);
    const int pages = static_cast<int>(tiff.pages.size());
    if (page < 0 && pages > 1)
        throw Error(path.string() + ": holds " + std::to_string(pages) +
                    " pages; a radiograph is one page (name the page)");
    const int index = page < 0 ? 0 : page;
    if (index >= pages)
        throw Error(path.string() + ": page " + std::to_string(index + 1) + " requested, the file holds " +
                    std::to_string(pages));
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

}  // namespace fm

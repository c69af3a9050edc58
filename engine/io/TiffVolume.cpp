#include "io/TiffVolume.h"

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

}  // namespace fm::io

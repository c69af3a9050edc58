#include "radiograph/LabelMask.h"

#include <string>

#include "core/Error.h"
#include "radiograph/Radiograph.h"

namespace fm {

Mask readLabelMask(const std::filesystem::path& path, glm::ivec2 size) {
    const RadiographFile file = readRadiograph(path);
    if (file.image.width != size.x || file.image.height != size.y)
        throw Error(path.string() + ": the mask is " + std::to_string(file.image.width) + "x" +
                    std::to_string(file.image.height) + " but the radiograph is " +
                    std::to_string(size.x) + "x" + std::to_string(size.y));
    Mask m(size.x, size.y, false);
    const float half = file.bitsPerSample > 8 ? 32767.5f : 127.5f;
    for (std::size_t i = 0; i < m.inside.size(); ++i) m.inside[i] = file.image.pixels[i] > half;
    return m;
}

}  // namespace fm

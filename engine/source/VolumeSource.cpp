#include "source/VolumeSource.h"

#include <algorithm>

#include "core/Error.h"
#include "io/HeaderText.h"
#include "io/ReadVolume.h"
#include "phantom/Phantoms.h"

namespace fm {

Volume loadVolume(const std::string& spec) {
    constexpr std::string_view kPrefix = "phantom:";
    if (spec.rfind(kPrefix, 0) == 0) return makePhantom(spec.substr(kPrefix.size()));
    // "stack.tif?spacing=sx,sy,sz": the voxel size of a file that carries none.
    constexpr std::string_view kSpacing = "?spacing=";
    const std::size_t at = spec.rfind(kSpacing);
    if (at == std::string::npos) return readVolume(spec);
    const std::string path = spec.substr(0, at), numbers = spec.substr(at + kSpacing.size());
    std::string spaced = numbers;
    for (char& c : spaced)
        if (c == ',') c = ' ';
    const auto v = io::parseNumbers(spaced, 3, spec + ": \"spacing\" (sx,sy,sz in mm)");
    if (std::count(numbers.begin(), numbers.end(), ',') != 2)
        throw Error(spec + ": \"spacing\" must be three numbers sx,sy,sz separated by commas");
    VolumeReadOptions options;
    options.spacing = glm::dvec3(v[0], v[1], v[2]);
    return readVolume(path, options);
}

}  // namespace fm

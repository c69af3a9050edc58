#include "volume/VolumeSource.h"

#include "io/ReadVolume.h"
#include "phantom/Phantoms.h"

namespace fm {

Volume loadVolume(const std::string& spec) {
    constexpr std::string_view kPrefix = "phantom:";
    if (spec.rfind(kPrefix, 0) == 0) return makePhantom(spec.substr(kPrefix.size()));
    return readVolume(spec);
}

}  // namespace fm

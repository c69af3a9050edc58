#include "render/TextureVersions.h"

#include <unordered_map>

namespace fm::render {
namespace {

// One counter for all textures: a deleted texture's name reused by a new one gets a new version.
std::uint64_t lastVersion = 0;
std::unordered_map<unsigned, std::uint64_t>& versions() {
    static std::unordered_map<unsigned, std::uint64_t> map;
    return map;
}

}  // namespace

void markTextureChanged(unsigned texture) { versions()[texture] = ++lastVersion; }

std::uint64_t textureVersion(unsigned texture) {
    const auto it = versions().find(texture);
    return it == versions().end() ? 0 : it->second;
}

}  // namespace fm::render

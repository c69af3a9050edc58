#pragma once
// A version number per GL texture that changes whenever its pixels do, so a frame that shows
// the same texture in the same place is known to look the same (FramePresenter redraws only
// what changed). Every code that writes a texture's pixels calls markTextureChanged; GL thread
// only.
#include <cstdint>

namespace fm::render {

void markTextureChanged(unsigned texture);
// 0 for a texture never marked (e.g. ImGui's font atlas, written once before the first frame).
std::uint64_t textureVersion(unsigned texture);

}  // namespace fm::render

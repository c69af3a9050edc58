#pragma once
// How DRRs are shown: value -> grey through window/level (bright = more attenuation, the look of
// a radiograph), and the comparison views of reference against user. Pure functions, no GL.
#include <cstdint>
#include <vector>

#include "core/Image.h"

namespace fm::render {

struct WindowLevel {
    float window = 1.0f;  // width of the value range mapped to black..white
    float level = 0.5f;   // value shown mid-grey
};

// Window/level spanning an image's value range (min..max), the default for a new reference.
WindowLevel fullRange(const Image& image);

// Grey RGBA, row 0 first: black at level - window/2, white at level + window/2.
std::vector<std::uint8_t> windowedRgba(const Image& image, const WindowLevel& wl);

// Signed difference user - reference, scaled by the window: red where the user's DRR has more
// attenuation, blue where less, black where equal. Sizes must match (else empty result).
std::vector<std::uint8_t> differenceRgba(const Image& reference, const Image& user,
                                         const WindowLevel& wl);
// Reference in magenta, user in green: where they agree the overlay is grey.
std::vector<std::uint8_t> overlayRgba(const Image& reference, const Image& user,
                                      const WindowLevel& wl);
// Alternating tiles of reference and user (tile edge in pixels): edges that do not continue
// across tiles show the misalignment.
std::vector<std::uint8_t> checkerboardRgba(const Image& reference, const Image& user,
                                           const WindowLevel& wl, int tile = 32);

}  // namespace fm::render

#pragma once
// A 2D float image (DRRs, X-ray frames, similarity maps). Row 0 first, column fastest:
// pixel (col, row) is at pixels[col + width * row]. Spacing is the detector pixel pitch in mm
// (1 when unknown).
#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

namespace fm {

struct Image {
    int width = 0;
    int height = 0;
    glm::dvec2 spacing{1.0};
    std::vector<float> pixels;

    Image() = default;
    Image(int w, int h, float fill = 0.0f)
        : width(w), height(h), pixels(static_cast<std::size_t>(w) * h, fill) {}

    bool empty() const { return pixels.empty(); }
    float& at(int col, int row) { return pixels[static_cast<std::size_t>(row) * width + col]; }
    float at(int col, int row) const { return pixels[static_cast<std::size_t>(row) * width + col]; }
};

}  // namespace fm

#pragma once
// An RGBA8 2D texture for showing images (DRRs, comparison views) and the film quad.
#include <cstdint>
#include <vector>

#include "platform/Gl.h"

namespace fm::render {

class Texture {
  public:
    Texture();
    ~Texture();
    Texture(const Texture&) = delete;
    Texture& operator=(const Texture&) = delete;

    // Uploads width*height RGBA pixels, row 0 first (becomes texture coordinate t = 0).
    void upload(int width, int height, const std::vector<std::uint8_t>& rgba);
    GLuint id() const { return id_; }
    int width() const { return width_; }
    int height() const { return height_; }
    bool empty() const { return width_ == 0; }

  private:
    GLuint id_ = 0;
    int width_ = 0, height_ = 0;
};

}  // namespace fm::render

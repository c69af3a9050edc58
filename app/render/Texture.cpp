#include "render/Texture.h"

#include "render/TextureVersions.h"

namespace fm::render {

Texture::Texture() {
    glGenTextures(1, &id_);
    glBindTexture(GL_TEXTURE_2D, id_);
    // Linear: the DRRs (256 px) are shown larger than they are; clamp: no wrap at the border.
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

Texture::~Texture() {
    if (!id_) return;
    markTextureChanged(id_);  // its name may be reused by a new texture
    glDeleteTextures(1, &id_);
}

void Texture::upload(int width, int height, const std::vector<std::uint8_t>& rgba) {
    glBindTexture(GL_TEXTURE_2D, id_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 rgba.data());
    markTextureChanged(id_);
    width_ = width;
    height_ = height;
}

}  // namespace fm::render

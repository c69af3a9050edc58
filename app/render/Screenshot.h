#pragma once
// Reading back what was drawn and writing it as PNG (stb_image_write from libstb).
#include <cstdint>
#include <filesystem>
#include <vector>

namespace fm::render {

struct RgbaImage {
    int width = 0, height = 0;
    std::vector<std::uint8_t> pixels;  // row 0 = top
};

// The current framebuffer (default or bound), flipped so row 0 is the top row.
RgbaImage readFramebuffer(int width, int height);
// Throws fm::Error naming the file when it cannot be written.
void writePng(const std::filesystem::path& path, const RgbaImage& image);
// Throws fm::Error naming the file when it cannot be read.
RgbaImage readPng(const std::filesystem::path& path);

}  // namespace fm::render

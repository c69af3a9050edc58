#include "TiffTestFiles.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include <tiffio.h>

namespace fm::test {

std::uint32_t tiffPattern(int x, int y, int p, int bits) {
    const std::uint32_t v = static_cast<std::uint32_t>(x * 37 + y * 101 + p * 59 + (x * y) % 13);
    return bits == 8 ? v % 256 : (v * 2731u) % 65536u;
}

void writeTestTiff(const std::filesystem::path& path, const TiffSpec& s) {
    TIFF* t = TIFFOpen(path.string().c_str(), s.bigEndian ? "wb" : "wl");
    if (!t) throw std::runtime_error("cannot write " + path.string());
    for (int p = 0; p < s.pages; ++p) {
        const int w = p < static_cast<int>(s.pageWidths.size()) ? s.pageWidths[p] : s.width;
        TIFFSetField(t, TIFFTAG_IMAGEWIDTH, w);
        TIFFSetField(t, TIFFTAG_IMAGELENGTH, s.height);
        TIFFSetField(t, TIFFTAG_BITSPERSAMPLE, s.bits);
        TIFFSetField(t, TIFFTAG_SAMPLESPERPIXEL, 1);
        TIFFSetField(t, TIFFTAG_PHOTOMETRIC, s.photometric);
        TIFFSetField(t, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG);
        TIFFSetField(t, TIFFTAG_COMPRESSION, s.compression);
        if (s.compression == COMPRESSION_LZW && s.predictor != 1) TIFFSetField(t, TIFFTAG_PREDICTOR, s.predictor);
        if (s.pages > 1) {
            TIFFSetField(t, TIFFTAG_SUBFILETYPE, FILETYPE_PAGE);
            TIFFSetField(t, TIFFTAG_PAGENUMBER, p, s.pages);
        }
        const int bytes = s.bits / 8;
        if (s.tiled) {
            TIFFSetField(t, TIFFTAG_TILEWIDTH, 16);
            TIFFSetField(t, TIFFTAG_TILELENGTH, 16);
            std::vector<std::uint8_t> tile(16 * 16 * bytes);
            for (int ty = 0; ty < s.height; ty += 16)
                for (int tx = 0; tx < w; tx += 16) {
                    std::fill(tile.begin(), tile.end(), 0);
                    for (int y = ty; y < std::min(s.height, ty + 16); ++y)
                        for (int x = tx; x < std::min(w, tx + 16); ++x) {
                            const std::uint32_t v = tiffPattern(x, y, p, s.bits);
                            const std::size_t at = ((y - ty) * 16 + (x - tx)) * bytes;
                            if (bytes == 1) tile[at] = static_cast<std::uint8_t>(v);
                            else {
                                const std::uint16_t v16 = static_cast<std::uint16_t>(v);
                                std::memcpy(&tile[at], &v16, 2);
                            }
                        }
                    if (TIFFWriteTile(t, tile.data(), tx, ty, 0, 0) < 0) throw std::runtime_error("tile");
                }
        } else {
            TIFFSetField(t, TIFFTAG_ROWSPERSTRIP, s.rowsPerStrip);
            std::vector<std::uint8_t> row(w * bytes);
            for (int y = 0; y < s.height; ++y) {
                for (int x = 0; x < w; ++x) {
                    const std::uint32_t v = tiffPattern(x, y, p, s.bits);
                    if (bytes == 1) row[x] = static_cast<std::uint8_t>(v);
                    else {
                        const std::uint16_t v16 = static_cast<std::uint16_t>(v);
                        std::memcpy(&row[x * 2], &v16, 2);  // host order: libtiff swaps if needed
                    }
                }
                if (TIFFWriteScanline(t, row.data(), y, 0) < 0) throw std::runtime_error("scanline");
            }
        }
        if (!TIFFWriteDirectory(t)) throw std::runtime_error("directory");
    }
    TIFFClose(t);
}

std::vector<std::uint8_t> handMadeTiff(std::uint32_t width, std::uint32_t height, std::size_t dataBytes) {
    std::vector<std::uint8_t> b = {'I', 'I', 42, 0, 8, 0, 0, 0};
    auto u16 = [&](std::uint32_t v) { b.push_back(v & 255), b.push_back((v >> 8) & 255); };
    auto u32 = [&](std::uint32_t v) { u16(v & 0xffff), u16(v >> 16); };
    const std::uint32_t entries = 8;
    const std::uint32_t dataAt = 8 + 2 + entries * 12 + 4;
    u16(entries);
    auto entry = [&](std::uint32_t tag, std::uint32_t type, std::uint32_t value) {
        u16(tag), u16(type), u32(1);
        if (type == 3) u16(value), u16(0);
        else u32(value);
    };
    entry(256, 4, width);
    entry(257, 4, height);
    entry(258, 3, 8);
    entry(259, 3, 1);
    entry(262, 3, 1);
    entry(273, 4, dataAt);
    entry(278, 4, height);
    entry(279, 4, width * height);
    u32(0);
    for (std::size_t i = 0; i < dataBytes; ++i) b.push_back(static_cast<std::uint8_t>(i * 7));
    return b;
}

}  // namespace fm::test

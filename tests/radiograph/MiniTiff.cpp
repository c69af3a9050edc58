#include "MiniTiff.h"

#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

namespace fm::test {

namespace {

struct Reader {
    std::vector<std::uint8_t> b;
    bool big = false;
    std::uint32_t u16(std::size_t at) const {
        if (at + 2 > b.size()) throw std::runtime_error("short file");
        return big ? (b[at] << 8 | b[at + 1]) : (b[at + 1] << 8 | b[at]);
    }
    std::uint32_t u32(std::size_t at) const {
        return big ? (u16(at) << 16 | u16(at + 2)) : (u16(at + 2) << 16 | u16(at));
    }
};

// Values of one IFD entry (SHORT or LONG, inline or at an offset).
std::vector<std::uint32_t> entryValues(const Reader& r, std::size_t entry) {
    const std::uint32_t type = r.u16(entry + 2), count = r.u32(entry + 4);
    const std::size_t size = type == 3 ? 2 : 4;
    if (type != 3 && type != 4) throw std::runtime_error("unexpected tag type");
    std::size_t at = count * size <= 4 ? entry + 8 : r.u32(entry + 8);
    std::vector<std::uint32_t> v;
    for (std::uint32_t i = 0; i < count; ++i, at += size) v.push_back(size == 2 ? r.u16(at) : r.u32(at));
    return v;
}

std::vector<std::uint8_t> unpackBits(const std::uint8_t* p, std::size_t n) {
    std::vector<std::uint8_t> out;
    std::size_t i = 0;
    while (i < n) {
        const int c = static_cast<std::int8_t>(p[i++]);
        if (c >= 0) {
            for (int k = 0; k <= c && i < n; ++k) out.push_back(p[i++]);
        } else if (c != -128) {
            if (i >= n) break;
            out.insert(out.end(), static_cast<std::size_t>(1 - c), p[i++]);
        }
    }
    return out;
}

std::vector<std::uint8_t> unLzw(const std::uint8_t* p, std::size_t n) {
    std::vector<std::vector<std::uint8_t>> table;
    auto reset = [&] {
        table.assign(258, {});
        for (int i = 0; i < 256; ++i) table[i] = {static_cast<std::uint8_t>(i)};
    };
    reset();
    std::vector<std::uint8_t> out;
    std::size_t bitPos = 0;
    int width = 9;
    auto next = [&]() -> int {
        if (bitPos + width > n * 8) return 257;
        int code = 0;
        for (int k = 0; k < width; ++k, ++bitPos)
            code = (code << 1) | ((p[bitPos / 8] >> (7 - bitPos % 8)) & 1);
        return code;
    };
    int prev = -1;
    for (;;) {
        int code = next();
        if (code == 257) break;
        if (code == 256) {
            reset();
            width = 9;
            code = next();
            if (code == 257) break;
            out.insert(out.end(), table.at(code).begin(), table.at(code).end());
            prev = code;
            continue;
        }
        std::vector<std::uint8_t> entry;
        if (code < static_cast<int>(table.size())) {
            entry = table[code];
            std::vector<std::uint8_t> added = table.at(prev);
            added.push_back(entry[0]);
            table.push_back(added);
        } else {
            entry = table.at(prev);
            entry.push_back(entry[0]);
            table.push_back(entry);
        }
        out.insert(out.end(), entry.begin(), entry.end());
        // TIFF's "early change": the code width grows one code before the table fills it.
        if (static_cast<int>(table.size()) >= (1 << width) - 1 && width < 12) ++width;
        prev = code;
    }
    return out;
}

}  // namespace

std::vector<MiniTiffPage> decodeMiniTiff(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    Reader r{std::vector<std::uint8_t>(std::istreambuf_iterator<char>(in), {})};
    if (r.b.size() < 8) throw std::runtime_error("not a TIFF");
    r.big = r.b[0] == 'M';
    if (r.u16(2) != 42) throw std::runtime_error("not a TIFF");
    std::vector<MiniTiffPage> pages;
    for (std::uint32_t ifd = r.u32(4); ifd != 0; ifd = r.u32(ifd + 2 + 12 * r.u16(ifd))) {
        MiniTiffPage page;
        std::vector<std::uint32_t> offsets, counts;
        std::uint32_t rowsPerStrip = 0xffffffffu, predictor = 1;
        for (std::uint32_t e = 0, n = r.u16(ifd); e < n; ++e) {
            const std::size_t entry = ifd + 2 + 12 * e;
            const std::uint32_t tag = r.u16(entry);
            if (tag == 256) page.width = static_cast<int>(entryValues(r, entry)[0]);
            if (tag == 257) page.height = static_cast<int>(entryValues(r, entry)[0]);
            if (tag == 258) page.bits = static_cast<int>(entryValues(r, entry)[0]);
            if (tag == 259) page.compression = static_cast<int>(entryValues(r, entry)[0]);
            if (tag == 273) offsets = entryValues(r, entry);
            if (tag == 278) rowsPerStrip = entryValues(r, entry)[0];
            if (tag == 279) counts = entryValues(r, entry);
            if (tag == 317) predictor = entryValues(r, entry)[0];
            if (tag == 277 && entryValues(r, entry)[0] != 1) throw std::runtime_error("not greyscale");
        }
        if (page.compression == 0) page.compression = 1;
        const std::size_t bytes = page.bits / 8, rowBytes = page.width * bytes;
        std::vector<std::uint8_t> data;
        for (std::size_t s = 0; s < offsets.size(); ++s) {
            if (offsets[s] + counts.at(s) > r.b.size()) throw std::runtime_error("strip beyond the file");
            const std::uint8_t* p = r.b.data() + offsets[s];
            std::vector<std::uint8_t> strip;
            if (page.compression == 1) strip.assign(p, p + counts[s]);
            else if (page.compression == 32773) strip = unpackBits(p, counts[s]);
            else if (page.compression == 5) strip = unLzw(p, counts[s]);
            else throw std::runtime_error("compression " + std::to_string(page.compression));
            const std::size_t rows = std::min<std::size_t>(rowsPerStrip, page.height - s * std::min<std::size_t>(rowsPerStrip, page.height));
            strip.resize(rows * rowBytes);
            data.insert(data.end(), strip.begin(), strip.end());
        }
        data.resize(rowBytes * page.height);
        page.values.resize(static_cast<std::size_t>(page.width) * page.height);
        for (int y = 0; y < page.height; ++y)
            for (int x = 0; x < page.width; ++x) {
                const std::uint8_t* q = data.data() + y * rowBytes + x * bytes;
                std::uint32_t v = bytes == 1 ? q[0] : r.big ? (q[0] << 8 | q[1]) : (q[1] << 8 | q[0]);
                if (predictor == 2 && x > 0) v = (v + page.values[y * page.width + x - 1]) & ((1u << page.bits) - 1);
                page.values[static_cast<std::size_t>(y) * page.width + x] = v;
            }
        pages.push_back(std::move(page));
    }
    return pages;
}

}  // namespace fm::test

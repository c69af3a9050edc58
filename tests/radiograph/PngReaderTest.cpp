// The PNG reader (libpng) on files written by libpng's writer and chunk by chunk: every colour
// type and depth as its stored grey values; the size limits and the deflate bound applied
// from the header, before decoding; every CRC and the zlib Adler-32 checked; truncation,
// missing or extra data refused; nothing printed.
#include <gtest/gtest.h>

#include "ImageTestFiles.h"
#include "common/TestData.h"
#include "core/Error.h"
#include "io/GreyImage.h"
#include "io/PngReader.h"
#include "radiograph/Radiograph.h"

namespace {

namespace fs = std::filesystem;
using fm::test::Bytes;

std::string pngErrorOf(const fs::path& p) {
    try {
        fm::io::readPng(p);
    } catch (const fm::Error& e) {
        return e.what();
    }
    return "";
}

// What the reader must give for `samples` written with `spec`: stb's luminance for colour,
// alpha dropped, palette looked up, 1/2/4-bit grey scaled to 0..255.
std::vector<float> expectedGrey(const fm::test::PngSpec& s,
                                const std::vector<std::uint32_t>& samples) {
    std::vector<float> out;
    const int channels = s.palette ? 1 : s.channels;
    for (std::size_t p = 0; p < std::size_t(s.width) * s.height; ++p) {
        const std::uint32_t* v = samples.data() + p * channels;
        std::uint32_t grey = v[0];
        if (s.palette) {
            std::uint32_t rgb[3];
            fm::test::paletteColour(static_cast<int>(v[0]), rgb);
            grey = fm::io::greyOfRgb(rgb[0], rgb[1], rgb[2]);
        } else if (channels >= 3) {
            grey = fm::io::greyOfRgb(v[0], v[1], v[2]);
        } else if (s.bitDepth < 8) {
            grey = v[0] * 255 / ((1u << s.bitDepth) - 1);
        }
        out.push_back(static_cast<float>(grey));
    }
    return out;
}

std::vector<std::uint32_t> pattern(const fm::test::PngSpec& s) {
    const int channels = s.palette ? 1 : s.channels;
    const std::uint32_t top = s.palette ? 255 : (1u << s.bitDepth) - 1;
    std::vector<std::uint32_t> v(std::size_t(s.width) * s.height * channels);
    for (std::size_t i = 0; i < v.size(); ++i)
        v[i] = static_cast<std::uint32_t>((i * 2654435761u) >> 7) % (top + 1);
    v[0] = top;  // the full scale appears
    return v;
}

TEST(PngReader, EveryColourTypeAndDepthGivesItsStoredGreyValues) {
    const fs::path dir = fm::test::scratchDir("png_layouts");
    struct Case {
        int channels, depth;
        bool palette, interlaced;
    };
    const Case cases[] = {{1, 8, false, false}, {1, 16, false, false}, {1, 1, false, false},
                          {1, 2, false, true},  {1, 4, false, false},  {2, 8, false, false},
                          {2, 16, false, true}, {3, 8, false, false},  {3, 16, false, false},
                          {4, 8, false, true},  {4, 16, false, false}, {1, 8, true, false},
                          {1, 16, false, true}, {1, 8, true, true}};
    int n = 0;
    for (const Case& c : cases) {
        fm::test::PngSpec s;
        s.width = 13, s.height = 11, s.channels = c.channels, s.bitDepth = c.depth;
        s.palette = c.palette, s.interlaced = c.interlaced, s.text = n % 2 == 1;
        const auto samples = pattern(s);
        const fs::path p = dir / ("p" + std::to_string(n++) + ".png");
        fm::test::writeTestPng(p, s, samples);
        const fm::io::GreyImage g = fm::io::readPng(p);
        ASSERT_EQ(g.image.width, 13) << p;
        ASSERT_EQ(g.image.height, 11) << p;
        EXPECT_EQ(g.bitsPerSample, c.depth == 16 ? 16 : 8) << p;
        EXPECT_EQ(g.image.pixels, expectedGrey(s, samples))
            << p << " channels " << c.channels << " depth " << c.depth;
    }
    // 16-bit values stay 0..65535 (not rescaled), through readRadiograph too.
    fm::test::PngSpec s;
    s.bitDepth = 16;
    std::vector<std::uint32_t> v(std::size_t(s.width) * s.height, 1234);
    v[0] = 65535, v[1] = 0;
    fm::test::writeTestPng(dir / "w.png", s, v);
    const fm::RadiographFile r = fm::readRadiograph(dir / "w.png");
    EXPECT_EQ(r.format, "PNG");
    EXPECT_EQ(r.bitsPerSample, 16);
    EXPECT_EQ(r.image.at(0, 0), 65535.0f);
    EXPECT_EQ(r.image.at(1, 0), 0.0f);
    EXPECT_EQ(r.image.at(2, 0), 1234.0f);
}

// The 32768 x 32768 bomb (a 217 KB file that cost 4.1 GB before it was refused): refused from
// the header by the pixel limit; a header within the limit but promising more than its IDAT
// bytes can inflate to is refused by the deflate bound. Neither decodes a row.
TEST(PngReader, HeaderPromisingTooMuchIsRefusedBeforeDecoding) {
    const fs::path dir = fm::test::scratchDir("png_bombs");
    const Bytes someRows = fm::test::zlibCompress(Bytes(16385 * 64, 0));
    fm::test::writeBytes(dir / "huge.png", fm::test::handMadePng(32768, 32768, someRows));
    const std::string huge = pngErrorOf(dir / "huge.png");
    EXPECT_NE(huge.find("'" + (dir / "huge.png").string() + "'"), std::string::npos) << huge;
    EXPECT_NE(huge.find("more than 268435456 pixels"), std::string::npos) << huge;
    fm::test::writeBytes(dir / "side.png", fm::test::handMadePng(40000, 2, someRows));
    EXPECT_NE(pngErrorOf(dir / "side.png").find("outside 1..32768"), std::string::npos)
        << pngErrorOf(dir / "side.png");
    fm::test::writeBytes(dir / "bomb.png", fm::test::handMadePng(16384, 16384, someRows));
    const std::string bomb = pngErrorOf(dir / "bomb.png");
    EXPECT_NE(bomb.find("cannot come from"), std::string::npos) << bomb;
    EXPECT_NE(bomb.find("1032:1"), std::string::npos) << bomb;
    // 16 bits per sample count double.
    fm::test::writeBytes(
        dir / "bomb16.png",
        fm::test::handMadePng(4096, 4096, fm::test::zlibCompress(Bytes(40000, 0)), 16));
    EXPECT_NE(pngErrorOf(dir / "bomb16.png").find("cannot come from"), std::string::npos)
        << pngErrorOf(dir / "bomb16.png");
}

// The deflate bound is not too tight: an all-zero image, deflate's best case, is read.
TEST(PngReader, AllZeroImageAtDeflatesBestRatioIsRead) {
    const fs::path dir = fm::test::scratchDir("png_zeros");
    const int w = 2048, h = 2048;
    const Bytes idat = fm::test::zlibCompress(Bytes(std::size_t(w + 1) * h, 0));
    std::cout << "[ deflate  ] " << w << " x " << h << " zeros: " << idat.size() << " bytes, ratio "
              << double(std::size_t(w + 1) * h) / double(idat.size()) << ":1\n";
    fm::test::writeBytes(dir / "zeros.png", fm::test::handMadePng(w, h, idat));
    const fm::io::GreyImage g = fm::io::readPng(dir / "zeros.png");
    EXPECT_EQ(g.image.width, w);
    EXPECT_EQ(std::count(g.image.pixels.begin(), g.image.pixels.end(), 0.0f),
              std::ptrdiff_t(w) * h);
}

struct Original {
    fs::path dir;
    Bytes bytes;
    std::vector<fm::test::PngChunk> chunks;
    const fm::test::PngChunk& find(const std::string& type) const {
        for (const auto& c : chunks)
            if (c.type == type) return c;
        throw std::runtime_error("no " + type);
    }
};

Original writeOriginal(const std::string& name) {
    Original o;
    o.dir = fm::test::scratchDir(name);
    fm::test::PngSpec s;
    s.width = 40, s.height = 30, s.text = true;
    fm::test::writeTestPng(o.dir / "o.png", s, pattern(s));
    o.bytes = fm::test::readBytes(o.dir / "o.png");
    o.chunks = fm::test::pngChunks(o.bytes);
    return o;
}

std::string errorOfBytes(const Original& o, const Bytes& b, const std::string& name) {
    fm::test::writeBytes(o.dir / name, b);
    return pngErrorOf(o.dir / name);
}

// One flipped bit anywhere in a chunk is refused: stb ignored every CRC and the Adler-32 and
// returned changed pixels.
TEST(PngReader, FlippedBitsAreRefused) {
    const Original o = writeOriginal("png_flips");
    ASSERT_EQ(pngErrorOf(o.dir / "o.png"), "");
    const fm::test::PngChunk& idat = o.find("IDAT");
    const fm::test::PngChunk& text = o.find("tEXt");
    // A payload byte of the image data: its chunk's CRC.
    Bytes b = o.bytes;
    b[idat.at + 8 + idat.length / 2] ^= 0x10;
    std::string e = errorOfBytes(o, b, "idat.png");
    EXPECT_NE(e.find("CRC error"), std::string::npos) << e;
    EXPECT_NE(e.find("idat.png'"), std::string::npos) << e;
    EXPECT_NE(e.find("IDAT"), std::string::npos) << e;
    // The CRC itself.
    b = o.bytes;
    b[idat.at + 8 + idat.length + 2] ^= 0x01;
    e = errorOfBytes(o, b, "crc.png");
    EXPECT_NE(e.find("CRC error"), std::string::npos) << e;
    // An ancillary chunk (text: no pixel depends on it) is refused all the same.
    b = o.bytes;
    b[text.at + 8 + 3] ^= 0x04;
    e = errorOfBytes(o, b, "text.png");
    EXPECT_NE(e.find("CRC error"), std::string::npos) << e;
    EXPECT_NE(e.find("tEXt"), std::string::npos) << e;
    // The zlib stream's Adler-32 (the IDAT's last 4 bytes), the chunk's CRC made to match.
    b = o.bytes;
    b[idat.at + 8 + idat.length - 2] ^= 0x01;
    fm::test::fixPngCrc(b, idat);
    e = errorOfBytes(o, b, "adler.png");
    EXPECT_NE(e.find("incorrect data check"), std::string::npos) << e;
    // A bit inside the compressed data, CRC made to match: zlib or the Adler-32 refuses it.
    for (std::size_t k = 2; k + 4 < idat.length; k += idat.length / 7) {
        b = o.bytes;
        b[idat.at + 8 + k] ^= 0x20;
        fm::test::fixPngCrc(b, idat);
        EXPECT_NE(errorOfBytes(o, b, "deflate.png"), "") << "byte " << k;
    }
    // IHDR's height, CRC made to match: the image data no longer fit.
    const fm::test::PngChunk& ihdr = o.find("IHDR");
    for (int delta : {-1, 1}) {
        b = o.bytes;
        b[ihdr.at + 8 + 7] = static_cast<std::uint8_t>(b[ihdr.at + 8 + 7] + delta);
        fm::test::fixPngCrc(b, ihdr);
        e = errorOfBytes(o, b, "height.png");
        EXPECT_NE(e, "") << delta;
    }
}

TEST(PngReader, TruncatedMissingAndExtraDataAreRefused) {
    const Original o = writeOriginal("png_truncated");
    const fm::test::PngChunk& idat = o.find("IDAT");
    const fm::test::PngChunk& iend = o.find("IEND");
    for (std::size_t cut :
         {std::size_t{0}, std::size_t{5}, std::size_t{20}, idat.at + 8 + idat.length / 2, iend.at,
          iend.at + 6, o.bytes.size() - 1}) {
        Bytes b(o.bytes.begin(), o.bytes.begin() + static_cast<std::ptrdiff_t>(cut));
        const std::string e = errorOfBytes(o, b, "cut.png");
        EXPECT_NE(e.find("cut.png'"), std::string::npos) << cut << ": " << e;
        if (cut > 8) {
            EXPECT_NE(e.find("truncated"), std::string::npos) << cut << ": " << e;
        }
    }
    // Rows of 40 pixels of value 7, each after its filter byte (0: none), as one zlib stream.
    auto rows = [](std::size_t n) {
        Bytes raw(std::size_t(41) * n, 7);
        for (std::size_t r = 0; r < n; ++r) raw[r * 41] = 0;
        return fm::test::zlibCompress(raw);
    };
    // An image one row short (a whole valid zlib stream, a correct CRC): not enough image data.
    EXPECT_NE(errorOfBytes(o, fm::test::handMadePng(40, 30, rows(29)), "short.png"), "");
    // One row too many: too much image data.
    EXPECT_NE(errorOfBytes(o, fm::test::handMadePng(40, 30, rows(31)), "long.png"), "");
    // Exactly right: read.
    fm::test::writeBytes(o.dir / "right.png", fm::test::handMadePng(40, 30, rows(30)));
    EXPECT_EQ(fm::io::readPng(o.dir / "right.png").image.at(3, 29), 7.0f);
    // Not a PNG at all, missing, empty.
    EXPECT_NE(errorOfBytes(o, {'h', 'e', 'l', 'l', 'o'}, "text.png").find("not a PNG file"),
              std::string::npos);
    EXPECT_NE(pngErrorOf(o.dir / "none.png").find("none.png"), std::string::npos);
    EXPECT_NE(errorOfBytes(o, {}, "empty.png"), "");
}

// libpng's warnings and errors become the fm::Error: none reaches stderr.
TEST(PngReader, NothingIsPrinted) {
    const Original o = writeOriginal("png_quiet");
    const fm::test::PngChunk& idat = o.find("IDAT");
    testing::internal::CaptureStderr();
    Bytes b = o.bytes;
    b[idat.at + 8 + 5] ^= 1;
    errorOfBytes(o, b, "a.png");
    fm::test::fixPngCrc(b, idat);
    errorOfBytes(o, b, "b.png");
    b = o.bytes;
    b.resize(b.size() - 20);
    errorOfBytes(o, b, "c.png");
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
}

}  // namespace

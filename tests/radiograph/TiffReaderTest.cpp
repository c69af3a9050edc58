// The TIFF reader on files written by libtiff's writer and by hand: every bit depth,
// compression, byte order, strips and tiles, several pages, against the pattern written and
// against the tests' own decoder (MiniTiff); refusal of mismatched pages, colour, huge and
// truncated files.
#include <gtest/gtest.h>

#include <fstream>

#include "MiniTiff.h"
#include "TiffTestFiles.h"
#include "common/TestData.h"
#include "core/Error.h"
#include "io/ReadVolume.h"
#include "io/TiffReader.h"
#include "radiograph/Radiograph.h"
#include "source/VolumeSource.h"

#include <stb/stb_image_write.h>
#include <tiffio.h>

namespace {

namespace fs = std::filesystem;
using fm::test::TiffSpec;

void writeBytes(const fs::path& p, const std::vector<std::uint8_t>& b) {
    std::ofstream(p, std::ios::binary).write(reinterpret_cast<const char*>(b.data()), static_cast<std::streamsize>(b.size()));
}

std::string tiffErrorOf(const fs::path& p) {
    try {
        fm::io::readTiff(p);
    } catch (const fm::Error& e) {
        return e.what();
    }
    return "";
}

TEST(TiffReader, EveryDepthCompressionAndLayoutReadsTheWrittenValues) {
    const fs::path dir = fm::test::scratchDir("tiff_layouts");
    int n = 0;
    for (int bits : {8, 16})
        for (int compression : {1, 5, 32773})
            for (bool big : {false, true})
                for (int pages : {1, 3})
                    for (bool tiled : {false, true}) {
                        TiffSpec s;
                        s.width = 37, s.height = 21, s.bits = bits, s.compression = compression;
                        s.bigEndian = big, s.pages = pages, s.tiled = tiled, s.rowsPerStrip = 4;
                        s.predictor = compression == 5 && bits == 16 ? 2 : 1;
                        const fs::path p = dir / ("t" + std::to_string(n++) + ".tif");
                        fm::test::writeTestTiff(p, s);
                        const fm::io::TiffContent c = fm::io::readTiff(p);
                        ASSERT_EQ(c.pages.size(), static_cast<std::size_t>(pages)) << p;
                        EXPECT_EQ(c.compression, compression == 1 ? "none" : compression == 5 ? "LZW" : "PackBits");
                        for (int k = 0; k < pages; ++k) {
                            const fm::io::TiffPage& page = c.pages[k];
                            ASSERT_EQ(page.width, 37);
                            ASSERT_EQ(page.height, 21);
                            EXPECT_EQ(page.bitsPerSample, bits);
                            int wrong = 0;
                            for (int y = 0; y < 21; ++y)
                                for (int x = 0; x < 37; ++x)
                                    wrong += page.values[y * 37 + x] != float(fm::test::tiffPattern(x, y, k, bits));
                            EXPECT_EQ(wrong, 0) << p << " page " << k;
                        }
                        // The tests' own decoder reads the strip files the same way.
                        if (!tiled) {
                            const auto mini = fm::test::decodeMiniTiff(p);
                            ASSERT_EQ(mini.size(), static_cast<std::size_t>(pages));
                            for (int k = 0; k < pages; ++k)
                                for (std::size_t i = 0; i < mini[k].values.size(); ++i)
                                    ASSERT_EQ(float(mini[k].values[i]), c.pages[k].values[i]) << p;
                        }
                    }
}

TEST(TiffReader, MinIsWhiteIsTurnedIntoMinIsBlack) {
    const fs::path p = fm::test::scratchDir("tiff_white") / "w.tif";
    TiffSpec s;
    s.photometric = 0;
    fm::test::writeTestTiff(p, s);
    const auto c = fm::io::readTiff(p);
    EXPECT_EQ(c.pages[0].values[3 + 7 * 2], 255.0f - float(fm::test::tiffPattern(3, 2, 0, 8)));
}

TEST(TiffReader, HandMadeUncompressedFile) {
    const fs::path p = fm::test::scratchDir("tiff_hand") / "h.tif";
    writeBytes(p, fm::test::handMadeTiff(4, 3, 12));
    const auto c = fm::io::readTiff(p);
    ASSERT_EQ(c.pages.size(), 1u);
    for (int i = 0; i < 12; ++i) EXPECT_EQ(c.pages[0].values[i], float((i * 7) % 256));
}

TEST(TiffReader, BrokenFilesAreRefusedNamingTheFile) {
    const fs::path dir = fm::test::scratchDir("tiff_broken");
    // Pages of different sizes.
    TiffSpec mixed;
    mixed.pages = 2;
    mixed.pageWidths = {7, 9};
    fm::test::writeTestTiff(dir / "mixed.tif", mixed);
    EXPECT_NE(tiffErrorOf(dir / "mixed.tif").find("page 2 is 9 x 5"), std::string::npos) << tiffErrorOf(dir / "mixed.tif");
    // Sizes beyond the limit are refused from the header, before any allocation.
    writeBytes(dir / "huge.tif", fm::test::handMadeTiff(100000, 100000, 16));
    EXPECT_NE(tiffErrorOf(dir / "huge.tif").find("outside 1..32768"), std::string::npos) << tiffErrorOf(dir / "huge.tif");
    // Truncated pixel data, uncompressed and LZW.
    writeBytes(dir / "short.tif", fm::test::handMadeTiff(64, 64, 100));
    EXPECT_NE(tiffErrorOf(dir / "short.tif").find("short.tif"), std::string::npos);
    TiffSpec lzw;
    lzw.width = 200, lzw.height = 100, lzw.compression = 5, lzw.rowsPerStrip = 100;
    fm::test::writeTestTiff(dir / "lzw.tif", lzw);
    {
        std::ifstream in(dir / "lzw.tif", std::ios::binary);
        std::vector<std::uint8_t> b((std::istreambuf_iterator<char>(in)), {});
        b.resize(b.size() / 2);
        writeBytes(dir / "lzw_cut.tif", b);
    }
    EXPECT_NE(tiffErrorOf(dir / "lzw_cut.tif").find("lzw_cut.tif"), std::string::npos);
    // Not a TIFF, missing, empty.
    writeBytes(dir / "text.tif", {'h', 'e', 'l', 'l', 'o'});
    EXPECT_NE(tiffErrorOf(dir / "text.tif").find("text.tif"), std::string::npos);
    EXPECT_NE(tiffErrorOf(dir / "none.tif").find("none.tif"), std::string::npos);
    writeBytes(dir / "empty.tif", {});
    EXPECT_NE(tiffErrorOf(dir / "empty.tif"), "");
}

TEST(TiffReader, ColourIsRefused) {
    const fs::path p = fm::test::scratchDir("tiff_rgb") / "rgb.tif";
    TIFF* t = TIFFOpen(p.string().c_str(), "w");
    TIFFSetField(t, TIFFTAG_IMAGEWIDTH, 4);
    TIFFSetField(t, TIFFTAG_IMAGELENGTH, 2);
    TIFFSetField(t, TIFFTAG_BITSPERSAMPLE, 8);
    TIFFSetField(t, TIFFTAG_SAMPLESPERPIXEL, 3);
    TIFFSetField(t, TIFFTAG_PHOTOMETRIC, PHOTOMETRIC_RGB);
    TIFFSetField(t, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG);
    std::vector<std::uint8_t> row(12, 9);
    for (int y = 0; y < 2; ++y) TIFFWriteScanline(t, row.data(), y, 0);
    TIFFClose(t);
    EXPECT_NE(tiffErrorOf(p).find("greyscale"), std::string::npos) << tiffErrorOf(p);
}

TEST(Radiograph, TiffPagesAndPngAreImagesOfStoredValues) {
    const fs::path dir = fm::test::scratchDir("radiograph_read");
    TiffSpec s;
    s.bits = 16, s.pages = 2, s.compression = 32773;
    fm::test::writeTestTiff(dir / "two.tif", s);
    EXPECT_THROW(fm::readRadiograph(dir / "two.tif"), fm::Error);  // which page?
    const fm::RadiographFile r = fm::readRadiograph(dir / "two.tif", 1);
    EXPECT_EQ(r.bitsPerSample, 16);
    EXPECT_EQ(r.image.at(5, 3), float(fm::test::tiffPattern(5, 3, 1, 16)));
    EXPECT_THROW(fm::readRadiograph(dir / "two.tif", 2), fm::Error);
    // PNG through stb: a 16-bit grey PNG written by stb's writer would be 8-bit, so write an
    // 8-bit one and read its stored values back.
    std::vector<std::uint8_t> grey(6 * 4);
    for (std::size_t i = 0; i < grey.size(); ++i) grey[i] = static_cast<std::uint8_t>(i * 10);
    ASSERT_TRUE(stbi_write_png((dir / "g.png").string().c_str(), 6, 4, 1, grey.data(), 6));
    const fm::RadiographFile png = fm::readRadiograph(dir / "g.png");
    EXPECT_EQ(png.format, "PNG");
    EXPECT_EQ(png.image.width, 6);
    EXPECT_EQ(png.image.at(5, 3), 230.0f);
    writeBytes(dir / "bad.png", {1, 2, 3});
    EXPECT_THROW(fm::readRadiograph(dir / "bad.png"), fm::Error);
}

TEST(TiffVolume, StacksNeedAVoxelSizeAndKeepPagesAsSlices) {
    const fs::path dir = fm::test::scratchDir("tiff_volume");
    TiffSpec s;
    s.bits = 16, s.pages = 4, s.compression = 32773;
    fm::test::writeTestTiff(dir / "stack.tif", s);
    EXPECT_THROW(fm::readVolume(dir / "stack.tif"), fm::Error);
    EXPECT_THROW(fm::loadVolume((dir / "stack.tif").string() + "?spacing=1,2"), fm::Error);
    EXPECT_THROW(fm::loadVolume((dir / "stack.tif").string() + "?spacing=1,0,2"), fm::Error);
    const fm::Volume v = fm::loadVolume((dir / "stack.tif").string() + "?spacing=0.5,0.25,2");
    EXPECT_EQ(v.dims, glm::ivec3(7, 5, 4));
    EXPECT_EQ(v.spacing, glm::dvec3(0.5, 0.25, 2));
    EXPECT_EQ(v.origin, glm::dvec3(0.0));
    EXPECT_EQ(v.at(6, 4, 3), float(fm::test::tiffPattern(6, 4, 3, 16)));
    EXPECT_EQ(fm::detectVolumeFormat(dir / "stack.tif"), "tiff");
}

// The directory entry of `tag` in a little-endian classic TIFF's first directory: its offset.
std::size_t ifdEntry(const std::vector<std::uint8_t>& b, std::uint16_t tag) {
    auto u16 = [&](std::size_t at) { return static_cast<std::uint16_t>(b[at] | b[at + 1] << 8); };
    const std::size_t ifd = b[4] | b[5] << 8 | b[6] << 16 | std::size_t{b[7]} << 24;
    for (std::size_t i = 0, n = u16(ifd); i < n; ++i)
        if (u16(ifd + 2 + 12 * i) == tag) return ifd + 2 + 12 * i;
    throw std::runtime_error("no tag " + std::to_string(tag));
}

std::vector<std::uint8_t> bytesOf(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

// The first strip's offset, through libtiff.
std::size_t firstStrip(const fs::path& p) {
    TIFF* t = TIFFOpen(p.string().c_str(), "r");
    const std::uint64_t offset = TIFFGetStrileOffset(t, 0);
    TIFFClose(t);
    return static_cast<std::size_t>(offset);
}

// libtiff warns and goes on where strip data are corrupt ("Discarding N bytes to avoid buffer
// overrun" in a PackBits run): that was a success with the values libtiff made up, ±3.4e38 in
// a float page. Now the file is refused, naming it and saying why.
TEST(TiffReader, WarningsAboutPixelDataAreErrors) {
    const fs::path dir = fm::test::scratchDir("tiff_data_warnings");
    TiffSpec s;
    s.compression = 32773, s.width = 7, s.height = 5, s.rowsPerStrip = 2;
    fm::test::writeTestTiff(dir / "packbits.tif", s);
    auto b = bytesOf(dir / "packbits.tif");
    b[firstStrip(dir / "packbits.tif")] = 0x7F;  // a literal run of 128 bytes in a 7-byte row
    writeBytes(dir / "run.tif", b);
    std::string e = tiffErrorOf(dir / "run.tif");
    EXPECT_NE(e.find("run.tif"), std::string::npos) << e;
    EXPECT_NE(e.find("corrupt image data"), std::string::npos) << e;
    EXPECT_NE(e.find("PackBitsDecode"), std::string::npos) << e;
    // A float radiograph, the same damage.
    {
        TIFF* t = TIFFOpen((dir / "float.tif").string().c_str(), "wl");
        TIFFSetField(t, TIFFTAG_IMAGEWIDTH, 2);
        TIFFSetField(t, TIFFTAG_IMAGELENGTH, 8);
        TIFFSetField(t, TIFFTAG_BITSPERSAMPLE, 32);
        TIFFSetField(t, TIFFTAG_SAMPLEFORMAT, SAMPLEFORMAT_IEEEFP);
        TIFFSetField(t, TIFFTAG_SAMPLESPERPIXEL, 1);
        TIFFSetField(t, TIFFTAG_PHOTOMETRIC, PHOTOMETRIC_MINISBLACK);
        TIFFSetField(t, TIFFTAG_COMPRESSION, COMPRESSION_PACKBITS);
        TIFFSetField(t, TIFFTAG_ROWSPERSTRIP, 8);
        std::vector<float> row(2);
        for (std::uint32_t y = 0; y < 8; ++y) {
            for (int x = 0; x < 2; ++x) row[x] = 0.25f * x + float(y);
            TIFFWriteScanline(t, row.data(), y, 0);
        }
        TIFFClose(t);
    }
    ASSERT_EQ(fm::readRadiograph(dir / "float.tif").image.at(1, 2), 2.25f);
    b = bytesOf(dir / "float.tif");
    b[firstStrip(dir / "float.tif")] = 0x7F;
    writeBytes(dir / "float_run.tif", b);
    try {
        fm::readRadiograph(dir / "float_run.tif");
        ADD_FAILURE() << "a float TIFF with a corrupt strip was read";
    } catch (const fm::Error& error) {
        EXPECT_NE(std::string(error.what()).find("float_run.tif: page 1: corrupt image data"), std::string::npos) << error.what();
    }
    // A directory warning about a tag that lays pixels out: a wrong count for "Predictor"
    // made libtiff drop the predictor and return differences as values.
    TiffSpec p;
    p.bits = 16, p.compression = 5, p.predictor = 2, p.width = 37, p.height = 21;
    fm::test::writeTestTiff(dir / "predictor.tif", p);
    b = bytesOf(dir / "predictor.tif");
    b[ifdEntry(b, 317) + 4] = 2;  // count 2
    writeBytes(dir / "predictor_count.tif", b);
    e = tiffErrorOf(dir / "predictor_count.tif");
    EXPECT_NE(e.find("corrupt directory"), std::string::npos) << e;
    EXPECT_NE(e.find("Predictor"), std::string::npos) << e;
}

// Warnings that change no pixel (an unknown tag, a directory out of order) stay warnings.
TEST(TiffReader, BenignWarningsAreKept) {
    const fs::path dir = fm::test::scratchDir("tiff_benign_warnings");
    TiffSpec s;
    s.compression = 5;
    fm::test::writeTestTiff(dir / "t.tif", s);
    auto b = bytesOf(dir / "t.tif");
    const std::size_t planar = ifdEntry(b, 284);  // PlanarConfiguration: contiguous is the default
    b[planar] = 0xE8, b[planar + 1] = 0xFD;       // tag 65000: unknown, and out of order
    writeBytes(dir / "unknown.tif", b);
    const fm::io::TiffContent c = fm::io::readTiff(dir / "unknown.tif");
    ASSERT_FALSE(c.warnings.empty());
    EXPECT_NE(c.warnings[0].find("65000"), std::string::npos) << c.warnings[0];
    EXPECT_EQ(c.pages[0].values[3 * 7 + 5], float(fm::test::tiffPattern(5, 3, 0, 8)));
    // The volume reader keeps them in the description.
    const fm::Volume v = fm::loadVolume((dir / "unknown.tif").string() + "?spacing=1,1,1");
    EXPECT_NE(v.meta.description.find("libtiff warning"), std::string::npos) << v.meta.description;
}

// TIFF bone volumes dropped libtiff's warnings: a corrupt strip in a stack is refused too.
TEST(TiffVolume, CorruptStripsAreRefused) {
    const fs::path dir = fm::test::scratchDir("tiff_volume_corrupt");
    TiffSpec s;
    s.bits = 16, s.pages = 3, s.compression = 32773, s.rowsPerStrip = 5;
    fm::test::writeTestTiff(dir / "stack.tif", s);
    auto b = bytesOf(dir / "stack.tif");
    b[firstStrip(dir / "stack.tif")] = 0x7F;
    writeBytes(dir / "bad.tif", b);
    try {
        fm::loadVolume((dir / "bad.tif").string() + "?spacing=0.5,0.5,1");
        ADD_FAILURE() << "a stack with a corrupt strip was read";
    } catch (const fm::Error& e) {
        EXPECT_NE(std::string(e.what()).find("corrupt image data"), std::string::npos) << e.what();
    }
}

}  // namespace

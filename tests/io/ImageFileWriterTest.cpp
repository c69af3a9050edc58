// Images written in the format the name asks for, decoded by independent readers: libtiff for
// TIFF (8-bit and float32), stb_image for JPEG and PNG, our MetaImage reader for .mha.
#include <gtest/gtest.h>

#include <stb/stb_image.h>
#include <tiffio.h>

#include <cmath>
#include <fstream>

#include "common/TestData.h"
#include "core/Error.h"
#include "io/ImageFileWriter.h"
#include "io/ReadVolume.h"

namespace {

namespace fs = std::filesystem;

// A 7 x 5 ramp with distinct float values, negative and fractional ones among them.
fm::Image ramp() {
    fm::Image image(7, 5);
    for (int r = 0; r < 5; ++r)
        for (int c = 0; c < 7; ++c) image.at(c, r) = -1.5f + 0.37f * c + 1.1f * r;
    image.spacing = {0.5, 0.25};
    return image;
}

std::vector<unsigned char> fileBytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(ImageFileWriter, FormatByExtension) {
    using F = fm::ImageFileFormat;
    EXPECT_EQ(fm::imageFileFormat("a/b.PNG", "--out"), F::Png);
    EXPECT_EQ(fm::imageFileFormat("x.jpg", "--out"), F::Jpeg);
    EXPECT_EQ(fm::imageFileFormat("x.jpeg", "--out"), F::Jpeg);
    EXPECT_EQ(fm::imageFileFormat("x.tif", "--out"), F::Tiff);
    EXPECT_EQ(fm::imageFileFormat("x.TIFF", "--out"), F::Tiff);
    EXPECT_EQ(fm::imageFileFormat("x.mha", "--out"), F::Volume);
    EXPECT_EQ(fm::imageFileFormat("x.nii.gz", "--out"), F::Volume);
    EXPECT_EQ(fm::imageFileFormat("/dev/null", "--out"), F::Png) << "written through";
    try {
        fm::imageFileFormat("shot.bmp", "--out");
        FAIL() << "a .bmp was accepted";
    } catch (const fm::Error& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("--out"), std::string::npos) << m;
        EXPECT_NE(m.find("shot.bmp"), std::string::npos) << m;
    }
    EXPECT_THROW(fm::imageFileFormat("noextension", "--out"), fm::Error);
    EXPECT_THROW(fm::checkExactImagePath("x.png"), fm::Error) << "8 bits cannot hold floats";
    EXPECT_THROW(fm::checkExactImagePath("x.jpg"), fm::Error);
    EXPECT_NO_THROW(fm::checkExactImagePath("x.tif"));
}

TEST(ImageFileWriter, Tiff8BitDecodesWithLibtiff) {
    const fs::path path = fm::test::scratchDir("image-writer-tiff8") / "grey.tif";
    const fm::Image image = ramp();
    fm::writeViewImage(image, path, -1.5f, 5.0f);
    const std::vector<std::uint8_t> expected = fm::windowToGrey8(image, -1.5f, 5.0f);
    TIFF* tif = TIFFOpen(path.c_str(), "r");
    ASSERT_NE(tif, nullptr);
    std::uint32_t w = 0, h = 0;
    std::uint16_t bits = 0, samples = 0, format = 0;
    TIFFGetField(tif, TIFFTAG_IMAGEWIDTH, &w);
    TIFFGetField(tif, TIFFTAG_IMAGELENGTH, &h);
    TIFFGetField(tif, TIFFTAG_BITSPERSAMPLE, &bits);
    TIFFGetField(tif, TIFFTAG_SAMPLESPERPIXEL, &samples);
    TIFFGetFieldDefaulted(tif, TIFFTAG_SAMPLEFORMAT, &format);
    EXPECT_EQ(w, 7u);
    EXPECT_EQ(h, 5u);
    EXPECT_EQ(bits, 8);
    EXPECT_EQ(samples, 1);
    EXPECT_EQ(format, SAMPLEFORMAT_UINT);
    std::vector<std::uint8_t> row(TIFFScanlineSize(tif));
    for (std::uint32_t r = 0; r < h; ++r) {
        ASSERT_EQ(TIFFReadScanline(tif, row.data(), r), 1);
        for (std::uint32_t c = 0; c < w; ++c) EXPECT_EQ(row[c], expected[r * w + c]) << r << "," << c;
    }
    TIFFClose(tif);
    // The grey levels are the window's: the first pixel is the window's low end.
    EXPECT_EQ(expected[0], 0);
}

TEST(ImageFileWriter, TiffFloatHoldsTheExactValues) {
    const fs::path path = fm::test::scratchDir("image-writer-tiff32") / "exact.tif";
    const fm::Image image = ramp();
    fm::writeExactImage(image, path);
    TIFF* tif = TIFFOpen(path.c_str(), "r");
    ASSERT_NE(tif, nullptr);
    std::uint16_t bits = 0, format = 0;
    TIFFGetField(tif, TIFFTAG_BITSPERSAMPLE, &bits);
    TIFFGetField(tif, TIFFTAG_SAMPLEFORMAT, &format);
    EXPECT_EQ(bits, 32);
    EXPECT_EQ(format, SAMPLEFORMAT_IEEEFP);
    std::vector<float> row(7);
    ASSERT_EQ(TIFFScanlineSize(tif), 28);
    for (int r = 0; r < 5; ++r) {
        ASSERT_EQ(TIFFReadScanline(tif, row.data(), r), 1);
        for (int c = 0; c < 7; ++c) EXPECT_EQ(row[c], image.at(c, r));
    }
    TIFFClose(tif);
}

TEST(ImageFileWriter, JpegIsAJpegWithTheImage) {
    const fs::path path = fm::test::scratchDir("image-writer-jpeg") / "view.jpg";
    // A smooth 64 x 64 ramp: baseline JPEG at quality 95 keeps it within a few grey levels.
    fm::Image image(64, 64);
    for (int r = 0; r < 64; ++r)
        for (int c = 0; c < 64; ++c) image.at(c, r) = float(c + r);
    fm::writeViewImage(image, path, 0.0f, 126.0f);
    const auto bytes = fileBytes(path);
    ASSERT_GE(bytes.size(), 4u);
    EXPECT_EQ(bytes[0], 0xFF);
    EXPECT_EQ(bytes[1], 0xD8) << "JPEG start-of-image marker, not PNG bytes";
    int w = 0, h = 0, n = 0;
    unsigned char* grey = stbi_load_from_memory(bytes.data(), int(bytes.size()), &w, &h, &n, 1);
    ASSERT_NE(grey, nullptr);
    EXPECT_EQ(w, 64);
    EXPECT_EQ(h, 64);
    const std::vector<std::uint8_t> expected = fm::windowToGrey8(image, 0.0f, 126.0f);
    double worst = 0.0;
    for (int k = 0; k < 64 * 64; ++k) worst = std::max(worst, std::abs(double(grey[k]) - expected[k]));
    stbi_image_free(grey);
    EXPECT_LE(worst, 6.0) << "lossy, but the same picture";
}

TEST(ImageFileWriter, PngAndVolumeFormats) {
    const fs::path dir = fm::test::scratchDir("image-writer-formats");
    const fm::Image image = ramp();
    fm::writeViewImage(image, dir / "view.png", -1.5f, 5.0f);
    const auto png = fileBytes(dir / "view.png");
    ASSERT_GE(png.size(), 8u);
    EXPECT_EQ(png[1], 'P');
    EXPECT_EQ(png[2], 'N');
    EXPECT_EQ(png[3], 'G');
    // .mha through --out: the exact values, not a windowed copy.
    fm::writeViewImage(image, dir / "view.mha", -1.5f, 5.0f);
    const fm::Volume back = fm::readVolume(dir / "view.mha");
    ASSERT_EQ(back.values.size(), image.pixels.size());
    for (std::size_t k = 0; k < image.pixels.size(); ++k) EXPECT_EQ(back.values[k], image.pixels[k]);
    EXPECT_THROW(fm::writeExactImage(image, dir / "x.png"), fm::Error);
}

}  // namespace

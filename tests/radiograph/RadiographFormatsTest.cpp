// readRadiograph by extension: BMP through stb after the size check (stb read missing bytes as
// zeros), JPEG and PNG through their readers, anything else refused by name.
#include <gtest/gtest.h>

#include <stb/stb_image_write.h>

#include "ImageTestFiles.h"
#include "common/TestData.h"
#include "core/Error.h"
#include "io/GreyImage.h"
#include "radiograph/Radiograph.h"

namespace {

namespace fs = std::filesystem;

std::string formatErrorOf(const fs::path& p) {
    try {
        fm::readRadiograph(p);
    } catch (const fm::Error& e) {
        return e.what();
    }
    return "";
}

TEST(RadiographFormats, BmpIsReadAsGreyAndRefusedWhenShort) {
    const fs::path dir = fm::test::scratchDir("radiograph_bmp");
    const int w = 11, h = 6;
    std::vector<std::uint8_t> rgb(std::size_t(w) * h * 3);
    for (std::size_t i = 0; i < rgb.size(); ++i) rgb[i] = static_cast<std::uint8_t>(i * 29 % 256);
    ASSERT_TRUE(stbi_write_bmp((dir / "c.bmp").string().c_str(), w, h, 3, rgb.data()));
    const fm::RadiographFile r = fm::readRadiograph(dir / "c.bmp");
    EXPECT_EQ(r.format, "BMP");
    EXPECT_EQ(r.bitsPerSample, 8);
    ASSERT_EQ(r.image.width, w);
    ASSERT_EQ(r.image.height, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::uint8_t* p = &rgb[(std::size_t(y) * w + x) * 3];
            ASSERT_EQ(r.image.at(x, y), float(fm::io::greyOfRgb(p[0], p[1], p[2])))
                << x << "," << y;
        }
    // Cut short: stb returned the missing rows as black.
    fm::test::Bytes b = fm::test::readBytes(dir / "c.bmp");
    b.resize(b.size() - 40);
    fm::test::writeBytes(dir / "short.bmp", b);
    const std::string e = formatErrorOf(dir / "short.bmp");
    EXPECT_NE(e.find("'" + (dir / "short.bmp").string() + "': truncated BMP"), std::string::npos)
        << e;
    // A header claiming 40000 columns.
    b = fm::test::readBytes(dir / "c.bmp");
    b[18] = 0x40, b[19] = 0x9C;
    fm::test::writeBytes(dir / "wide.bmp", b);
    EXPECT_NE(formatErrorOf(dir / "wide.bmp").find("outside 1..32768"), std::string::npos)
        << formatErrorOf(dir / "wide.bmp");
    fm::test::writeBytes(dir / "text.bmp", {'h', 'i'});
    EXPECT_NE(formatErrorOf(dir / "text.bmp").find("not a BMP file"), std::string::npos);
}

TEST(RadiographFormats, ExtensionsChooseTheReader) {
    const fs::path dir = fm::test::scratchDir("radiograph_formats");
    fm::test::PngSpec s;
    fm::test::writeTestPng(dir / "upper.PNG", s,
                           std::vector<std::uint32_t>(std::size_t(s.width) * s.height, 77));
    EXPECT_EQ(fm::readRadiograph(dir / "upper.PNG").image.at(2, 2), 77.0f);
    fm::test::JpegSpec j;
    fm::test::writeBytes(dir / "f.jpeg",
                         fm::test::encodeTestJpeg(
                             j, std::vector<std::uint8_t>(std::size_t(j.width) * j.height, 200)));
    EXPECT_NEAR(fm::readRadiograph(dir / "f.jpeg").image.at(5, 5), 200.0f, 1.0f);
    // A PNG's bytes under a JPEG's name: the JPEG reader says it is not one.
    fs::copy_file(dir / "upper.PNG", dir / "png.jpg");
    EXPECT_NE(formatErrorOf(dir / "png.jpg").find("png.jpg'"), std::string::npos)
        << formatErrorOf(dir / "png.jpg");
    // stb read anything it could sniff; now other formats are refused by name.
    fs::copy_file(dir / "upper.PNG", dir / "x.gif");
    EXPECT_NE(formatErrorOf(dir / "x.gif").find("unknown radiograph format '.gif'"), std::string::npos)
        << formatErrorOf(dir / "x.gif");
}


// A folder or a device given as a radiograph is named as such in every format, not "no such
// file" (the TIFF reader said that) and never read (a device would be read for ever).
TEST(RadiographFormats, AFolderOrADeviceIsNamedAsSuch) {
    const fs::path dir = fm::test::scratchDir("radiograph_not_files");
    for (const char* extension : {".tif", ".png", ".jpg", ".bmp"}) {
        const fs::path folder = dir / (std::string("folder") + extension);
        fs::create_directories(folder);
        std::string e = formatErrorOf(folder);
        EXPECT_NE(e.find("is a folder, not a file"), std::string::npos) << extension << ": " << e;
        EXPECT_NE(e.find(folder.filename().string()), std::string::npos) << e;
        const fs::path device = dir / (std::string("device") + extension);
        fs::remove(device);
        fs::create_symlink("/dev/zero", device);
        e = formatErrorOf(device);
        EXPECT_NE(e.find("not a regular file"), std::string::npos) << extension << ": " << e;
        EXPECT_EQ(e.find("no such file"), std::string::npos) << e;
        e = formatErrorOf(dir / (std::string("missing") + extension));
        EXPECT_NE(e.find("not found"), std::string::npos) << extension << ": " << e;
    }
}

}  // namespace

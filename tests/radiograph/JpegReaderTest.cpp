// The JPEG reader (libjpeg-turbo) on files written by libjpeg's encoder: grey and colour,
// baseline and progressive, against stb_image's decoder; headers promising more than their
// data refused (before allocating when the file size tells, by the premature end otherwise);
// every libjpeg warning an error; nothing printed.
#include <gtest/gtest.h>

#include <stb/stb_image.h>

#include "ImageTestFiles.h"
#include "common/TestData.h"
#include "core/Error.h"
#include "io/JpegReader.h"
#include "radiograph/Radiograph.h"

namespace {

namespace fs = std::filesystem;
using fm::test::Bytes;

std::string errorOf(const fs::path& p) {
    try {
        fm::io::readJpeg(p);
    } catch (const fm::Error& e) {
        return e.what();
    }
    return "";
}

std::string errorOfBytes(const fs::path& dir, const Bytes& b, const std::string& name) {
    fm::test::writeBytes(dir / name, b);
    return errorOf(dir / name);
}

const fm::test::JpegMarker& frameHeader(const std::vector<fm::test::JpegMarker>& markers) {
    for (const auto& m : markers)
        if (m.code == 0xC0 || m.code == 0xC2) return m;
    throw std::runtime_error("no SOF");
}

// The frame header says `height` x `width` (what a lying header does).
Bytes withFrameSize(Bytes b, std::uint16_t width, std::uint16_t height) {
    // The markers are a temporary: keep the SOF's offset, not a reference into them.
    const std::size_t at = frameHeader(fm::test::jpegMarkers(b)).at;
    b[at + 5] = static_cast<std::uint8_t>(height >> 8);
    b[at + 6] = static_cast<std::uint8_t>(height);
    b[at + 7] = static_cast<std::uint8_t>(width >> 8);
    b[at + 8] = static_cast<std::uint8_t>(width);
    return b;
}

TEST(JpegReader, GreyAndColourBaselineAndProgressiveDecodeLikeStb) {
    const fs::path dir = fm::test::scratchDir("jpeg_layouts");
    int n = 0;
    for (int components : {1, 3})
        for (bool progressive : {false, true})
            for (int restart : {0, 2}) {
                fm::test::JpegSpec s;
                s.width = 61, s.height = 45, s.components = components, s.progressive = progressive,
                s.restartRows = restart;
                const Bytes jpeg = fm::test::encodeTestJpeg(
                    s, fm::test::testPicture(s.width, s.height, components));
                const fs::path p = dir / ("j" + std::to_string(n++) + ".jpg");
                fm::test::writeBytes(p, jpeg);
                const fm::RadiographFile r = fm::readRadiograph(p);
                EXPECT_EQ(r.format, "JPEG");
                EXPECT_EQ(r.bitsPerSample, 8);
                ASSERT_EQ(r.image.width, s.width);
                ASSERT_EQ(r.image.height, s.height);
                int w = 0, h = 0, c = 0;
                std::unique_ptr<stbi_uc, void (*)(void*)> stb(
                    stbi_load_from_memory(jpeg.data(), static_cast<int>(jpeg.size()), &w, &h, &c,
                                          1),
                    stbi_image_free);
                ASSERT_TRUE(stb);
                double sum = 0, worst = 0;
                for (std::size_t i = 0; i < r.image.pixels.size(); ++i) {
                    const double d = std::abs(r.image.pixels[i] - float(stb.get()[i]));
                    sum += d, worst = std::max(worst, d);
                }
                // Two decoders (IDCT, chroma upsampling) agree to a count or so, not to the bit.
                EXPECT_LT(sum / double(r.image.pixels.size()), 1.0) << p;
                EXPECT_LE(worst, 12.0) << p;
            }
}

// A header saying 16384 x 16384 over the data of 1024 x 1024 (stb accepted it: 3.9 GB): the
// file cannot hold that many blocks, refused before anything is allocated; a header within
// what the file could hold but beyond its data is refused at the data's premature end.
TEST(JpegReader, HeaderLargerThanItsDataIsRefused) {
    const fs::path dir = fm::test::scratchDir("jpeg_bombs");
    fm::test::JpegSpec s;
    s.width = 1024, s.height = 1024;
    const Bytes jpeg = fm::test::encodeTestJpeg(s, fm::test::testPicture(1024, 1024, 1));
    ASSERT_EQ(errorOfBytes(dir, jpeg, "right.jpg"), "");
    std::string e = errorOfBytes(dir, withFrameSize(jpeg, 16384, 16384), "bomb.jpg");
    EXPECT_NE(e.find("bomb.jpg'"), std::string::npos) << e;
    EXPECT_NE(e.find("cannot come from"), std::string::npos) << e;
    e = errorOfBytes(dir, withFrameSize(jpeg, 1024, 2048), "taller.jpg");
    EXPECT_NE(e.find("taller.jpg'"), std::string::npos) << e;
    EXPECT_NE(e.find("corrupt JPEG data"), std::string::npos) << e;
    e = errorOfBytes(dir, withFrameSize(jpeg, 1032, 1024), "wider.jpg");
    EXPECT_NE(e, "");
    e = errorOfBytes(dir, withFrameSize(jpeg, 1024, 1000), "shorter.jpg");  // data left over
    EXPECT_NE(e, "");
    e = errorOfBytes(dir, withFrameSize(jpeg, 40000, 8), "side.jpg");
    EXPECT_NE(e.find("outside 1..32768"), std::string::npos) << e;
}

TEST(JpegReader, TruncatedOrCorruptDataAreRefused) {
    const fs::path dir = fm::test::scratchDir("jpeg_corrupt");
    for (bool progressive : {false, true}) {
        fm::test::JpegSpec s;
        s.width = 120, s.height = 96, s.components = 3, s.progressive = progressive,
        s.restartRows = 1;
        const Bytes jpeg = fm::test::encodeTestJpeg(s, fm::test::testPicture(s.width, s.height, 3));
        ASSERT_EQ(errorOfBytes(dir, jpeg, "o.jpg"), "");
        // Cut anywhere, down to the EOI marker alone: stb filled the rest in and said nothing.
        for (std::size_t cut : {jpeg.size() / 3, jpeg.size() / 2, jpeg.size() - 40, jpeg.size() - 2,
                                jpeg.size() - 1}) {
            const std::string e = errorOfBytes(
                dir, Bytes(jpeg.begin(), jpeg.begin() + static_cast<std::ptrdiff_t>(cut)),
                "cut.jpg");
            EXPECT_NE(e.find("cut.jpg'"), std::string::npos) << cut << ": " << e;
            EXPECT_NE(e.find("JPEG"), std::string::npos) << cut << ": " << e;
        }
        EXPECT_NE(errorOfBytes(dir, Bytes(jpeg.begin(), jpeg.begin() + 300), "head.jpg")
                      .find("truncated JPEG"),
                  std::string::npos);
        // Bytes that do not belong before the EOI marker (libjpeg: "extraneous bytes"). A few
        // vanish unseen into the Huffman decoder's look-ahead (and change no pixel); 64 do not.
        Bytes b = jpeg;
        b.insert(b.end() - 2, 64, 0x5A);
        const std::string extra = errorOfBytes(dir, b, "extra.jpg");
        EXPECT_NE(extra.find("corrupt JPEG data"), std::string::npos) << extra;
        // A restart marker out of sequence.
        b = jpeg;
        for (const auto& m : fm::test::jpegMarkers(b))
            if (m.code == 0xD1) {
                b[m.at + 1] = 0xD5;
                break;
            }
        EXPECT_NE(errorOfBytes(dir, b, "restart.jpg"), "");
    }
    EXPECT_NE(errorOfBytes(dir, {0xFF, 0xD8, 0xFF}, "stub.jpg"), "");
    EXPECT_NE(errorOfBytes(dir, {}, "empty.jpg"), "");
    EXPECT_NE(errorOf(dir / "none.jpg").find("none.jpg"), std::string::npos);
}

TEST(JpegReader, UnsupportedCodingsAreRefusedByName) {
    const fs::path dir = fm::test::scratchDir("jpeg_arith");
    fm::test::JpegSpec s;
    s.arithmetic = true;
    const std::string e = errorOfBytes(
        dir, fm::test::encodeTestJpeg(s, fm::test::testPicture(s.width, s.height, 1)), "a.jpg");
    EXPECT_NE(e.find("arithmetic-coded"), std::string::npos) << e;
}

TEST(JpegReader, NothingIsPrinted) {
    const fs::path dir = fm::test::scratchDir("jpeg_quiet");
    const fm::test::JpegSpec s;
    const Bytes jpeg = fm::test::encodeTestJpeg(s, fm::test::testPicture(s.width, s.height, 1));
    testing::internal::CaptureStderr();
    errorOfBytes(dir, Bytes(jpeg.begin(), jpeg.end() - 30), "a.jpg");
    Bytes b = jpeg;
    b.insert(b.end() - 2, {1, 2, 3});
    errorOfBytes(dir, b, "b.jpg");
    errorOfBytes(dir, withFrameSize(jpeg, 64, 96), "c.jpg");
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
}

}  // namespace

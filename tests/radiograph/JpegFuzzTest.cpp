// Random corruption of small valid JPEGs (a real fluoroscopy crop when the shared data are
// there; grey and colour, baseline and progressive, with and without restart markers). Never
// a crash or a message on stderr, and:
//   * truncation anywhere, and changed segment lengths: refused, naming the file;
//   * a changed frame size: refused, or (a size within the same 8 x 8 or 16 x 16 blocks, so
//     the same data fit it) read with the original's pixels where both have them (up to the
//     edges, where upsampling and block smoothing look across);
//   * bit flips and byte changes anywhere: refused or read at the header's size. A JPEG holds
//     no checksum: a flipped bit in a quantization table or in a coefficient's magnitude
//     decodes to other pixels that no decoder can tell from the original. Such files are
//     counted and shown (the headers' structural bytes and the Huffman codes catch most).
#include <gtest/gtest.h>

#include <iostream>
#include <random>

#include "ImageTestFiles.h"
#include "common/TestData.h"
#include "core/Error.h"
#include "io/JpegReader.h"

namespace {

namespace fs = std::filesystem;
using fm::test::Bytes;
constexpr int kCases = 150;  // x 4 files
constexpr unsigned kSeed = 20261208u;

enum Kind { Cut, SegmentLength, FrameSize, HeaderFlip, DataFlip, DataBytes, kKinds };
const char* const kKindNames[kKinds] = {"truncation",       "segment length", "frame size",
                                        "header bit flips", "data bit flips", "data byte changes"};

// The same pixels as `original` where both have them, up to 16 pixels from the nearer right
// and bottom edges (colour upsampling and progressive block smoothing look across an edge,
// which moved).
bool samePixelsInside(const fm::Image& image, const fm::Image& original) {
    const int w = std::min(image.width, original.width) - 16,
              h = std::min(image.height, original.height) - 16;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            if (image.at(x, y) != original.at(x, y)) return false;
    return true;
}

TEST(JpegFuzz, DamagedFilesAreRefusedOrReadAtTheirSize) {
    const fs::path dir = fm::test::scratchDir("jpeg_fuzz");
    std::mt19937 rng(kSeed);
    auto pick = [&](std::size_t n) {
        return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng);
    };
    fm::test::JpegSpec specs[4];
    specs[0].width = 64, specs[0].height = 48;
    specs[1].width = 50, specs[1].height = 34, specs[1].components = 3, specs[1].progressive = true;
    specs[2].width = 40, specs[2].height = 40, specs[2].restartRows = 1;
    specs[3].width = 45, specs[3].height = 30, specs[3].components = 3, specs[3].restartRows = 2;
    int refused[kKinds] = {}, identical[kKinds] = {}, other[kKinds] = {};
    testing::internal::CaptureStderr();
    for (int s = 0; s < 4; ++s) {
        const fm::test::JpegSpec& spec = specs[s];
        const Bytes bytes = fm::test::encodeTestJpeg(
            spec, fm::test::testPicture(spec.width, spec.height, spec.components));
        fm::test::writeBytes(dir / "o.jpg", bytes);
        const fm::io::GreyImage reference = fm::io::readJpeg(dir / "o.jpg");
        const auto markers = fm::test::jpegMarkers(bytes);
        std::vector<fm::test::JpegMarker> segments;  // markers with a length field
        std::size_t frame = 0, dataStart = 0;
        for (const auto& m : markers) {
            if (m.length) segments.push_back(m);
            if (m.code == 0xC0 || m.code == 0xC2) frame = m.at;
            if (m.code == 0xDA && !dataStart) dataStart = m.at + 2 + m.length;
        }
        ASSERT_GT(frame, 0u);
        ASSERT_GT(dataStart, frame);
        for (int c = 0; c < kCases; ++c) {
            Bytes b = bytes;
            const Kind kind = static_cast<Kind>(c % kKinds);
            switch (kind) {
                case Cut:
                    b.resize(pick(b.size()));
                    break;
                case SegmentLength: {
                    const fm::test::JpegMarker& m = segments[pick(segments.size())];
                    const std::size_t length =
                        pick(2) ? m.length + 1 + pick(20)
                                : m.length - 1 - pick(std::min<std::size_t>(m.length - 1, 20));
                    b[m.at + 2] = static_cast<std::uint8_t>(length >> 8),
                             b[m.at + 3] = static_cast<std::uint8_t>(length);
                    break;
                }
                case FrameSize: {
                    const std::size_t field = frame + 5 + (pick(2) ? 0 : 2);  // height or width
                    const int now = b[field] << 8 | b[field + 1];
                    const int changed = pick(3) ? std::max(1, now + static_cast<int>(pick(33)) - 16)
                                                : static_cast<int>(pick(65536));
                    b[field] = static_cast<std::uint8_t>(changed >> 8),
                    b[field + 1] = static_cast<std::uint8_t>(changed);
                    break;
                }
                case HeaderFlip:
                    b[pick(dataStart)] ^= static_cast<std::uint8_t>(1u << pick(8));
                    break;
                case DataFlip:
                    b[dataStart + pick(b.size() - 2 - dataStart)] ^=
                        static_cast<std::uint8_t>(1u << pick(8));
                    break;
                default:
                    for (std::size_t f = 0, n = 1 + pick(4); f < n; ++f)
                        b[dataStart + pick(b.size() - 2 - dataStart)] =
                            static_cast<std::uint8_t>(pick(256));
            }
            const fs::path p = dir / "m.jpg";
            fm::test::writeBytes(p, b);
            try {
                const fm::io::GreyImage g = fm::io::readJpeg(p);
                ASSERT_EQ(g.image.pixels.size(), std::size_t(g.image.width) * g.image.height);
                ASSERT_NE(kind, Cut) << "a truncated JPEG was read: file " << s << ", case " << c;
                ASSERT_NE(kind, SegmentLength)
                    << "a JPEG with a wrong segment length was read: file " << s << ", case " << c;
                if (g.image.width == reference.image.width &&
                    g.image.height == reference.image.height &&
                    g.image.pixels == reference.image.pixels) {
                    ++identical[kind];
                } else {
                    ASSERT_TRUE(kind != FrameSize || samePixelsInside(g.image, reference.image))
                        << "a resized frame read as other pixels: file " << s << ", case " << c
                        << ", " << g.image.width << " x " << g.image.height;
                    ++other[kind];
                }
            } catch (const fm::Error& e) {
                ASSERT_NE(std::string(e.what()).find("m.jpg'"), std::string::npos) << e.what();
                ++refused[kind];
            } catch (const std::exception& e) {
                FAIL() << "case " << c << ": non-fm exception " << e.what();
            }
        }
    }
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
    for (int k = 0; k < kKinds; ++k) {
        std::cout << "[ fuzz     ] jpeg " << kKindNames[k] << ": " << refused[k] << " refused, "
                  << identical[k] << " identical, " << other[k]
                  << (k == FrameSize ? " read at their size, same pixels inside"
                                     : " read as other pixels")
                  << "\n";
        EXPECT_GT(refused[k], 0) << kKindNames[k];
    }
}

}  // namespace

// Random corruption of small valid PNGs (a real fluoroscopy crop when the shared data are
// there; grey, 16-bit interlaced, palette, RGBA): bit flips, byte changes, truncation, chunk
// length changes, anywhere in the file; and, with the damaged chunk's CRC made to match,
// changes to the compressed data and to the header's size. Never a crash or a message on
// stderr; every damaged file is refused with an fm::Error naming it, or gives exactly the
// original's pixels: no garbage accepted. (A header whose CRC was made to match is a valid
// PNG of another size: it may be read, at its size.)
#include <gtest/gtest.h>

#include <iostream>
#include <random>

#include "ImageTestFiles.h"
#include "common/TestData.h"
#include "core/Error.h"
#include "io/PngReader.h"

namespace {

namespace fs = std::filesystem;
using fm::test::Bytes;
constexpr int kPngCases = 250;  // x 4 files: 1000 cases, well under a second
constexpr unsigned kPngSeed = 20261207u;

enum PngKind { PngFlip, PngBytes, PngCut, PngLength, PngCompressedData, PngHeaderSize, kPngKinds };
const char* const kPngKindNames[kPngKinds] = {
    "bit flips",    "byte changes",          "truncation",
    "chunk length", "IDAT data (CRC fixed)", "IHDR size (CRC fixed)"};

TEST(PngFuzz, DamagedFilesAreRefusedOrIdentical) {
    const fs::path dir = fm::test::scratchDir("png_fuzz");
    std::mt19937 rng(kPngSeed);
    auto pick = [&](std::size_t n) {
        return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng);
    };
    fm::test::PngSpec specs[4];
    specs[0].width = 48, specs[0].height = 40, specs[0].text = true;
    specs[1].width = 30, specs[1].height = 20, specs[1].bitDepth = 16, specs[1].interlaced = true;
    specs[2].width = 25, specs[2].height = 17, specs[2].palette = true;
    specs[3].width = 20, specs[3].height = 16, specs[3].channels = 4, specs[3].text = true;
    int refused[kPngKinds] = {}, identical[kPngKinds] = {}, resized = 0;
    testing::internal::CaptureStderr();
    for (int s = 0; s < 4; ++s) {
        const fm::test::PngSpec& spec = specs[s];
        const int channels = spec.palette ? 1 : spec.channels;
        const auto picture = fm::test::testPicture(spec.width, spec.height, channels);
        std::vector<std::uint32_t> samples(picture.begin(), picture.end());
        if (spec.bitDepth == 16)
            for (auto& v : samples) v = v * 257 + (v % 7);
        const fs::path original = dir / ("o" + std::to_string(s) + ".png");
        fm::test::writeTestPng(original, spec, samples);
        const fm::io::GreyImage reference = fm::io::readPng(original);
        const Bytes bytes = fm::test::readBytes(original);
        const auto chunks = fm::test::pngChunks(bytes);
        for (int c = 0; c < kPngCases; ++c) {
            Bytes b = bytes;
            const PngKind kind = static_cast<PngKind>(c % kPngKinds);
            const fm::test::PngChunk& chunk = chunks[pick(chunks.size())];
            switch (kind) {
                case PngFlip:
                    for (std::size_t f = 0, n = 1 + pick(3); f < n; ++f)
                        b[pick(b.size())] ^= static_cast<std::uint8_t>(1u << pick(8));
                    break;
                case PngBytes:
                    for (std::size_t f = 0, n = 1 + pick(6); f < n; ++f)
                        b[8 + pick(b.size() - 8)] = static_cast<std::uint8_t>(pick(256));
                    break;
                case PngCut:
                    b.resize(pick(b.size()));
                    break;
                case PngLength: {
                    const std::uint32_t length =
                        chunk.length +
                        static_cast<std::uint32_t>(
                            pick(2) ? 1 + pick(40)
                                    : -1 - static_cast<int>(
                                               pick(std::min<std::size_t>(40, chunk.length + 1))));
                    for (int i = 0; i < 4; ++i)
                        b[chunk.at + i] = static_cast<std::uint8_t>(length >> (24 - 8 * i));
                    break;
                }
                case PngCompressedData: {
                    const fm::test::PngChunk* idat = nullptr;
                    for (const auto& k : chunks)
                        if (k.type == "IDAT") idat = &k;
                    b[idat->at + 8 + pick(idat->length)] ^=
                        static_cast<std::uint8_t>(1u << pick(8));
                    fm::test::fixPngCrc(b, *idat);
                    break;
                }
                default: {  // width or height, CRC fixed
                    const std::size_t field = chunks[0].at + 8 + (pick(2) ? 0 : 4) + 2 + pick(2);
                    b[field] =
                        static_cast<std::uint8_t>(pick(2) ? b[field] + 1 + pick(3) : pick(256));
                    fm::test::fixPngCrc(b, chunks[0]);
                }
            }
            const fs::path p = dir / "m.png";
            fm::test::writeBytes(p, b);
            try {
                const fm::io::GreyImage g = fm::io::readPng(p);
                if (kind == PngHeaderSize && (g.image.width != reference.image.width ||
                                           g.image.height != reference.image.height)) {
                    ASSERT_EQ(g.image.pixels.size(), std::size_t(g.image.width) * g.image.height);
                    ++resized;
                    continue;
                }
                ASSERT_EQ(g.image.width, reference.image.width)
                    << kPngKindNames[kind] << ", file " << s << ", case " << c;
                ASSERT_EQ(g.image.height, reference.image.height);
                ASSERT_TRUE(g.image.pixels == reference.image.pixels)
                    << "garbage accepted: " << kPngKindNames[kind] << ", file " << s << ", case " << c;
                ++identical[kind];
            } catch (const fm::Error& e) {
                ASSERT_NE(std::string(e.what()).find("m.png'"), std::string::npos) << e.what();
                ++refused[kind];
            } catch (const std::exception& e) {
                FAIL() << "case " << c << ": non-fm exception " << e.what();
            }
        }
    }
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
    for (int k = 0; k < kPngKinds; ++k) {
        std::cout << "[ fuzz     ] png " << kPngKindNames[k] << ": " << refused[k] << " refused, "
                  << identical[k] << " identical"
                  << (k == PngHeaderSize ? ", " + std::to_string(resized) + " read at their new size"
                                      : "")
                  << "\n";
        EXPECT_GT(refused[k], 0) << kPngKindNames[k];
    }
    EXPECT_EQ(identical[PngCut], 0);
}

}  // namespace

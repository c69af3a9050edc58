// Random corruption of small valid TIFFs (strips and tiles; none, LZW, PackBits; 8 and 16 bit):
// the reader returns pages of the stated size or throws fm::Error. Never a crash, a hang, a
// sanitizer report, another exception, or a message from libtiff on stderr.
#include <gtest/gtest.h>

#include <fstream>
#include <iostream>
#include <random>

#include "TiffTestFiles.h"
#include "common/TestData.h"
#include "core/Error.h"
#include "io/TiffReader.h"

namespace {

namespace fs = std::filesystem;
constexpr int kCases = 150;  // x 4 files; the time is file I/O
constexpr unsigned kSeed = 20261201u;

std::vector<std::uint8_t> readAll(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

TEST(TiffFuzz, CorruptFilesAreReadOrRefused) {
    const fs::path dir = fm::test::scratchDir("tiff_fuzz");
    std::mt19937 rng(kSeed);
    auto pick = [&](std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng); };
    fm::test::TiffSpec specs[4];
    specs[0].compression = 5, specs[0].width = 30, specs[0].height = 12, specs[0].rowsPerStrip = 4;
    specs[1].compression = 32773, specs[1].bits = 16, specs[1].pages = 3;
    specs[2].bits = 16, specs[2].bigEndian = true, specs[2].pages = 2;
    specs[3].compression = 5, specs[3].tiled = true, specs[3].width = 20, specs[3].height = 18;
    for (int s = 0; s < 4; ++s) {
        const fs::path original = dir / ("o" + std::to_string(s) + ".tif");
        fm::test::writeTestTiff(original, specs[s]);
        ASSERT_NO_THROW(fm::io::readTiff(original));
        const auto bytes = readAll(original);
        int loaded = 0, refused = 0;
        for (int c = 0; c < kCases; ++c) {
            auto b = bytes;
            switch (pick(3)) {
                case 0:  // header and directories are where the decisions are
                    for (std::size_t f = 0, n = 1 + pick(4); f < n; ++f) b[pick(std::min<std::size_t>(b.size(), 64))] = static_cast<std::uint8_t>(pick(256));
                    break;
                case 1:
                    for (std::size_t f = 0, n = 1 + pick(8); f < n; ++f) b[pick(b.size())] = static_cast<std::uint8_t>(pick(256));
                    break;
                default:
                    b.resize(pick(b.size()));
            }
            const fs::path p = dir / "m.tif";
            std::ofstream(p, std::ios::binary).write(reinterpret_cast<const char*>(b.data()), static_cast<std::streamsize>(b.size()));
            try {
                const fm::io::TiffContent t = fm::io::readTiff(p);
                for (const auto& page : t.pages)
                    ASSERT_EQ(page.values.size(), static_cast<std::size_t>(page.width) * page.height);
                ++loaded;
            } catch (const fm::Error&) {
                ++refused;
            } catch (const std::exception& e) {
                ADD_FAILURE() << "case " << c << ": non-fm exception " << e.what();
            }
        }
        std::cout << "[ fuzz     ] tiff " << s << ": " << loaded << " loaded, " << refused << " refused\n";
        EXPECT_GT(refused, 0);
        EXPECT_GT(loaded, 0);
    }
}

}  // namespace

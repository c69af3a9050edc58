// The structural pre-check that keeps malformed files away from GDCM's asserting parser.
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

}  // namespace
}  // namespace fm

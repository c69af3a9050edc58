// The DICOM reader on the two real series in the shared data (facts from
// /work/shared/data/README.md; per-file tags read here with GDCM directly, not through the
// reader under test).
#include <gdcmImage.h>
#include <gdcmImageReader.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "common/TestData.h"
#include "core/Error.h"
#include "io/DicomReader.h"
#include "volume/Volume.h"

namespace fm {
namespace {

// Positions and spacings are stored in the files as decimal strings with >= 6 digits.
constexpr double kGeometryToleranceMm = 1e-3;
// Integer stored values times slope 1 plus an integer intercept are exact in float.
constexpr double kExactValueTolerance = 1e-3;

// What the reader documents for "no data" in a CT (docs/coordinates.md).
constexpr float kAirHu = -1024.0f;

// One original slice, read with GDCM directly: geometry and HU values.
struct RawSlice {
    glm::dvec3 position{0.0};
    glm::dvec3 row{0.0}, col{0.0};
    double columnSpacing = 0, rowSpacing = 0;
    int columns = 0, rows = 0;
    std::optional<double> padding;  // stored PixelPaddingValue, if any
    std::vector<float> values;      // HU, column fastest; padding pixels set to kAirHu
    float at(int c, int r) const { return values[static_cast<std::size_t>(r) * columns + c]; }
};

RawSlice readRawSlice(const std::filesystem::path& file) {
    RawSlice s;
    gdcm::ImageReader reader;
    reader.SetFileName(file.string().c_str());
    EXPECT_TRUE(reader.Read()) << file;
    const gdcm::Image& image = reader.GetImage();
    const double* origin = image.GetOrigin();
    const double* cosines = image.GetDirectionCosines();
    const double* spacing = image.GetSpacing();
    s.position = glm::dvec3(origin[0], origin[1], origin[2]);
    s.row = glm::dvec3(cosines[0], cosines[1], cosines[2]);
    s.col = glm::dvec3(cosines[3], cosines[4], cosines[5]);
    s.columnSpacing = spacing[0];
    s.rowSpacing = spacing[1];
    s.columns = static_cast<int>(image.GetDimension(0));
    s.rows = static_cast<int>(image.GetDimension(1));
    std::vector<char> buffer(image.GetBufferLength());
    EXPECT_TRUE(image.GetBuffer(buffer.data()));
    const bool isSigned = image.GetPixelFormat().GetPixelRepresentation() == 1;
    // PixelPaddingValue (0028,0120), same signedness as the pixels: "no data", read as air.
    std::optional<double> padding;
    const gdcm::DataSet& ds = reader.GetFile().GetDataSet();
    if (ds.FindDataElement(gdcm::Tag(0x0028, 0x0120))) {
        const gdcm::ByteValue* bv = ds.GetDataElement(gdcm::Tag(0x0028, 0x0120)).GetByteValue();
        if (bv && bv->GetLength() == 2) {
            std::uint16_t word;
            std::memcpy(&word, bv->GetPointer(), 2);
            padding = isSigned ? double(static_cast<std::int16_t>(word)) : double(word);
        }
    }
    s.padding = padding;
    s.values.resize(static_cast<std::size_t>(s.columns) * s.rows);
    for (std::size_t n = 0; n < s.values.size(); ++n) {
        std::uint16_t word;
        std::memcpy(&word, buffer.data() + 2 * n, 2);
        const double stored = isSigned ? double(static_cast<std::int16_t>(word)) : double(word);
        s.values[n] = padding && stored == *padding
                          ? kAirHu
                          : static_cast<float>(stored * image.GetSlope() + image.GetIntercept());
    }
    return s;
}

std::vector<std::filesystem::path> dicomFilesIn(const std::filesystem::path& folder) {
    std::vector<std::filesystem::path> files;
    for (const auto& e : std::filesystem::directory_iterator(folder))
        if (e.path().extension() == ".dcm" || e.path().filename().string().rfind("CT.", 0) == 0)
            files.push_back(e.path());
    std::sort(files.begin(), files.end());
    return files;
}

// Trilinear interpolation of the volume at a world point (NaN outside the voxel centres' hull).
double sampleVolume(const Volume& v, const glm::dvec3& world) {
    const glm::dvec3 ijk = v.worldToIndex(world);
    for (int a = 0; a < 3; ++a)
        if (ijk[a] < -1e-6 || ijk[a] > v.dims[a] - 1 + 1e-6) return std::nan("");
    const glm::dvec3 c = glm::clamp(ijk, glm::dvec3(0.0), glm::dvec3(v.dims - 1));
    const glm::ivec3 i0 = glm::min(glm::ivec3(c), glm::max(v.dims - 2, glm::ivec3(0)));
    const glm::dvec3 f = c - glm::dvec3(i0);
    double sum = 0.0;
    for (int dz = 0; dz < 2; ++dz)
        for (int dy = 0; dy < 2; ++dy)
            for (int dx = 0; dx < 2; ++dx) {
                const glm::ivec3 p = glm::min(i0 + glm::ivec3(dx, dy, dz), v.dims - 1);
                const double w = (dx ? f.x : 1 - f.x) * (dy ? f.y : 1 - f.y) * (dz ? f.z : 1 - f.z);
                if (w != 0.0) sum += w * v.at(p.x, p.y, p.z);
            }
    return sum;
}

double correlation(const std::vector<double>& a, const std::vector<double>& b) {
    const double n = double(a.size());
    double ma = 0, mb = 0;
    for (std::size_t i = 0; i < a.size(); ++i) ma += a[i] / n, mb += b[i] / n;
    double sab = 0, saa = 0, sbb = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        sab += (a[i] - ma) * (b[i] - mb);
        saa += (a[i] - ma) * (a[i] - ma);
        sbb += (b[i] - mb) * (b[i] - mb);
    }
    return sab / std::sqrt(saa * sbb);
}

// ---------------------------------------------------------------------------------------------
// TotalSegmentator example: 20 JPEG 2000 slices, empty SeriesInstanceUID, 2 mm apart.

const char* const kTotalSegDicom = "totalseg-example-ct/example_ct_dicom";

TEST(DicomRealData, TotalSegJpeg2000SeriesGeometryAndValues) {
    FM_REQUIRE_SHARED_DATA(kTotalSegDicom);
    const Volume v = readDicomSeries(test::sharedDataDir() / kTotalSegDicom);
    EXPECT_EQ(v.dims, glm::ivec3(512, 512, 20));
    EXPECT_NEAR(v.spacing.x, 0.9765625, kGeometryToleranceMm);
    EXPECT_NEAR(v.spacing.y, 0.9765625, kGeometryToleranceMm);
    EXPECT_NEAR(v.spacing.z, 2.0, kGeometryToleranceMm);
    EXPECT_EQ(orientationCode(v.direction), "LPS");  // IOP 1,0,0,0,1,0; slices ordered +z
    EXPECT_NEAR(v.origin.z, -804.5, kGeometryToleranceMm);
    EXPECT_NEAR(v.indexToWorld(glm::dvec3(0, 0, 19)).z, -766.5, kGeometryToleranceMm);
    const auto [lo, hi] = std::minmax_element(v.values.begin(), v.values.end());
    EXPECT_NEAR(*lo, -1024.0, kExactValueTolerance);  // stored 0 + intercept -1024
    EXPECT_NEAR(*hi, 1839.0, kExactValueTolerance);   // stored 2863 + intercept -1024
    EXPECT_EQ(v.meta.modality, "CT");
    EXPECT_EQ(v.meta.units, ValueUnit::HounsfieldUnits);
    EXPECT_NE(v.meta.description.find("CT Body 3.0"), std::string::npos) << v.meta.description;
    EXPECT_EQ(v.meta.description.find("resampled"), std::string::npos) << v.meta.description;
}

TEST(DicomRealData, TotalSegPlaneKIsTheSliceAtThatPosition) {
    FM_REQUIRE_SHARED_DATA(kTotalSegDicom);
    const Volume v = readDicomSeries(test::sharedDataDir() / kTotalSegDicom);
    const auto files = dicomFilesIn(test::sharedDataDir() / kTotalSegDicom);
    ASSERT_EQ(files.size(), 20u);
    for (std::size_t f : {std::size_t{0}, std::size_t{7}, std::size_t{19}}) {
        const RawSlice raw = readRawSlice(files[f]);
        const glm::dvec3 k = v.worldToIndex(raw.position);
        const int plane = static_cast<int>(std::lround(k.z));
        EXPECT_NEAR(k.x, 0.0, 1e-3);
        EXPECT_NEAR(k.y, 0.0, 1e-3);
        EXPECT_NEAR(k.z, plane, 1e-3) << files[f];
        ASSERT_GE(plane, 0);
        ASSERT_LT(plane, 20);
        int mismatches = 0;
        for (int r = 0; r < raw.rows; ++r)
            for (int c = 0; c < raw.columns; ++c)
                if (std::abs(v.at(c, r, plane) - raw.at(c, r)) > kExactValueTolerance) ++mismatches;
        EXPECT_EQ(mismatches, 0) << files[f];
    }
}

TEST(DicomRealData, TotalSegOrderDoesNotDependOnFileNames) {
    FM_REQUIRE_SHARED_DATA(kTotalSegDicom);
    const auto source = test::sharedDataDir() / kTotalSegDicom;
    const Volume reference = readDicomSeries(source);
    auto files = dicomFilesIn(source);
    // Renamed so that name order is a fixed random permutation of the original order.
    std::mt19937 random(12345);
    std::vector<int> names(files.size());
    for (std::size_t i = 0; i < names.size(); ++i) names[i] = static_cast<int>(i);
    std::shuffle(names.begin(), names.end(), random);
    const auto scratch = test::scratchDir("dicom-shuffled-totalseg");
    for (std::size_t i = 0; i < files.size(); ++i) {
        char name[32];
        std::snprintf(name, sizeof name, "img%02d", names[i]);
        std::filesystem::copy_file(files[i], scratch / name);
    }
    const Volume shuffled = readDicomSeries(scratch);
    EXPECT_EQ(shuffled.dims, reference.dims);
    EXPECT_NEAR(glm::length(shuffled.origin - reference.origin), 0.0, kGeometryToleranceMm);
    EXPECT_TRUE(shuffled.values == reference.values);
}

// ---------------------------------------------------------------------------------------------
// GE head: gantry tilt 18.5 deg, steps of 4.0 / 1.08 / 7.0 mm along the normal.

const char* const kGeTilt = "dcmqa-ct-ge-tilt";

TEST(DicomRealData, GeTiltIsResampledOntoARegularGridAlongTheNormal) {
    FM_REQUIRE_SHARED_DATA(kGeTilt);
    const auto folder = test::sharedDataDir() / kGeTilt;
    const Volume v = readDicomSeries(folder);
    v.validate("GE tilt");  // orthonormal directions, positive spacing

    // i, j keep the slices' own axes (README: IOP 1,0,0, 0,0.9483237,-0.3173047).
    const glm::dvec3 row(1, 0, 0);
    const glm::dvec3 col = glm::normalize(glm::dvec3(0, 0.9483237, -0.3173047));
    const glm::dvec3 normal = glm::cross(row, col);
    constexpr double kCosineTolerance = 1e-5;  // 7 stored digits
    EXPECT_NEAR(glm::length(v.direction[0] - row), 0.0, kCosineTolerance);
    EXPECT_NEAR(glm::length(v.direction[1] - col), 0.0, kCosineTolerance);
    EXPECT_NEAR(glm::length(v.direction[2] - normal), 0.0, kCosineTolerance);
    EXPECT_NEAR(std::acos(normal.z) * 180.0 / M_PI, 18.5, 0.05);
    EXPECT_NEAR(v.spacing.x, 0.4882812, kGeometryToleranceMm);
    EXPECT_NEAR(v.spacing.y, 0.4882812, kGeometryToleranceMm);

    // Extent along the normal = first-to-last slice distance along the normal, both from the
    // files' IPP and from the README's steps (13 x 4.0 + 1.14 * cos(18.5 deg) + 13 x 7.0).
    const auto files = dicomFilesIn(folder);
    ASSERT_EQ(files.size(), 28u);
    std::vector<double> along;
    for (const auto& f : files) along.push_back(glm::dot(readRawSlice(f).position, normal));
    const double firstToLast = *std::max_element(along.begin(), along.end()) -
                               *std::min_element(along.begin(), along.end());
    const double lengthK = (v.dims.z - 1) * v.spacing.z;
    EXPECT_NEAR(lengthK, firstToLast, kGeometryToleranceMm);
    constexpr double kReadmeRoundingMm = 0.5;  // README steps are given to 2-3 digits
    EXPECT_NEAR(lengthK, 13 * 4.0 + 1.14 * std::cos(18.5 * M_PI / 180.0) + 13 * 7.0,
                kReadmeRoundingMm);
    // The grid is finer than the smallest gap (1.08 mm along the normal), not coarser.
    EXPECT_LE(v.spacing.z, 1.09);
    EXPECT_GT(v.spacing.z, 0.48);

    // The -1500 outside the reconstruction circle is the files' PixelPaddingValue: read as air.
    EXPECT_EQ(readRawSlice(files.front()).padding, std::optional<double>(-1500.0));
    // Interpolation never leaves the range of the data (up to 2121 HU) or the air fill.
    const auto [lo, hi] = std::minmax_element(v.values.begin(), v.values.end());
    EXPECT_GE(*lo, kAirHu - 1e-3f);
    EXPECT_LE(*hi, 2121.0f + 1e-3f);
    EXPECT_EQ(v.meta.units, ValueUnit::HounsfieldUnits);
    EXPECT_NE(v.meta.description.find("resampled"), std::string::npos) << v.meta.description;
}

TEST(DicomRealData, GeTiltResampledVolumeMatchesOriginalSlicesInWorldCoordinates) {
    FM_REQUIRE_SHARED_DATA(kGeTilt);
    const auto folder = test::sharedDataDir() / kGeTilt;
    const Volume v = readDicomSeries(folder);
    const auto files = dicomFilesIn(folder);
    ASSERT_EQ(files.size(), 28u);
    const RawSlice firstSlice = readRawSlice(files.front());

    for (std::size_t f : {std::size_t{0}, std::size_t{6}, std::size_t{13}, std::size_t{14},
                          std::size_t{20}, std::size_t{27}}) {
        const RawSlice raw = readRawSlice(files[f]);
        // Every 4th pixel of the central 256 x 256 region (the head), in world coordinates.
        std::vector<double> original, resampled, sheared;
        for (int r = 128; r < 384; r += 4)
            for (int c = 128; c < 384; c += 4) {
                const glm::dvec3 world =
                    raw.position + c * raw.columnSpacing * raw.row + r * raw.rowSpacing * raw.col;
                const double value = sampleVolume(v, world);
                ASSERT_FALSE(std::isnan(value)) << files[f] << " pixel " << c << "," << r;
                original.push_back(raw.at(c, r));
                resampled.push_back(value);
                // Where a reader that stacked slices without their in-plane shift would put
                // this pixel: same (c, r) as in slice 0's lattice, at this slice's depth.
                const glm::dvec3 unshifted =
                    firstSlice.position + c * raw.columnSpacing * raw.row +
                    r * raw.rowSpacing * raw.col +
                    glm::dot(raw.position - firstSlice.position, v.direction[2]) * v.direction[2];
                const double wrong = sampleVolume(v, unshifted);
                sheared.push_back(std::isnan(wrong) ? -1024.0 : wrong);
            }
        std::vector<double> absDiff;
        for (std::size_t n = 0; n < original.size(); ++n)
            absDiff.push_back(std::abs(original[n] - resampled[n]));
        std::nth_element(absDiff.begin(), absDiff.begin() + absDiff.size() / 2, absDiff.end());
        const double medianAbsDiff = absDiff[absDiff.size() / 2];
        const double match = correlation(original, resampled);
        const double shearMatch = correlation(original, sheared);
        // A slice's plane generally falls between two output planes, so sampling the volume
        // there interpolates twice (slices -> planes -> point): 4-7 mm through-plane blur in a
        // skull gives median differences of tens of HU. A shear by the tilt's offset (up to
        // 48 mm) drops the correlation to about zero instead.
        constexpr double kMinCorrelation = 0.99;
        constexpr double kMaxMedianHu = 30.0;
        EXPECT_GT(match, kMinCorrelation) << files[f];
        EXPECT_LT(medianAbsDiff, kMaxMedianHu) << files[f];
        if (f > 0) {
            EXPECT_LT(shearMatch, match - 0.5) << files[f];  // a shear would be caught
        }
    }
    // First slice: on output plane 0 and on the output lattice, so reproduced exactly (up to
    // the test's world points using the file's 7-digit cosines where the volume uses the
    // orthonormalised ones: ~1e-6 pixel offsets times gradients up to ~1000 HU per pixel).
    constexpr double kCosineRoundingHu = 0.05;
    for (int r = 100; r < 400; r += 37)
        for (int c = 100; c < 400; c += 41) {
            const glm::dvec3 world = firstSlice.position +
                                     c * firstSlice.columnSpacing * firstSlice.row +
                                     r * firstSlice.rowSpacing * firstSlice.col;
            EXPECT_NEAR(sampleVolume(v, world), firstSlice.at(c, r), kCosineRoundingHu);
        }
}

// Bilinear value of a raw slice at a world point projected along the slice normal, or NaN
// beyond its pixels' boxes (the edge pixel's value within the outer half pixel).
double bilinearOnSlice(const RawSlice& s, const glm::dvec3& world) {
    const glm::dvec3 d = world - s.position;
    double u = glm::dot(d, glm::normalize(s.row)) / s.columnSpacing;
    double w = glm::dot(d, glm::normalize(s.col)) / s.rowSpacing;
    if (u < -0.5 || u > s.columns - 0.5 || w < -0.5 || w > s.rows - 0.5) return std::nan("");
    u = std::clamp(u, 0.0, s.columns - 1.0);
    w = std::clamp(w, 0.0, s.rows - 1.0);
    const int c = std::min(int(u), s.columns - 2), r = std::min(int(w), s.rows - 2);
    const double fu = u - c, fw = w - r;
    return (s.at(c, r) * (1 - fu) + s.at(c + 1, r) * fu) * (1 - fw) +
           (s.at(c, r + 1) * (1 - fu) + s.at(c + 1, r + 1) * fu) * fw;
}

TEST(DicomRealData, GeTiltVoxelsInterpolateTheTwoBracketingSlices) {
    FM_REQUIRE_SHARED_DATA(kGeTilt);
    const auto folder = test::sharedDataDir() / kGeTilt;
    const Volume v = readDicomSeries(folder);
    std::vector<RawSlice> slices;
    for (const auto& f : dicomFilesIn(folder)) slices.push_back(readRawSlice(f));
    const glm::dvec3 normal = v.direction[2];
    std::sort(slices.begin(), slices.end(), [&](const RawSlice& a, const RawSlice& b) {
        return glm::dot(a.position, normal) < glm::dot(b.position, normal);
    });
    // Same rounding argument as above (file cosines vs orthonormalised axes).
    constexpr double kCosineRoundingHu = 0.05;
    int checked = 0;
    for (int k = 0; k < v.dims.z; k += 9) {
        for (int j = 20; j < v.dims.y; j += 53)
            for (int i = 30; i < v.dims.x; i += 61) {
                const glm::dvec3 world = v.indexToWorld(glm::dvec3(i, j, k));
                const double d = glm::dot(world, normal);
                std::size_t b = 1;
                while (b + 1 < slices.size() && glm::dot(slices[b].position, normal) < d) ++b;
                const double da = glm::dot(slices[b - 1].position, normal);
                const double db = glm::dot(slices[b].position, normal);
                const double t = std::clamp((d - da) / (db - da), 0.0, 1.0);
                const double va = bilinearOnSlice(slices[b - 1], world);
                const double vb = bilinearOnSlice(slices[b], world);
                if (std::isnan(va) || std::isnan(vb)) continue;  // near a footprint's edge
                EXPECT_NEAR(v.at(i, j, k), va * (1 - t) + vb * t, kCosineRoundingHu)
                    << "voxel " << i << "," << j << "," << k;
                ++checked;
            }
    }
    EXPECT_GT(checked, 500);
    // The in-plane extent is the union of the slice footprints: the tilt shifts the last slice
    // against the first along the column direction, which adds that many rows of pixels.
    const double shiftPixels =
        std::abs(glm::dot(slices.back().position - slices.front().position, v.direction[1])) /
        v.spacing.y;
    EXPECT_EQ(v.dims.x, 512);
    EXPECT_EQ(v.dims.y, 512 + static_cast<int>(std::ceil(shiftPixels)));
    // Rows of plane 0 beyond the first slice's footprint hold the air fill.
    const int emptyRows = v.dims.y - 512;
    int notAir = 0;
    for (int j = 0; j < emptyRows; ++j)
        for (int i = 0; i < v.dims.x; ++i) notAir += v.at(i, j, 0) != kAirHu;
    EXPECT_EQ(notAir, 0);
}

TEST(DicomRealData, GeTiltListsOneSeriesAndSkipsNonDicomFiles) {
    FM_REQUIRE_SHARED_DATA(kGeTilt);
    // The folder also holds LICENSE / README text files: they are not DICOM and are skipped.
    const auto list = listDicomSeries(test::sharedDataDir() / kGeTilt);
    ASSERT_EQ(list.size(), 1u);
    EXPECT_EQ(list[0].sliceCount, 28u);
    EXPECT_TRUE(list[0].keyIsUid);
}

}  // namespace
}  // namespace fm

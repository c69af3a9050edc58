// The DICOM reader on small series written by the test with GDCM: every expected value follows
// from the stored values, geometry and rescale the test wrote (SyntheticDicom.h).
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <string>

#include <gtest/gtest.h>

#include "common/TestData.h"
#include "core/Error.h"
#include "dicom/SyntheticDicom.h"
#include "io/DicomReader.h"
#include "volume/Volume.h"

namespace fm {
namespace {

using test::makeSyntheticSlice;
using test::SyntheticSlice;
using test::syntheticStoredValue;
using test::writeSyntheticSlice;

// Positions and spacings go through decimal strings of up to 16 characters.
constexpr double kGeometryTolerance = 1e-6;
// Small integers times small rescale factors are exact in float; interpolated values are
// computed in double and rounded once to float (values up to ~2000: ulp ~1e-4).
constexpr double kValueTolerance = 1e-3;

std::string errorOf(const std::filesystem::path& folder, const DicomReadOptions& options = {}) {
    try {
        readDicomSeries(folder, options);
    } catch (const Error& e) {
        return e.what();
    }
    return "(no error)";
}

// "<prefix><n><suffix>" (snprintf: GCC 12 warns falsely on "literal" + std::string).
std::string numbered(const char* prefix, int n, const char* suffix = "") {
    char name[64];
    std::snprintf(name, sizeof name, "%s%d%s", prefix, n, suffix);
    return name;
}

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

// Writes slices z = z0 + k * step (k < count) under names that sort opposite to position, with
// instance numbers that disagree with both.
void writeStack(const std::filesystem::path& folder, int count, double step,
                const std::function<void(SyntheticSlice&, int)>& adjust = {}) {
    for (int k = 0; k < count; ++k) {
        SyntheticSlice s = makeSyntheticSlice(k, 5.0 + k * step);
        s.instanceNumber = (k * 3) % count + 1;
        if (adjust) adjust(s, k);
        writeSyntheticSlice(s, folder / numbered("f", 9 - k, ".dcm"));
    }
}

TEST(DicomSynthetic, ValuesGeometryAndRescaleOfAnUnsortedSeries) {
    const auto folder = test::scratchDir("dicom-known-values");
    writeStack(folder, 5, 2.5, [](SyntheticSlice& s, int) {
        s.slope = 2.0;
        s.intercept = -1000.0;
    });
    const Volume v = readDicomSeries(folder);
    ASSERT_EQ(v.dims, glm::ivec3(8, 6, 5));
    EXPECT_NEAR(v.spacing.x, 0.5, kGeometryTolerance);   // PixelSpacing[1]: between columns
    EXPECT_NEAR(v.spacing.y, 0.75, kGeometryTolerance);  // PixelSpacing[0]: between rows
    EXPECT_NEAR(v.spacing.z, 2.5, kGeometryTolerance);
    EXPECT_NEAR(glm::length(v.origin - glm::dvec3(-10, 20, 5)), 0.0, kGeometryTolerance);
    EXPECT_EQ(orientationCode(v.direction), "LPS");
    EXPECT_EQ(v.meta.units, ValueUnit::HounsfieldUnits);
    EXPECT_EQ(v.meta.modality, "CT");
    int wrong = 0;
    for (int k = 0; k < 5; ++k)
        for (int r = 0; r < 6; ++r)
            for (int c = 0; c < 8; ++c)
                wrong += std::abs(v.at(c, r, k) - (2.0 * syntheticStoredValue(c, r, k) - 1000.0)) >
                         kValueTolerance;
    EXPECT_EQ(wrong, 0);
}

TEST(DicomSynthetic, ObliqueOrientationGivesDirectionColumnsRowColumnNormal) {
    const auto folder = test::scratchDir("dicom-sagittal");
    // Sagittal: rows run posterior (+y), columns run inferior (-z); the normal is then -x, so
    // slices are stacked towards the patient's right.
    writeStack(folder, 3, 1.0, [](SyntheticSlice& s, int k) {
        s.rowDirection = glm::dvec3(0, 1, 0);
        s.columnDirection = glm::dvec3(0, 0, -1);
        s.position = glm::dvec3(-2.0 * k, 0.0, 0.0);
    });
    const Volume v = readDicomSeries(folder);
    EXPECT_EQ(orientationCode(v.direction), "PIR");
    EXPECT_NEAR(v.spacing.z, 2.0, kGeometryTolerance);
    EXPECT_NEAR(glm::length(v.origin - glm::dvec3(0, 0, 0)), 0.0, kGeometryTolerance);
    // Plane k is the slice written at x = -2k, i.e. slice index k.
    EXPECT_NEAR(v.at(3, 2, 2), syntheticStoredValue(3, 2, 2), kValueTolerance);
}

TEST(DicomSynthetic, UnsignedTwelveBitValuesIgnoreBitsAboveBitsStored) {
    const auto folder = test::scratchDir("dicom-12bit");
    writeStack(folder, 2, 1.0, [](SyntheticSlice& s, int) {
        s.isSigned = false;
        s.bitsStored = 12;
        for (auto& word : s.stored)  // unused high bits set, as overlays in old files do
            word = static_cast<std::int16_t>(static_cast<std::uint16_t>(word + 1000) | 0xF000);
        s.intercept = -1024.0;
    });
    const Volume v = readDicomSeries(folder);
    EXPECT_NEAR(v.at(5, 4, 1), syntheticStoredValue(5, 4, 1) + 1000 - 1024.0, kValueTolerance);
}

TEST(DicomSynthetic, PixelPaddingValueBecomesAir) {
    const auto folder = test::scratchDir("dicom-padding");
    writeStack(folder, 2, 1.0, [](SyntheticSlice& s, int) {
        s.stored[0] = -2000;
        s.pixelPadding = -2000;
    });
    const Volume v = readDicomSeries(folder);
    EXPECT_EQ(v.at(0, 0, 0), -1024.0f);
    EXPECT_EQ(v.at(0, 0, 1), -1024.0f);
    EXPECT_NEAR(v.at(1, 0, 0), syntheticStoredValue(1, 0, 0), kValueTolerance);
}

TEST(DicomSynthetic, TwoSeriesInOneFolder) {
    const auto folder = test::scratchDir("dicom-two-series");
    writeStack(folder, 5, 1.0);    // series A: 5 slices, stored values as written
    for (int k = 0; k < 3; ++k) {  // series B: 3 slices, values offset by 7000
        SyntheticSlice s = makeSyntheticSlice(k, 100.0 + k);
        for (auto& w : s.stored) w = static_cast<std::int16_t>(w + 7000);
        s.seriesInstanceUid = "1.2.826.0.1.3680043.2.1125.1.2";
        s.seriesDescription = "second";
        writeSyntheticSlice(s, folder / numbered("b", k, ".dcm"));
    }
    const auto list = listDicomSeries(folder);
    ASSERT_EQ(list.size(), 2u);
    EXPECT_EQ(list[0].sliceCount, 5u);
    EXPECT_EQ(list[1].sliceCount, 3u);

    const Volume largest = readDicomSeries(folder);
    EXPECT_EQ(largest.dims.z, 5);
    EXPECT_NEAR(largest.at(0, 0, 0), syntheticStoredValue(0, 0, 0), kValueTolerance);
    EXPECT_TRUE(contains(largest.meta.description, "2 series")) << largest.meta.description;

    DicomReadOptions byIndex;
    byIndex.seriesIndex = 1;
    const Volume second = readDicomSeries(folder, byIndex);
    EXPECT_EQ(second.dims.z, 3);
    EXPECT_NEAR(second.at(0, 0, 0), syntheticStoredValue(0, 0, 0) + 7000, kValueTolerance);
    EXPECT_TRUE(contains(second.meta.description, "second"));

    DicomReadOptions byUid;
    byUid.seriesInstanceUid = "1.2.826.0.1.3680043.2.1125.1.2";
    EXPECT_EQ(readDicomSeries(folder, byUid).dims.z, 3);
    byUid.seriesInstanceUid = "9.9.9";
    EXPECT_TRUE(contains(errorOf(folder, byUid), "9.9.9"));
    byIndex.seriesIndex = 2;
    EXPECT_TRUE(contains(errorOf(folder, byIndex), "out of range"));
}

TEST(DicomSynthetic, EmptySeriesUidGroupsBySeriesNumberAndGeometry) {
    const auto folder = test::scratchDir("dicom-empty-uid");
    // 4 slices of series number 3, 2 of series number 4, all with an empty SeriesInstanceUID.
    writeStack(folder, 4, 1.0, [](SyntheticSlice& s, int) { s.seriesInstanceUid = ""; });
    for (int k = 0; k < 2; ++k) {
        SyntheticSlice s = makeSyntheticSlice(k, 50.0 + k);
        s.seriesInstanceUid = "";
        s.seriesNumber = "4";
        writeSyntheticSlice(s, folder / numbered("other", k, ".dcm"));
    }
    const auto list = listDicomSeries(folder);
    ASSERT_EQ(list.size(), 2u);
    EXPECT_EQ(list[0].sliceCount, 4u);
    EXPECT_EQ(list[1].sliceCount, 2u);
    EXPECT_FALSE(list[0].keyIsUid);
    EXPECT_EQ(readDicomSeries(folder).dims.z, 4);
}

TEST(DicomSynthetic, UnevenStepsAreResampledBetweenTheBracketingSlices) {
    const auto folder = test::scratchDir("dicom-uneven");
    const double z[] = {0.0, 1.0, 3.0, 6.0};
    for (int k = 0; k < 4; ++k)
        writeSyntheticSlice(makeSyntheticSlice(k, z[k]), folder / numbered("s", k));
    const Volume v = readDicomSeries(folder);
    // Step = the smallest slice step (1 mm; not below the 0.5 mm pixel nor 1/4 of the 2 mm
    // median step), so 7 planes at z = 0..6.
    ASSERT_EQ(v.dims, glm::ivec3(8, 6, 7));
    EXPECT_NEAR(v.spacing.z, 1.0, kGeometryTolerance);
    EXPECT_TRUE(contains(v.meta.description, "resampled"));
    for (int k = 0; k < 7; ++k) {
        // Fractional slice index at z = k: linear between the written slices.
        double s = 0;
        for (int a = 0; a < 3; ++a)
            if (k >= z[a] && k <= z[a + 1]) s = a + (k - z[a]) / (z[a + 1] - z[a]);
        // Stored values are linear in the slice index, so interpolation reproduces them.
        const double expected = 100.0 * s + 10.0 * 3 + 2 - 50;
        EXPECT_NEAR(v.at(2, 3, k), expected, kValueTolerance) << "plane " << k;
    }
}

TEST(DicomSynthetic, PositionJitterBelowTheToleranceIsCopiedAboveItResampled) {
    // docs/coordinates.md: regular when positions lie within max(0.01 mm, 1 % of the step) of
    // an even grid and in-plane offsets within max(0.01 mm, 5 % of a pixel).
    struct Case {
        double jitterAlongNormal, inPlaneShift;
        bool resampled;
    };
    const Case cases[] = {
        {0.005, 0.0, false},  // 0.25 % of the 2 mm step
        {0.0, 0.02, false},   // 4 % of the 0.5 mm pixel
        {0.1, 0.0, true},     // 5 % of the step
        {0.0, 0.1, true},     // 20 % of a pixel
    };
    for (const Case& c : cases) {
        const auto folder = test::scratchDir("dicom-jitter");
        writeStack(folder, 4, 2.0, [&](SyntheticSlice& s, int k) {
            if (k == 2) s.position += glm::dvec3(c.inPlaneShift, 0.0, c.jitterAlongNormal);
        });
        const Volume v = readDicomSeries(folder);
        EXPECT_EQ(contains(v.meta.description, "resampled"), c.resampled)
            << c.jitterAlongNormal << " " << c.inPlaneShift << ": " << v.meta.description;
        if (!c.resampled) {
            EXPECT_EQ(v.dims.z, 4);
            EXPECT_NEAR(v.spacing.z, 2.0, kGeometryTolerance);
            EXPECT_NEAR(v.at(1, 1, 2), syntheticStoredValue(1, 1, 2), kValueTolerance);
        }
    }
}

TEST(DicomSynthetic, GantryTiltIsResampledWithoutShear) {
    const auto folder = test::scratchDir("dicom-tilt");
    // Tilt 20 deg about x: columns run along (0, cos, -sin); IPPs advance along z only, so each
    // slice is shifted within its plane against the previous one.
    const double tilt = 20.0 * M_PI / 180.0;
    const glm::dvec3 row(1, 0, 0), col(0, std::cos(tilt), -std::sin(tilt));
    const glm::dvec3 normal = glm::cross(row, col);
    const int count = 5;
    const double zStep = 3.0;
    for (int k = 0; k < count; ++k) {
        SyntheticSlice s = makeSyntheticSlice(k, k * zStep);
        s.columnDirection = col;
        writeSyntheticSlice(s, folder / numbered("t", count - k));
    }
    const Volume v = readDicomSeries(folder);
    EXPECT_NEAR(glm::length(v.direction[2] - normal), 0.0, 1e-9);
    // Regular along the normal (3 cos 20 deg) but shifted: extent = first-to-last distance.
    const double firstToLast = (count - 1) * zStep * normal.z;
    EXPECT_NEAR((v.dims.z - 1) * v.spacing.z, firstToLast, kGeometryTolerance);
    EXPECT_TRUE(contains(v.meta.description, "resampled"));

    // Analytic value at a world point: in each bracketing slice the stored value is linear in
    // (column, row), so bilinear interpolation is exact; then linear between the two slices.
    const auto slicePosition = [&](int k) { return glm::dvec3(-10.0, 20.0, k * zStep); };
    int checked = 0;
    for (int k = 0; k < v.dims.z; ++k)
        for (int j = 0; j < v.dims.y; ++j)
            for (int i = 0; i < v.dims.x; ++i) {
                const glm::dvec3 p = v.indexToWorld(glm::dvec3(i, j, k));
                const double d = glm::dot(p - slicePosition(0), normal) / (zStep * normal.z);
                const int a = std::min(static_cast<int>(std::floor(d + 1e-9)), count - 2);
                const double t = d - a;
                double value = 0.0;
                bool inside = true;
                for (int s : {a, a + 1}) {
                    const glm::dvec3 q = p - slicePosition(s);
                    const double c = glm::dot(q, row) / 0.5, r = glm::dot(q, col) / 0.75;
                    if (c < -1e-9 || c > 7 + 1e-9 || r < -1e-9 || r > 5 + 1e-9) inside = false;
                    value += (s == a ? 1 - t : t) * (100.0 * s + 10.0 * r + c - 50.0);
                }
                if (!inside) continue;  // edges: clamped or air, checked elsewhere
                EXPECT_NEAR(v.at(i, j, k), value, kValueTolerance) << i << "," << j << "," << k;
                ++checked;
            }
    EXPECT_GT(checked, 60);
}

// --- errors -----------------------------------------------------------------------------

TEST(DicomSyntheticErrors, EmptyMissingAndNonDicomFolders) {
    const auto empty = test::scratchDir("dicom-empty");
    EXPECT_TRUE(contains(errorOf(empty), "no files")) << errorOf(empty);
    EXPECT_TRUE(contains(errorOf(empty / "nope"), "does not exist"));
    const auto text = test::scratchDir("dicom-text-only");
    std::ofstream(text / "README.txt") << "not a DICOM file\n";
    std::ofstream(text / "notes") << std::string(300, 'x');
    EXPECT_TRUE(contains(errorOf(text), "no DICOM image")) << errorOf(text);
    EXPECT_TRUE(contains(errorOf(text / "README.txt"), "not a folder"));
}

TEST(DicomSyntheticErrors, SliceWithoutPixelDataIsNamed) {
    const auto folder = test::scratchDir("dicom-no-pixels");
    writeStack(folder, 4, 1.0);
    test::editDicomElement(folder / "f8.dcm", 0x7fe0, 0x0010, std::nullopt);
    const std::string message = errorOf(folder);
    EXPECT_TRUE(contains(message, "f8.dcm")) << message;
    EXPECT_TRUE(contains(message, "no pixel data")) << message;
}

TEST(DicomSyntheticErrors, TruncatedPixelDataIsNamed) {
    const auto folder = test::scratchDir("dicom-truncated");
    writeStack(folder, 3, 1.0);
    const auto file = folder / "f8.dcm";
    std::filesystem::resize_file(file, std::filesystem::file_size(file) - 20);
    const std::string message = errorOf(folder);
    EXPECT_TRUE(contains(message, "f8.dcm")) << message;
    EXPECT_TRUE(contains(message, "truncated")) << message;
}

TEST(DicomSyntheticErrors, SlicesOfDifferentSizesInOneSeries) {
    const auto folder = test::scratchDir("dicom-sizes");
    writeStack(folder, 3, 1.0, [](SyntheticSlice& s, int k) {
        if (k == 1) {
            s.rows = 5;
            s.stored.resize(static_cast<std::size_t>(s.rows) * s.columns);
        }
    });
    const std::string message = errorOf(folder);
    EXPECT_TRUE(contains(message, "different sizes")) << message;
}

TEST(DicomSyntheticErrors, SlicesOfDifferentOrientationsInOneSeries) {
    const auto folder = test::scratchDir("dicom-orientations");
    writeStack(folder, 3, 1.0, [](SyntheticSlice& s, int k) {
        if (k == 2) s.columnDirection = glm::dvec3(0, std::cos(0.3), -std::sin(0.3));
    });
    EXPECT_TRUE(contains(errorOf(folder), "different orientations")) << errorOf(folder);
}

TEST(DicomSyntheticErrors, MissingOrAbsurdGeometry) {
    struct Case {
        std::uint16_t group, element;
        std::optional<std::string> value;
        const char* expected;
    };
    const Case cases[] = {
        {0x0020, 0x0032, std::nullopt, "missing ImagePositionPatient"},
        {0x0020, 0x0037, std::nullopt, "missing ImageOrientationPatient"},
        {0x0028, 0x0030, std::nullopt, "missing PixelSpacing"},
        {0x0028, 0x0030, std::string("nan\\0.5"), "PixelSpacing"},
        {0x0028, 0x0030, std::string("0\\0"), "PixelSpacing"},
        {0x0028, 0x0030, std::string("1e9\\1e9"), "PixelSpacing"},
        {0x0020, 0x0032, std::string("1\\2"), "ImagePositionPatient"},
        {0x0020, 0x0032, std::string("1\\2\\inf"), "ImagePositionPatient"},
        {0x0020, 0x0037, std::string("1\\0\\0\\1\\0\\0"), "ImageOrientationPatient"},
        {0x0028, 0x1053, std::string("0"), "RescaleSlope"},
    };
    for (const Case& c : cases) {
        const auto folder = test::scratchDir("dicom-bad-geometry");
        writeStack(folder, 3, 1.0);
        test::editDicomElement(folder / "f8.dcm", c.group, c.element, c.value);
        const std::string message = errorOf(folder);
        EXPECT_TRUE(contains(message, c.expected) && contains(message, "f8.dcm"))
            << c.expected << ": " << message;
    }
}

TEST(DicomSyntheticErrors, TwoSlicesAtOnePosition) {
    const auto folder = test::scratchDir("dicom-duplicate");
    writeStack(folder, 3, 1.0);
    std::filesystem::copy_file(folder / "f8.dcm", folder / "copy.dcm");
    EXPECT_TRUE(contains(errorOf(folder), "same position")) << errorOf(folder);
}

TEST(DicomSyntheticErrors, MultiFrameIsRefusedClearly) {
    const auto folder = test::scratchDir("dicom-multiframe");
    writeStack(folder, 2, 1.0);
    test::editDicomElement(folder / "f8.dcm", 0x0028, 0x0008, std::string("4"));
    EXPECT_TRUE(contains(errorOf(folder), "multi-frame")) << errorOf(folder);
}

}  // namespace
}  // namespace fm

#include <gtest/gtest.h>

#include <nifti/nifti1.h>
#include <stb/stb_image.h>
#include <zlib.h>

#include <cmath>
#include <cstring>
#include <limits>

#include <glm/gtc/matrix_transform.hpp>

#include "IoTestFiles.h"
#include "TestExpect.h"
#include "common/TestData.h"
#include "io/AtomicFile.h"
#include "io/PngWriter.h"
#include "io/ReadVolume.h"
#include "io/VolumeWriter.h"

namespace {

namespace fs = std::filesystem;
using fm::test::expectVec;

// NIfTI-1 stores the affine as float32: ~6e-8 relative, on values up to ~100 mm.
constexpr double kNiftiGeometryTol = 2e-5;
// MetaImage writes geometry as shortest round-trip decimal text: exact.
constexpr double kMhaGeometryTol = 0.0;

// A volume with an oblique, left-handed-looking (mirrored) axis set and distinct values.
fm::Volume obliqueVolume(bool mirrored) {
    fm::Volume v = fm::Volume::allocate({5, 4, 3});
    for (std::size_t n = 0; n < v.values.size(); ++n)
        v.values[n] = static_cast<float>(n) * 1.25f - 30.0f;
    v.values[7] = std::numeric_limits<float>::max();
    v.values[8] = -std::numeric_limits<float>::denorm_min();
    v.spacing = {0.7, 1.3, 2.9};
    v.origin = {-12.5, 33.25, 101.0};
    const glm::dmat4 r = glm::rotate(glm::dmat4(1.0), 0.4, glm::normalize(glm::dvec3(1, 2, 3)));
    v.direction = glm::dmat3(r);
    if (mirrored) v.direction[2] = -v.direction[2];
    v.meta.description = "oblique test volume";
    return v;
}

void expectSameVolume(const fm::Volume& a, const fm::Volume& b, double geometryTol) {
    EXPECT_EQ(a.dims, b.dims);
    ASSERT_EQ(a.values.size(), b.values.size());
    for (std::size_t n = 0; n < a.values.size(); ++n) ASSERT_EQ(a.values[n], b.values[n]) << n;
    expectVec(a.origin, b.origin, geometryTol);
    expectVec(a.spacing, b.spacing, geometryTol);
    for (int c = 0; c < 3; ++c) expectVec(a.direction[c], b.direction[c], geometryTol);
}

TEST(VolumeWriter, RoundTripsWithObliqueDirection) {
    const fs::path dir = fm::test::scratchDir("writer_roundtrip");
    for (bool mirrored : {false, true}) {
        const fm::Volume v = obliqueVolume(mirrored);
        SCOPED_TRACE(mirrored ? "mirrored" : "rotation");
        fm::writeMetaImage(v, dir / "c.mha", true);
        expectSameVolume(v, fm::readVolume(dir / "c.mha"), kMhaGeometryTol);
        fm::writeMetaImage(v, dir / "u.mha", false);
        expectSameVolume(v, fm::readVolume(dir / "u.mha"), kMhaGeometryTol);
        fm::writeVolume(v, dir / "v.nii.gz");
        expectSameVolume(v, fm::readVolume(dir / "v.nii.gz"), kNiftiGeometryTol);
        fm::writeVolume(v, dir / "v.nii");
        expectSameVolume(v, fm::readVolume(dir / "v.nii"), kNiftiGeometryTol);
    }
}

// The qform we write must describe the same axes as the sform (tools that read only the qform,
// e.g. some plastimatch paths, must get the same geometry): decode it with the standard's
// formula from the raw header, independent of our reader.
TEST(VolumeWriter, NiftiQformMatchesSform) {
    const fs::path dir = fm::test::scratchDir("writer_qform");
    for (bool mirrored : {false, true}) {
        const fm::Volume v = obliqueVolume(mirrored);
        fm::writeVolume(v, dir / "q.nii.gz");
        gzFile gz = gzopen((dir / "q.nii.gz").string().c_str(), "rb");
        ASSERT_NE(gz, nullptr);
        nifti_1_header h;
        ASSERT_EQ(gzread(gz, &h, sizeof h), static_cast<int>(sizeof h));
        gzclose(gz);
        EXPECT_EQ(h.sizeof_hdr, 348);
        EXPECT_EQ(std::string(h.magic), "n+1");
        EXPECT_EQ(h.datatype, DT_FLOAT32);
        EXPECT_EQ(h.sform_code, NIFTI_XFORM_SCANNER_ANAT);
        EXPECT_EQ(h.qform_code, NIFTI_XFORM_SCANNER_ANAT);
        EXPECT_EQ(h.vox_offset, 352.0f);
        EXPECT_EQ(XYZT_TO_SPACE(h.xyzt_units), NIFTI_UNITS_MM);
        const double b = h.quatern_b, c = h.quatern_c, d = h.quatern_d;
        const double a = std::sqrt(std::max(0.0, 1.0 - (b * b + c * c + d * d)));
        const double R[3][3] = {
            {a * a + b * b - c * c - d * d, 2 * b * c - 2 * a * d, 2 * b * d + 2 * a * c},
            {2 * b * c + 2 * a * d, a * a + c * c - b * b - d * d, 2 * c * d - 2 * a * b},
            {2 * b * d - 2 * a * c, 2 * c * d + 2 * a * b, a * a + d * d - c * c - b * b}};
        const double qfac = h.pixdim[0] < 0 ? -1.0 : 1.0;
        EXPECT_EQ(qfac, mirrored ? -1.0 : 1.0);
        const float* srow[3] = {h.srow_x, h.srow_y, h.srow_z};
        for (int row = 0; row < 3; ++row)
            for (int col = 0; col < 3; ++col) {
                const double q = R[row][col] * h.pixdim[col + 1] * (col == 2 ? qfac : 1.0);
                EXPECT_NEAR(q, srow[row][col], kNiftiGeometryTol) << row << "," << col;
            }
        // And the sform is the LPS geometry turned into RAS (x and y negated).
        for (int col = 0; col < 3; ++col) {
            const glm::dvec3 axis = v.direction[col] * v.spacing[col];
            EXPECT_NEAR(srow[0][col], -axis.x, kNiftiGeometryTol);
            EXPECT_NEAR(srow[1][col], -axis.y, kNiftiGeometryTol);
            EXPECT_NEAR(srow[2][col], axis.z, kNiftiGeometryTol);
        }
        EXPECT_NEAR(h.qoffset_x, -v.origin.x, kNiftiGeometryTol);
        EXPECT_NEAR(srow[2][3], v.origin.z, kNiftiGeometryTol);
    }
}

TEST(VolumeWriter, MetaImageHeaderIsWhatItkExpects) {
    const fs::path dir = fm::test::scratchDir("writer_mha_header");
    fm::Volume v = fm::Volume::allocate({2, 3, 4}, 1.0f);
    v.direction = glm::dmat3(glm::dvec3(0, 1, 0), glm::dvec3(-1, 0, 0), glm::dvec3(0, 0, 1));
    fm::writeMetaImage(v, dir / "h.mha", false);
    const fm::test::Bytes file = fm::test::readFile(dir / "h.mha");
    const std::string text(file.begin(), file.end());
    EXPECT_NE(text.find("ElementType = MET_FLOAT\nElementDataFile = LOCAL\n"), std::string::npos);
    // Each group of three is one axis (ITK's layout).
    EXPECT_NE(text.find("TransformMatrix = 0 1 0 -1 0 0 0 0 1\n"), std::string::npos);
    EXPECT_NE(text.find("DimSize = 2 3 4\n"), std::string::npos);
    EXPECT_NE(text.find("BinaryDataByteOrderMSB = False\n"), std::string::npos);
    // Header then exactly 24 float32 samples.
    EXPECT_EQ(file.size(), text.find("LOCAL\n") + 6 + 24 * 4);
}

TEST(ImageWriter, ImageRoundTripsAsOneSliceVolume) {
    const fs::path dir = fm::test::scratchDir("writer_image");
    fm::Image img(7, 5);
    for (int r = 0; r < 5; ++r)
        for (int c = 0; c < 7; ++c) img.at(c, r) = static_cast<float>(c * 10 + r) + 0.5f;
    img.spacing = {0.373, 0.25};
    for (const char* name : {"drr.mha", "drr.nii.gz"}) {
        fm::writeImage(img, dir / name);
        const fm::Volume v = fm::readVolume(dir / name);
        SCOPED_TRACE(name);
        EXPECT_EQ(v.dims, glm::ivec3(7, 5, 1));
        EXPECT_TRUE(v.values == img.pixels);
        EXPECT_NEAR(v.spacing.x, 0.373, kNiftiGeometryTol);
        EXPECT_NEAR(v.spacing.y, 0.25, kNiftiGeometryTol);
        EXPECT_NEAR(v.at(3, 2, 0), 32.5, 0.0);
    }
    EXPECT_THROW(fm::writeImage(img, dir / "drr.tiff"), fm::Error);
}

TEST(PngWriter, MapsWindowToGreyLevels) {
    const fs::path dir = fm::test::scratchDir("writer_png");
    fm::Image img(4, 2);
    const float values[8] = {0.0f, 100.0f, 50.0f, -20.0f, 130.0f, std::nanf(""), 25.0f, 75.0f};
    std::copy(values, values + 8, img.pixels.begin());
    fm::writePng(img, dir / "g.png", 0.0f, 100.0f);
    int w = 0, h = 0, channels = 0;
    unsigned char* pixels = stbi_load((dir / "g.png").string().c_str(), &w, &h, &channels, 0);
    ASSERT_NE(pixels, nullptr);
    EXPECT_EQ(w, 4);
    EXPECT_EQ(h, 2);
    EXPECT_EQ(channels, 1);
    // round(v / 100 * 255), clamped; NaN -> 0. Row 0 is the top row.
    const int expected[8] = {0, 255, 128, 0, 255, 0, 64, 191};
    for (int n = 0; n < 8; ++n) EXPECT_EQ(pixels[n], expected[n]) << n;
    stbi_image_free(pixels);

    EXPECT_THROW(fm::writePng(img, dir / "bad.png", 5.0f, 5.0f), fm::Error);
    EXPECT_THROW(fm::writePng(fm::Image(), dir / "empty.png", 0.0f, 1.0f), fm::Error);
    EXPECT_FALSE(fs::exists(dir / "bad.png"));
}

TEST(AtomicFile, FailedWriteKeepsTheOldFile) {
    const fs::path dir = fm::test::scratchDir("writer_atomic");
    const fs::path target = dir / "keep.mha";
    fm::test::writeFile(target, std::string("old content"));
    // A writer that produces part of a file and then fails.
    EXPECT_THROW(fm::io::writeViaTemporary(target,
                                           [](const fs::path& temp) {
                                               fm::test::writeFile(temp, std::string("half"));
                                               return false;
                                           }),
                 fm::Error);
    EXPECT_THROW(fm::io::writeViaTemporary(target,
                                           [](const fs::path& temp) -> bool {
                                               fm::test::writeFile(temp, std::string("half"));
                                               throw fm::Error("simulated failure");
                                           }),
                 fm::Error);
    const fm::test::Bytes kept = fm::test::readFile(target);
    EXPECT_EQ(std::string(kept.begin(), kept.end()), "old content");
    // No temporary files left behind.
    int entries = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++entries;
    EXPECT_EQ(entries, 1);

    // An invalid volume is refused before anything is written.
    fm::Volume bad = fm::Volume::allocate({2, 2, 2});
    bad.spacing.x = 0.0;
    EXPECT_THROW(fm::writeVolume(bad, target), fm::Error);
    EXPECT_EQ(fm::test::readFile(target).size(), 11u);
    // A missing folder is a clear error.
    EXPECT_THROW(fm::writeVolume(obliqueVolume(false), dir / "no_such_dir" / "v.mha"), fm::Error);
    // Success replaces the file.
    fm::writeVolume(obliqueVolume(false), target);
    EXPECT_EQ(fm::readVolume(target).dims, glm::ivec3(5, 4, 3));
}

}  // namespace

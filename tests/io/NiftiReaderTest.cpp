#include <gtest/gtest.h>

#include <nifti/nifti1.h>

#include <cmath>
#include <limits>
#include <random>
#include <utility>

#include "IoTestFiles.h"
#include "TestExpect.h"
#include "common/TestData.h"
#include "core/Error.h"
#include "io/NiftiReader.h"
#include "io/ReadVolume.h"

namespace {

namespace fs = std::filesystem;
using fm::test::Bytes;
using fm::test::NiftiSpec;
using fm::test::ScalarType;

// NIfTI-1 stores geometry as float32: about 7 significant digits of values up to ~100.
constexpr double kFloatGeometryTol = 1e-5;
// Direction cosines computed from float32 quaternions / affines.
constexpr double kDirectionTol = 1e-6;

int datatypeOf(ScalarType t) {
    switch (t) {
        case ScalarType::U8:
            return DT_UINT8;
        case ScalarType::I8:
            return DT_INT8;
        case ScalarType::U16:
            return DT_UINT16;
        case ScalarType::I16:
            return DT_INT16;
        case ScalarType::U32:
            return DT_UINT32;
        case ScalarType::I32:
            return DT_INT32;
        case ScalarType::U64:
            return DT_UINT64;
        case ScalarType::I64:
            return DT_INT64;
        case ScalarType::F32:
            return DT_FLOAT32;
        case ScalarType::F64:
            return DT_FLOAT64;
    }
    return 0;
}

NiftiSpec smallSpec(ScalarType type = ScalarType::I16) {
    NiftiSpec s;
    s.dim = {3, 3, 4, 5};
    s.datatype = datatypeOf(type);
    s.values = fm::test::sampleValues(type, 60);
    return s;
}

fs::path writeSpec(const NiftiSpec& s, const fs::path& dir, const std::string& name) {
    const fs::path p = dir / name;
    fm::test::writeFile(p, s.bytes());
    return p;
}

using fm::test::expectError;
using fm::test::expectValues;
using fm::test::expectVec;

TEST(NiftiReader, EveryDatatypeBothVersionsBothByteOrders) {
    const fs::path dir = fm::test::scratchDir("nifti_types");
    for (int version : {1, 2})
        for (bool big : {false, true})
            for (ScalarType type : fm::test::allScalarTypes()) {
                NiftiSpec s = smallSpec(type);
                s.version = version;
                s.bigEndian = big;
                std::string name = std::to_string(version);  // piecewise: GCC 12 -Wrestrict
                name += big ? "be_" : "le_";
                name += fm::io::toString(type);
                name += ".nii";
                const fm::Volume v = fm::readVolume(writeSpec(s, dir, name));
                SCOPED_TRACE(name);
                EXPECT_EQ(v.dims, glm::ivec3(3, 4, 5));
                expectValues(v, s.values);
                // No qform/sform: pixdim only, axes RAS as ITK and nibabel take them.
                EXPECT_EQ(fm::orientationCode(v.direction), "RAS");
            }
}

TEST(NiftiReader, GzipAndTwoFilePairs) {
    const fs::path dir = fm::test::scratchDir("nifti_gz_pair");
    NiftiSpec s = smallSpec(ScalarType::F32);
    fm::test::writeFile(dir / "a.nii.gz", fm::test::gzipBytes(s.bytes()));
    expectValues(fm::readVolume(dir / "a.nii.gz"), s.values);

    NiftiSpec p = smallSpec(ScalarType::U16);
    p.pair = true;
    p.bigEndian = true;
    fm::test::writeFile(dir / "b.hdr", p.header());
    fm::test::writeFile(dir / "b.img", p.data());
    expectValues(fm::readVolume(dir / "b.hdr"), p.values);
    expectValues(fm::readVolume(dir / "b.img"), p.values);  // the data path finds its header

    NiftiSpec p2 = smallSpec(ScalarType::I32);
    p2.pair = true;
    p2.version = 2;
    fm::test::writeFile(dir / "c.hdr", p2.header());
    fm::test::writeFile(dir / "c.img.gz", fm::test::gzipBytes(p2.data()));
    expectValues(fm::readVolume(dir / "c.hdr"), p2.values);
}

// gzip NIfTIs are converted while they inflate: samples split between two inflated pieces
// (the input arrives 256 KiB at a time, so with incompressible data the pieces end anywhere)
// must come out as in the uncompressed file, for every sample size and both byte orders.
TEST(NiftiReader, LargeGzipFilesConvertAsTheyInflate) {
    const fs::path dir = fm::test::scratchDir("nifti_gz_streamed");
    std::mt19937 rng(11);
    for (auto [type, bigEndian] : {std::pair{ScalarType::U8, false}, {ScalarType::I16, false},
                                   {ScalarType::I16, true}, {ScalarType::F64, true}}) {
        {
            NiftiSpec s;
            s.dim = {3, 91, 67, 43};
            s.datatype = datatypeOf(type);
            s.bigEndian = bigEndian;
            s.values.resize(91 * 67 * 43);
            for (double& v : s.values)
                v = type == ScalarType::U8 ? double(rng() % 256) : double(int(rng() % 4096) - 1024);
            const Bytes bytes = s.bytes();
            fm::test::writeFile(dir / "a.nii.gz", fm::test::gzipBytes(bytes));
            ASSERT_GT(fs::file_size(dir / "a.nii.gz"), 256u * 1024) << "more than one input piece";
            const fm::Volume v = fm::readVolume(dir / "a.nii.gz");
            expectValues(v, s.values);
            // Cut short: the truncation is reported with the decompressed size.
            Bytes cut = fm::test::gzipBytes(Bytes(bytes.begin(), bytes.end() - 5));
            fm::test::writeFile(dir / "b.nii.gz", cut);
            expectError([&] { fm::readVolume(dir / "b.nii.gz"); }, dir / "b.nii.gz",
                        "decompressed file has only " + std::to_string(bytes.size() - 5));
        }
    }
}

TEST(NiftiReader, SformPreferredOverQformAndConvertedToLps) {
    const fs::path dir = fm::test::scratchDir("nifti_sform");
    for (int version : {1, 2}) {
        NiftiSpec s = smallSpec();
        s.version = version;
        s.sformCode = NIFTI_XFORM_SCANNER_ANAT;
        s.qformCode = NIFTI_XFORM_SCANNER_ANAT;  // a different qform that must be ignored
        s.quatern[2] = 1.0;                      // 180 degrees about z
        // i -> RAS (0, 2, 0): anterior; j -> RAS (-3, 0, 0): left; k -> RAS (0, 0, 4): superior.
        s.srow[0][0] = 0, s.srow[0][1] = -3, s.srow[0][2] = 0, s.srow[0][3] = 10;
        s.srow[1][0] = 2, s.srow[1][1] = 0, s.srow[1][2] = 0, s.srow[1][3] = -20;
        s.srow[2][0] = 0, s.srow[2][1] = 0, s.srow[2][2] = 4, s.srow[2][3] = 30;
        const fm::Volume v = fm::readVolume(writeSpec(s, dir, "s.nii"));
        expectVec(v.spacing, {2, 3, 4}, kFloatGeometryTol);
        // LPS = RAS with x and y negated.
        expectVec(v.origin, {-10, 20, 30}, kFloatGeometryTol);
        expectVec(v.direction[0], {0, -1, 0}, kDirectionTol);  // anterior
        expectVec(v.direction[1], {1, 0, 0}, kDirectionTol);   // LPS +x: patient left
        expectVec(v.direction[2], {0, 0, 1}, kDirectionTol);
        EXPECT_EQ(fm::orientationCode(v.direction), "ALS");
    }
}

TEST(NiftiReader, QformQuaternionWithQfac) {
    const fs::path dir = fm::test::scratchDir("nifti_qform");
    for (int version : {1, 2})
        for (double qfac : {1.0, -1.0}) {
            NiftiSpec s = smallSpec();
            s.version = version;
            s.qformCode = NIFTI_XFORM_SCANNER_ANAT;
            // 90 degrees about z: (a, b, c, d) = (cos 45, 0, 0, sin 45).
            s.quatern[2] = std::sqrt(0.5);
            s.qoffset[0] = 5, s.qoffset[1] = 6, s.qoffset[2] = 7;
            s.pixdim[0] = qfac;
            s.pixdim[1] = 0.5, s.pixdim[2] = 0.75, s.pixdim[3] = 2.5;
            const fm::Volume v = fm::readVolume(writeSpec(s, dir, "q.nii"));
            SCOPED_TRACE(version);
            expectVec(v.spacing, {0.5, 0.75, 2.5}, kFloatGeometryTol);
            expectVec(v.origin, {-5, -6, 7}, kFloatGeometryTol);
            // RAS axes: i -> (0,1,0), j -> (-1,0,0), k -> (0,0,qfac); then x,y negated.
            expectVec(v.direction[0], {0, -1, 0}, kDirectionTol);
            expectVec(v.direction[1], {1, 0, 0}, kDirectionTol);
            expectVec(v.direction[2], {0, 0, qfac}, kDirectionTol);
        }
}

TEST(NiftiReader, PixdimOnlyAndUnits) {
    const fs::path dir = fm::test::scratchDir("nifti_units");
    NiftiSpec s = smallSpec();
    s.pixdim[1] = 2, s.pixdim[2] = 3, s.pixdim[3] = 4;
    s.xyztUnits = NIFTI_UNITS_MM;
    expectVec(fm::readVolume(writeSpec(s, dir, "mm.nii")).spacing, {2, 3, 4}, kFloatGeometryTol);
    s.xyztUnits = NIFTI_UNITS_METER | NIFTI_UNITS_SEC;  // time bits must not matter
    s.pixdim[1] = 0.002, s.pixdim[2] = 0.003, s.pixdim[3] = 0.004;
    expectVec(fm::readVolume(writeSpec(s, dir, "m.nii")).spacing, {2, 3, 4}, kFloatGeometryTol);
    s.xyztUnits = NIFTI_UNITS_MICRON;
    s.pixdim[1] = 2000, s.pixdim[2] = 3000, s.pixdim[3] = 4000;
    expectVec(fm::readVolume(writeSpec(s, dir, "um.nii")).spacing, {2, 3, 4}, kFloatGeometryTol);
    s.xyztUnits = 0;  // unknown: millimetres assumed
    s.pixdim[1] = 2, s.pixdim[2] = 3, s.pixdim[3] = 4;
    const fm::Volume v = fm::readVolume(writeSpec(s, dir, "unknown.nii"));
    expectVec(v.spacing, {2, 3, 4}, kFloatGeometryTol);
    expectVec(v.origin, {0, 0, 0}, 0.0);
    EXPECT_EQ(v.meta.units, fm::ValueUnit::Unknown);
}

TEST(NiftiReader, SlopeAndIntercept) {
    const fs::path dir = fm::test::scratchDir("nifti_slope");
    for (int version : {1, 2}) {
        NiftiSpec s = smallSpec(ScalarType::I16);
        s.version = version;
        s.sclSlope = 0.5;
        s.sclInter = -1024;
        const fm::Volume v = fm::readVolume(writeSpec(s, dir, "slope.nii"));
        for (std::size_t n = 0; n < s.values.size(); ++n)
            ASSERT_EQ(v.values[n], static_cast<float>(s.values[n] * 0.5 - 1024)) << n;
        // Slope 0 and NaN both mean "unset": stored values as they are, intercept ignored.
        for (double unset : {0.0, std::numeric_limits<double>::quiet_NaN()}) {
            s.sclSlope = unset;
            expectValues(fm::readVolume(writeSpec(s, dir, "unset.nii")), s.values);
        }
    }
}

TEST(NiftiReader, RescalingBeyondFloatRangeIsRefused) {
    // int16 samples up to 32767 times a float32 slope of 1e38 exceed float range (3.4e38): the
    // file held no infinity, so the voxels would be invented; refused naming the scaling. A
    // float64 NIfTI-2 intercept of -1e300 likewise.
    const fs::path dir = fm::test::scratchDir("nifti_rescale_overflow");
    NiftiSpec s = smallSpec(ScalarType::I16);
    s.sclSlope = 1e38;
    expectError([&] { fm::readVolume(writeSpec(s, dir, "slope.nii")); }, "slope.nii",
                "outside float range once rescaled");
    s.version = 2;
    s.sclSlope = 1.0;
    s.sclInter = -1e300;
    expectError([&] { fm::readVolume(writeSpec(s, dir, "inter.nii")); }, "inter.nii",
                "outside float range once rescaled");
}

TEST(NiftiReader, TwoDimensionalImageIsOneSlice) {
    const fs::path dir = fm::test::scratchDir("nifti_2d");
    NiftiSpec s = smallSpec();
    s.dim = {2, 6, 10};
    const fm::Volume v = fm::readVolume(writeSpec(s, dir, "flat.nii"));
    EXPECT_EQ(v.dims, glm::ivec3(6, 10, 1));
    expectValues(v, s.values);
}

TEST(NiftiReader, RejectsBadFiles) {
    const fs::path dir = fm::test::scratchDir("nifti_bad");
    auto fileOf = [&](const NiftiSpec& s, const std::string& name) {
        return writeSpec(s, dir, name);
    };
    auto read = [](const fs::path& p) { return [p] { fm::readNifti(p); }; };

    for (int dt : {DT_COMPLEX64, DT_COMPLEX128}) {
        NiftiSpec s = smallSpec();
        s.datatype = dt;
        const fs::path p = fileOf(s, "complex.nii");
        expectError(read(p), p, "complex");
    }
    for (int dt : {DT_RGB24, DT_RGBA32}) {
        NiftiSpec s = smallSpec();
        s.datatype = dt;
        const fs::path p = fileOf(s, "rgb.nii");
        expectError(read(p), p, "RGB");
    }
    {
        NiftiSpec s = smallSpec();
        s.datatype = 77;
        const fs::path p = fileOf(s, "unknown_type.nii");
        expectError(read(p), p, "unknown NIfTI datatype");
    }
    {  // data promised but absent (file cut in the middle of the samples)
        Bytes b = smallSpec().bytes();
        b.erase(b.end() - 7, b.end());
        const fs::path p = dir / "truncated.nii";
        fm::test::writeFile(p, b);
        expectError(read(p), p, "truncated");
        fm::test::writeFile(dir / "truncated.nii.gz", fm::test::gzipBytes(b));
        expectError(read(dir / "truncated.nii.gz"), dir / "truncated.nii.gz", "truncated");
    }
    {  // header cut short
        Bytes b = smallSpec().bytes();
        b.resize(200);
        const fs::path p = dir / "short_header.nii";
        fm::test::writeFile(p, b);
        expectError(read(p), p, "truncated NIfTI header");
    }
    {  // sizes far beyond kMaxVoxelCount in a small file: refused before any allocation
        NiftiSpec s = smallSpec();
        s.dim = {3, 32767, 32767, 32767};
        const fs::path p = fileOf(s, "absurd.nii");
        expectError(read(p), p, "exceed the supported maximum");
        NiftiSpec s2 = smallSpec();
        s2.version = 2;
        s2.dim = {3, 1LL << 40, 1LL << 40, 1LL << 40};
        const fs::path p2 = fileOf(s2, "absurd2.nii");
        expectError(read(p2), p2, "invalid dimensions");
    }
    {  // header promising more data than present (dims too big for the file, but allowed)
        NiftiSpec s = smallSpec();
        s.dim = {3, 300, 400, 500};
        const fs::path p = fileOf(s, "more_promised.nii");
        expectError(read(p), p, "truncated");
    }
    {
        NiftiSpec s = smallSpec();
        s.dim = {3, 3, -4, 5};
        const fs::path p = fileOf(s, "negative_dim.nii");
        expectError(read(p), p, "must be positive");
    }
    {
        NiftiSpec s = smallSpec();
        s.dim = {4, 3, 4, 5, 2};
        s.values.resize(120, 0);
        const fs::path p = fileOf(s, "4d.nii");
        expectError(read(p), p, "only 3D volumes");
    }
    for (double bad : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN()}) {
        NiftiSpec s = smallSpec();
        s.pixdim[2] = bad;
        const fs::path p = fileOf(s, "bad_pixdim.nii");
        expectError(read(p), p, "pixdim[2]");
    }
    {
        NiftiSpec s = smallSpec();
        s.sformCode = 1;
        s.srow[1][3] = std::numeric_limits<double>::quiet_NaN();
        const fs::path p = fileOf(s, "nan_srow.nii");
        expectError(read(p), p, "srow");
    }
    {
        NiftiSpec s = smallSpec();
        s.sformCode = 1;
        s.srow[0][1] = 0.5;  // sheared, and no qform to fall back on
        const fs::path p = fileOf(s, "shear.nii");
        expectError(read(p), p, "sheared");
    }
    {
        NiftiSpec s = smallSpec();
        s.qformCode = 1;
        s.quatern[0] = std::numeric_limits<double>::quiet_NaN();
        const fs::path p = fileOf(s, "nan_quatern.nii");
        expectError(read(p), p, "quatern");
    }
    {
        NiftiSpec s = smallSpec();
        s.magicOverride = "xyz";
        const fs::path p = fileOf(s, "analyze.nii");
        expectError(read(p), p, "ANALYZE");
    }
    {
        NiftiSpec s = smallSpec();
        s.voxOffset = 100;
        const fs::path p = fileOf(s, "offset_in_header.nii");
        expectError(read(p), p, "inside the header");
    }
    {
        const fs::path p = dir / "not_nifti.nii";
        fm::test::writeFile(p, std::string(400, 'x'));
        expectError(read(p), p, "not a NIfTI file");
    }
    {
        const fs::path p = dir / "corrupt.nii.gz";
        Bytes gz = fm::test::gzipBytes(smallSpec().bytes());
        for (std::size_t n = 20; n < gz.size() - 8; n += 3) gz[n] ^= 0x5a;
        fm::test::writeFile(p, gz);
        EXPECT_THROW(fm::readNifti(p), fm::Error);
    }
    expectError([&] { fm::readNifti(dir / "missing.nii"); }, dir / "missing.nii", "not found");
}

}  // namespace

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "IoTestFiles.h"
#include "TestExpect.h"
#include "common/TestData.h"
#include "io/MetaImageReader.h"
#include "io/ReadVolume.h"

namespace {

namespace fs = std::filesystem;
using fm::test::Bytes;
using fm::test::expectError;
using fm::test::expectValues;
using fm::test::expectVec;
using fm::test::ScalarType;

// Geometry is written as short decimal text and parsed back as double: exact up to rounding.
constexpr double kTextGeometryTol = 1e-12;

const char* metType(ScalarType t) {
    switch (t) {
        case ScalarType::U8:
            return "MET_UCHAR";
        case ScalarType::I8:
            return "MET_CHAR";
        case ScalarType::U16:
            return "MET_USHORT";
        case ScalarType::I16:
            return "MET_SHORT";
        case ScalarType::U32:
            return "MET_UINT";
        case ScalarType::I32:
            return "MET_INT";
        case ScalarType::U64:
            return "MET_ULONG_LONG";
        case ScalarType::I64:
            return "MET_LONG_LONG";
        case ScalarType::F32:
            return "MET_FLOAT";
        case ScalarType::F64:
            return "MET_DOUBLE";
    }
    return "";
}

struct MetaSpec {
    ScalarType type = ScalarType::I16;
    bool msb = false;
    bool compressed = false;
    std::string dims = "3 4 5";
    std::string extra;  // extra header lines
    std::string dataFile = "LOCAL";
    std::vector<double> values = fm::test::sampleValues(ScalarType::I16, 60);

    std::string header() const {
        std::string h =
            "ObjectType = Image\nNDims = " +
            std::to_string(std::count(dims.begin(), dims.end(), ' ') + 1) +
            "\nBinaryData = True\nBinaryDataByteOrderMSB = " + (msb ? "True" : "False") +
            "\nCompressedData = " + (compressed ? "True" : "False") + "\n" + extra +
            "DimSize = " + dims + "\nElementType = " + metType(type) +
            "\nElementDataFile = " + dataFile + "\n";
        return h;
    }
    Bytes samples() const {
        const Bytes raw = fm::test::encodeSamples(values, type, msb);
        return compressed ? fm::test::zlibBytes(raw) : raw;
    }
    Bytes bytes() const { return fm::test::concat(fm::test::toBytes(header()), samples()); }
};

TEST(MetaImageReader, EveryElementTypeBothByteOrdersCompressedOrNot) {
    const fs::path dir = fm::test::scratchDir("mha_types");
    for (bool compressed : {false, true})
        for (bool msb : {false, true})
            for (ScalarType type : fm::test::allScalarTypes()) {
                MetaSpec s;
                s.type = type;
                s.msb = msb;
                s.compressed = compressed;
                s.values = fm::test::sampleValues(type, 60);
                const fs::path p = dir / "t.mha";
                fm::test::writeFile(p, s.bytes());
                SCOPED_TRACE(std::string(metType(type)) + (msb ? " msb" : "") +
                             (compressed ? " compressed" : ""));
                const fm::Volume v = fm::readVolume(p);
                EXPECT_EQ(v.dims, glm::ivec3(3, 4, 5));
                expectValues(v, s.values);
            }
}

// Uncompressed samples are read and converted in 4 MiB pieces (volumeFromFile): 2.25 M
// samples are two pieces of int16 and five of double, the last one partial, in both byte orders.
TEST(MetaImageReader, SamplesSpanningSeveralReadPiecesConvertExactly) {
    const fs::path dir = fm::test::scratchDir("mha_pieces");
    for (ScalarType type : {ScalarType::I16, ScalarType::F64})
        for (bool msb : {false, true}) {
            MetaSpec s;
            s.type = type;
            s.msb = msb;
            s.dims = "160 128 110";
            s.values = fm::test::sampleValues(type, 160 * 128 * 110);
            const fs::path p = dir / "big.mha";
            fm::test::writeFile(p, s.bytes());
            SCOPED_TRACE(std::string(metType(type)) + (msb ? " msb" : ""));
            const fm::Volume v = fm::readVolume(p);
            EXPECT_EQ(v.dims, glm::ivec3(160, 128, 110));
            expectValues(v, s.values);
        }
}

TEST(MetaImageReader, GeometryIsLpsAsWritten) {
    const fs::path dir = fm::test::scratchDir("mha_geometry");
    MetaSpec s;
    // Axis i along +y, j along -x, k along +z (each group of three is one axis).
    s.extra =
        "TransformMatrix = 0 1 0 -1 0 0 0 0 1\nOffset = 1.5 -2.25 300\n"
        "ElementSpacing = 0.5 0.75 2\nAnatomicalOrientation = PLS\nModality = MET_MOD_CT\n";
    fm::test::writeFile(dir / "g.mha", s.bytes());
    const fm::Volume v = fm::readVolume(dir / "g.mha");
    expectVec(v.origin, {1.5, -2.25, 300}, kTextGeometryTol);
    expectVec(v.spacing, {0.5, 0.75, 2}, kTextGeometryTol);
    expectVec(v.direction[0], {0, 1, 0}, kTextGeometryTol);
    expectVec(v.direction[1], {-1, 0, 0}, kTextGeometryTol);
    expectVec(v.direction[2], {0, 0, 1}, kTextGeometryTol);
    EXPECT_EQ(fm::orientationCode(v.direction), "PRS");
    EXPECT_EQ(v.meta.modality, "CT");
    // The 3D point of voxel (1, 2, 3): origin + i*0.5*(0,1,0) + 2*0.75*(-1,0,0) + 3*2*(0,0,1).
    expectVec(v.indexToWorld({1, 2, 3}), {1.5 - 1.5, -2.25 + 0.5, 306}, kTextGeometryTol);
}

TEST(MetaImageReader, DetachedDataFilesAndAscii) {
    const fs::path dir = fm::test::scratchDir("mhd_detached");
    MetaSpec s;
    // One raw file with a 16-byte preamble skipped by HeaderSize.
    s.dataFile = "g.raw";
    s.extra = "HeaderSize = 16\n";
    fm::test::writeFile(dir / "g.mhd", s.header());
    fm::test::writeFile(dir / "g.raw", fm::test::concat(Bytes(16, 0xee), s.samples()));
    expectValues(fm::readVolume(dir / "g.mhd"), s.values);

    // HeaderSize = -1: the data is at the end of the file, whatever precedes it.
    s.extra = "HeaderSize = -1\n";
    fm::test::writeFile(dir / "g.mhd", s.header());
    fm::test::writeFile(dir / "g.raw", fm::test::concat(Bytes(37, 0xee), s.samples()));
    expectValues(fm::readVolume(dir / "g.mhd"), s.values);

    // Compressed detached file.
    s.extra = "";
    s.compressed = true;
    fm::test::writeFile(dir / "g.mhd", s.header());
    fm::test::writeFile(dir / "g.raw", s.samples());
    expectValues(fm::readVolume(dir / "g.mhd"), s.values);
    s.compressed = false;

    // One file per slice, by pattern and by LIST.
    const Bytes all = s.samples();
    const std::size_t perSlice = all.size() / 5;
    for (int k = 0; k < 5; ++k)
        fm::test::writeFile(dir / ("slice" + std::to_string(100 + 2 * k) + ".raw"),
                            Bytes(all.begin() + k * perSlice, all.begin() + (k + 1) * perSlice));
    s.dataFile = "slice%03d.raw 100 108 2";
    fm::test::writeFile(dir / "p.mhd", s.header());
    expectValues(fm::readVolume(dir / "p.mhd"), s.values);
    s.dataFile = "LIST 2D\nslice100.raw\nslice102.raw\nslice104.raw\nslice106.raw\nslice108.raw";
    fm::test::writeFile(dir / "l.mhd", s.header());
    expectValues(fm::readVolume(dir / "l.mhd"), s.values);

    // ASCII data (BinaryData = False).
    std::string ascii =
        "ObjectType = Image\nNDims = 3\nDimSize = 2 2 1\nBinaryData = False\n"
        "ElementType = MET_FLOAT\nElementDataFile = LOCAL\n1.5 -2\n 3e2\t4\n";
    fm::test::writeFile(dir / "a.mha", ascii);
    expectValues(fm::readVolume(dir / "a.mha"), {1.5, -2, 300, 4});

    // NDims = 2: a single slice.
    MetaSpec flat;
    flat.dims = "6 10";
    fm::test::writeFile(dir / "flat.mha", flat.bytes());
    const fm::Volume v = fm::readVolume(dir / "flat.mha");
    EXPECT_EQ(v.dims, glm::ivec3(6, 10, 1));
    expectValues(v, flat.values);
}

TEST(MetaImageReader, RejectsBadFiles) {
    const fs::path dir = fm::test::scratchDir("mha_bad");
    auto check = [&](const MetaSpec& s, const std::string& name, const std::string& fragment) {
        const fs::path p = dir / name;
        fm::test::writeFile(p, s.bytes());
        expectError([&] { fm::readMetaImage(p); }, p, fragment);
    };
    MetaSpec s;
    s.extra = "ElementNumberOfChannels = 3\n";
    check(s, "rgb.mha", "ElementNumberOfChannels");
    s.extra = "ElementSpacing = 1 nan 1\n";
    check(s, "nan_spacing.mha", "ElementSpacing: 'nan' is not finite");
    s.extra = "ElementSpacing = 1 0 1\n";
    check(s, "zero_spacing.mha", "spacing must be positive");
    s.extra = "ElementSpacing = 1 -2 1\n";
    check(s, "negative_spacing.mha", "spacing must be positive");
    s.extra = "Offset = 0 inf 0\n";
    check(s, "inf_offset.mha", "not finite");
    s.extra = "TransformMatrix = 1 1 0 0 1 0 0 0 1\n";
    check(s, "skew.mha", "orthonormal");
    s.extra = "";

    MetaSpec unknownType;
    std::string h = unknownType.header();
    h.replace(h.find("MET_SHORT"), 9, "MET_QUAT");
    fm::test::writeFile(dir / "type.mha",
                        fm::test::concat(fm::test::toBytes(h), unknownType.samples()));
    expectError([&] { fm::readMetaImage(dir / "type.mha"); }, dir / "type.mha", "ElementType");

    MetaSpec truncated;
    Bytes b = truncated.bytes();
    b.erase(b.end() - 1, b.end());
    fm::test::writeFile(dir / "truncated.mha", b);
    expectError([&] { fm::readMetaImage(dir / "truncated.mha"); }, dir / "truncated.mha",
                "truncated");

    MetaSpec compressedShort;
    compressedShort.compressed = true;
    Bytes c = compressedShort.bytes();
    c.erase(c.end() - 20, c.end());
    fm::test::writeFile(dir / "ctrunc.mha", c);
    EXPECT_THROW(fm::readMetaImage(dir / "ctrunc.mha"), fm::Error);

    MetaSpec absurd;
    absurd.dims = "100000 100000 100000";
    check(absurd, "absurd.mha", "exceed the supported maximum");
    absurd.dims = "300 300 300";  // allowed size, but the file holds 120 bytes
    check(absurd, "promised.mha", "truncated");
    // Just under the voxel limit (4 GB of floats): refused from the file size, before the volume
    // is allocated.
    absurd.dims = "1024 1024 1000";
    check(absurd, "promised_huge.mha", "truncated");
    absurd.dims = "3 -4 5";
    check(absurd, "negative.mha", "positive integers");
    MetaSpec count;
    std::string countHeader = count.header();
    countHeader.replace(countHeader.find("DimSize = 3 4 5"), 15, "DimSize = 3 4");
    fm::test::writeFile(dir / "count.mha",
                        fm::test::concat(fm::test::toBytes(countHeader), count.samples()));
    expectError([&] { fm::readMetaImage(dir / "count.mha"); }, dir / "count.mha",
                "expected 3 numbers");

    MetaSpec missingFile;
    missingFile.dataFile = "nowhere.raw";
    fm::test::writeFile(dir / "missing.mhd", missingFile.header());
    expectError([&] { fm::readMetaImage(dir / "missing.mhd"); }, dir / "nowhere.raw", "not found");

    MetaSpec badList;
    badList.dataFile = "slice%d.raw 1 1000000000 1";
    check(badList, "biglist.mhd", "invalid range");
    badList.dataFile = "slice%s.raw 1 5 1";
    check(badList, "format.mhd", "integer conversion");

    fm::test::writeFile(dir / "noheader.mha", std::string("NDims = 3\nDimSize = 1 1 1\n"));
    expectError([&] { fm::readMetaImage(dir / "noheader.mha"); }, dir / "noheader.mha",
                "ElementDataFile");
}

}  // namespace

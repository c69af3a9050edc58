#include <gtest/gtest.h>

#include <sstream>

#include "IoTestFiles.h"
#include "TestExpect.h"
#include "common/TestData.h"
#include "io/NrrdReader.h"
#include "io/ReadVolume.h"

namespace {

namespace fs = std::filesystem;
using fm::test::Bytes;
using fm::test::expectError;
using fm::test::expectValues;
using fm::test::expectVec;
using fm::test::ScalarType;

constexpr double kTextGeometryTol = 1e-12;  // decimal text parsed to double

// One NRRD type name per scalar type, plus synonyms checked separately.
const char* nrrdType(ScalarType t) {
    switch (t) {
        case ScalarType::U8:
            return "uchar";
        case ScalarType::I8:
            return "signed char";
        case ScalarType::U16:
            return "unsigned short";
        case ScalarType::I16:
            return "short";
        case ScalarType::U32:
            return "uint";
        case ScalarType::I32:
            return "int32_t";
        case ScalarType::U64:
            return "unsigned long long int";
        case ScalarType::I64:
            return "longlong";
        case ScalarType::F32:
            return "float";
        case ScalarType::F64:
            return "double";
    }
    return "";
}

struct NrrdSpec {
    ScalarType type = ScalarType::I16;
    std::string typeName;  // overrides nrrdType(type) when set
    bool bigEndian = false;
    std::string encoding = "raw";
    std::string sizes = "3 4 5";
    int dimension = 3;
    std::string geometry = "spacings: 1 1 1\n";
    std::string extra;
    std::vector<double> values = fm::test::sampleValues(ScalarType::I16, 60);

    std::string header(const std::string& dataFile = "") const {
        std::ostringstream h;
        h << "NRRD0004\n# a comment\ntype: " << (typeName.empty() ? nrrdType(type) : typeName)
          << "\ndimension: " << dimension << "\nsizes: " << sizes << "\n"
          << geometry << "endian: " << (bigEndian ? "big" : "little") << "\nencoding: " << encoding
          << "\n"
          << extra;
        if (!dataFile.empty()) h << "data file: " << dataFile << "\n";
        return h.str();
    }
    Bytes samples() const {
        if (encoding == "ascii" || encoding == "text") {
            std::ostringstream t;
            t.precision(17);
            for (std::size_t n = 0; n < values.size(); ++n)
                t << values[n] << (n % 7 == 6 ? "\n" : " ");
            return fm::test::toBytes(t.str());
        }
        const Bytes raw = fm::test::encodeSamples(values, type, bigEndian);
        return encoding == "gzip" ? fm::test::gzipBytes(raw) : raw;
    }
    Bytes attached() const {
        return fm::test::concat(fm::test::toBytes(header() + "\n"), samples());
    }
};

TEST(NrrdReader, EveryTypeEndianAndEncodingAttached) {
    const fs::path dir = fm::test::scratchDir("nrrd_types");
    for (const char* encoding : {"raw", "gzip", "ascii"})
        for (bool big : {false, true})
            for (ScalarType type : fm::test::allScalarTypes()) {
                NrrdSpec s;
                s.type = type;
                s.bigEndian = big;
                s.encoding = encoding;
                s.values = fm::test::sampleValues(type, 60);
                fm::test::writeFile(dir / "t.nrrd", s.attached());
                SCOPED_TRACE(std::string(nrrdType(type)) + " " + encoding + (big ? " big" : ""));
                const fm::Volume v = fm::readVolume(dir / "t.nrrd");
                EXPECT_EQ(v.dims, glm::ivec3(3, 4, 5));
                expectValues(v, s.values);
            }
}

TEST(NrrdReader, TypeSynonyms) {
    const fs::path dir = fm::test::scratchDir("nrrd_synonyms");
    const std::vector<std::pair<std::string, ScalarType>> synonyms = {
        {"unsigned char", ScalarType::U8},
        {"uint8_t", ScalarType::U8},
        {"int8", ScalarType::I8},
        {"short int", ScalarType::I16},
        {"signed short int", ScalarType::I16},
        {"int16_t", ScalarType::I16},
        {"ushort", ScalarType::U16},
        {"uint16", ScalarType::U16},
        {"int", ScalarType::I32},
        {"signed int", ScalarType::I32},
        {"unsigned int", ScalarType::U32},
        {"uint32_t", ScalarType::U32},
        {"long long", ScalarType::I64},
        {"int64", ScalarType::I64},
        {"ulonglong", ScalarType::U64},
        {"uint64_t", ScalarType::U64},
    };
    for (const auto& [name, type] : synonyms) {
        NrrdSpec s;
        s.type = type;
        s.typeName = name;
        s.values = fm::test::sampleValues(type, 60);
        fm::test::writeFile(dir / "s.nrrd", s.attached());
        SCOPED_TRACE(name);
        expectValues(fm::readVolume(dir / "s.nrrd"), s.values);
    }
}

TEST(NrrdReader, SpaceDirectionsOriginAndSpaces) {
    const fs::path dir = fm::test::scratchDir("nrrd_space");
    NrrdSpec s;
    // RAS: i along anterior (0,2,0), j along left (-3,0,0), k superior (0,0,4).
    s.geometry =
        "space: right-anterior-superior\nspace directions: (0,2,0) (-3, 0, 0) (0,0,4)\n"
        "space origin: (10,-20,30)\n";
    fm::test::writeFile(dir / "ras.nrrd", s.attached());
    fm::Volume v = fm::readVolume(dir / "ras.nrrd");
    expectVec(v.spacing, {2, 3, 4}, kTextGeometryTol);
    expectVec(v.origin, {-10, 20, 30}, kTextGeometryTol);  // x, y negated into LPS
    expectVec(v.direction[0], {0, -1, 0}, kTextGeometryTol);
    expectVec(v.direction[1], {1, 0, 0}, kTextGeometryTol);
    EXPECT_EQ(fm::orientationCode(v.direction), "ALS");

    s.geometry =
        "space: LPS\nspace directions: (0,2,0) (-3,0,0) (0,0,4)\nspace origin: (10,-20,30)\n";
    fm::test::writeFile(dir / "lps.nrrd", s.attached());
    v = fm::readVolume(dir / "lps.nrrd");
    expectVec(v.origin, {10, -20, 30}, kTextGeometryTol);
    EXPECT_EQ(fm::orientationCode(v.direction), "PRS");

    s.geometry = "space: left-anterior-superior\nspace directions: (1,0,0) (0,1,0) (0,0,1)\n";
    fm::test::writeFile(dir / "las.nrrd", s.attached());
    EXPECT_EQ(fm::orientationCode(fm::readVolume(dir / "las.nrrd").direction), "LAS");

    // A leading 1-sample component axis ("none") is dropped.
    s.dimension = 4;
    s.sizes = "1 3 4 5";
    s.geometry =
        "space: 3D-right-handed\nspace directions: none (1,0,0) (0,1,0) (0,0,1)\n"
        "kinds: vector domain domain domain\n";
    fm::test::writeFile(dir / "vec1.nrrd", s.attached());
    v = fm::readVolume(dir / "vec1.nrrd");
    EXPECT_EQ(v.dims, glm::ivec3(3, 4, 5));
    expectValues(v, s.values);
}

TEST(NrrdReader, DetachedFilesListsAndSkips) {
    const fs::path dir = fm::test::scratchDir("nrrd_detached");
    NrrdSpec s;
    const Bytes all = s.samples();

    // Single detached file with line skip and byte skip.
    fm::test::writeFile(dir / "one.raw",
                        fm::test::concat(fm::test::toBytes("junk line\nmore junk\nXYZ"), all));
    s.extra = "line skip: 2\nbyte skip: 3\n";
    fm::test::writeFile(dir / "one.nhdr", s.header("one.raw"));
    expectValues(fm::readVolume(dir / "one.nhdr"), s.values);

    // byte skip -1: the data is at the end of the file.
    s.extra = "byte skip: -1\n";
    fm::test::writeFile(dir / "tail.raw", fm::test::concat(Bytes(123, 7), all));
    fm::test::writeFile(dir / "tail.nhdr", s.header("tail.raw"));
    expectValues(fm::readVolume(dir / "tail.nhdr"), s.values);
    s.extra = "";

    // Numbered slice files, counting down, zero padded.
    const std::size_t perSlice = all.size() / 5;
    for (int k = 0; k < 5; ++k)
        fm::test::writeFile(dir / ("sl" + std::to_string(10 + (4 - k)) + ".raw"),
                            Bytes(all.begin() + k * perSlice, all.begin() + (k + 1) * perSlice));
    fm::test::writeFile(dir / "down.nhdr", s.header("sl%02d.raw 14 10 -1"));
    expectValues(fm::readVolume(dir / "down.nhdr"), s.values);
    // subdim 2 given explicitly.
    fm::test::writeFile(dir / "sub.nhdr", s.header("sl%d.raw 14 10 -1 2"));
    expectValues(fm::readVolume(dir / "sub.nhdr"), s.values);

    // LIST: the rest of the header names the files.
    fm::test::writeFile(dir / "list.nhdr",
                        s.header("LIST") + "sl14.raw\nsl13.raw\nsl12.raw\nsl11.raw\nsl10.raw\n");
    expectValues(fm::readVolume(dir / "list.nhdr"), s.values);

    // gzip-compressed detached file.
    NrrdSpec g;
    g.encoding = "gzip";
    fm::test::writeFile(dir / "g.raw.gz", g.samples());
    fm::test::writeFile(dir / "g.nhdr", g.header("g.raw.gz"));
    expectValues(fm::readVolume(dir / "g.nhdr"), g.values);
}

TEST(NrrdReader, RejectsBadFiles) {
    const fs::path dir = fm::test::scratchDir("nrrd_bad");
    auto check = [&](const NrrdSpec& s, const std::string& name, const std::string& fragment) {
        const fs::path p = dir / name;
        fm::test::writeFile(p, s.attached());
        expectError([&] { fm::readNrrd(p); }, p, fragment);
    };
    NrrdSpec s;
    s.typeName = "block";
    check(s, "block.nrrd", "unsupported NRRD type");
    s.typeName = "";
    s.encoding = "bzip2";
    check(s, "bzip.nrrd", "encoding");
    s.encoding = "raw";
    s.geometry = "spacings: 1 nan 1\n";
    check(s, "nan_spacing.nrrd", "not spatial");  // NaN marks a non-spatial axis, size 4 > 1
    s.geometry = "spacings: 1 0 1\n";
    check(s, "zero_spacing.nrrd", "must be positive");
    s.geometry = "space: RAS\nspace directions: (1,0,0) (0,0,0) (0,0,1)\n";
    check(s, "zero_direction.nrrd", "zero length");
    s.geometry = "space: RAS\nspace directions: (1,0,0) (0,1,0) (0,0,1)\nspace origin: (0,nan,0)\n";
    check(s, "nan_origin.nrrd", "not finite");
    s.geometry = "space: moon-centric\n";
    check(s, "space.nrrd", "unsupported NRRD space");
    s.geometry = "spacings: 1 1 1\n";
    s.sizes = "100000 100000 100000";
    check(s, "absurd.nrrd", "exceed the supported maximum");
    s.sizes = "300 300 300";
    check(s, "promised.nrrd", "truncated");
    s.sizes = "3 4 5";
    s.encoding = "gzip";
    {
        Bytes b = s.attached();
        b.erase(b.end() - 30, b.end());
        fm::test::writeFile(dir / "gz_truncated.nrrd", b);
        EXPECT_THROW(fm::readNrrd(dir / "gz_truncated.nrrd"), fm::Error);
    }
    s.encoding = "ascii";
    {
        Bytes b = s.attached();
        b.erase(b.end() - 40, b.end());
        fm::test::writeFile(dir / "ascii_truncated.nrrd", b);
        expectError([&] { fm::readNrrd(dir / "ascii_truncated.nrrd"); },
                    dir / "ascii_truncated.nrrd", "truncated");
    }
    s.encoding = "raw";
    s.dimension = 4;
    s.sizes = "3 3 4 5";
    s.geometry = "kinds: RGB-color domain domain domain\n";
    check(s, "rgb.nrrd", "multi-component");
    {
        const fs::path p = dir / "no_endian.nrrd";
        fm::test::writeFile(p,
                            "NRRD0004\ntype: short\ndimension: 1\nsizes: 2\nencoding: raw\n\nabcd");
        expectError([&] { fm::readNrrd(p); }, p, "'endian' is missing");
        fm::test::writeFile(
            p, "NRRD0004\ntype: short\ndimension: 1\nencoding: raw\nendian: big\n\nab");
        expectError([&] { fm::readNrrd(p); }, p, "'sizes' is missing");
        fm::test::writeFile(p,
                            "NRRD0004\ntype: short\ndimension: 1\nsizes: 2\nendian: little\n"
                            "encoding: raw\ndata file: x%d 1 2000000000 1\n");
        expectError([&] { fm::readNrrd(p); }, p, "invalid range");
        fm::test::writeFile(p,
                            "NRRD0004\ntype: short\ndimension: 2\nsizes: 2 2\nendian: little\n"
                            "encoding: raw\ndata file: missing%d.raw 1 2 1\n");
        expectError([&] { fm::readNrrd(p); }, "missing1.raw", "not found");
        fm::test::writeFile(p,
                            "NRRD0004\ntype: short\ndimension: 2\nsizes: 2 2\nendian: little\n"
                            "encoding: raw\nline skip: 5\ndata file: one.raw\n");
        fm::test::writeFile(dir / "one.raw", std::string("a\nb\n12345678"));
        expectError([&] { fm::readNrrd(p); }, "one.raw", "truncated");
        fm::test::writeFile(p, "NRRD0004 \ngarbage");
        expectError([&] { fm::readNrrd(p); }, p, "not a NRRD file");
    }
}

}  // namespace

#include <gtest/gtest.h>

#include <sstream>

#include "IoTestFiles.h"
#include "TestExpect.h"
#include "common/TestData.h"
#include "io/ReadVolume.h"
#include "io/VtkReader.h"

namespace {

namespace fs = std::filesystem;
using fm::test::Bytes;
using fm::test::expectError;
using fm::test::expectValues;
using fm::test::expectVec;
using fm::test::ScalarType;

constexpr double kVtkTextGeometryTol = 1e-12;  // decimal text parsed to double

const char* vtkType(ScalarType t) {
    switch (t) {
        case ScalarType::U8:
            return "unsigned_char";
        case ScalarType::I8:
            return "char";
        case ScalarType::U16:
            return "unsigned_short";
        case ScalarType::I16:
            return "short";
        case ScalarType::U32:
            return "unsigned_int";
        case ScalarType::I32:
            return "int";
        case ScalarType::U64:
            return "vtktypeuint64";
        case ScalarType::I64:
            return "vtktypeint64";
        case ScalarType::F32:
            return "float";
        case ScalarType::F64:
            return "double";
    }
    return "";
}

struct VtkSpec {
    ScalarType type = ScalarType::I16;
    bool binary = true;
    std::string dims = "3 4 5";
    std::string points = "60";
    std::string geometry = "ASPECT_RATIO 1.0 1.0 1.0\nORIGIN 0.0 0.0 0.0\n";
    std::string scalarsExtra;  // e.g. " 1"
    bool lookupTable = true;
    std::vector<double> values = fm::test::sampleValues(ScalarType::I16, 60);

    Bytes bytes() const {
        std::ostringstream h;
        h << "# vtk DataFile Version 1.0\nmade by a test\n"
          << (binary ? "BINARY" : "ASCII") << "\nDATASET STRUCTURED_POINTS\nDIMENSIONS " << dims
          << "\n"
          << geometry << "POINT_DATA " << points << "\nSCALARS scalars " << vtkType(type)
          << scalarsExtra << "\n"
          << (lookupTable ? "LOOKUP_TABLE default\n" : "");
        if (binary)
            return fm::test::concat(fm::test::toBytes(h.str()),
                                    fm::test::encodeSamples(values, type, true));  // big-endian
        h.precision(17);
        for (std::size_t n = 0; n < values.size(); ++n) h << values[n] << (n % 9 == 8 ? "\n" : " ");
        return fm::test::toBytes(h.str());
    }
};

TEST(VtkReader, BinaryBigEndianAndAsciiEveryType) {
    const fs::path dir = fm::test::scratchDir("vtk_types");
    for (bool binary : {true, false})
        for (ScalarType type : fm::test::allScalarTypes()) {
            VtkSpec s;
            s.type = type;
            s.binary = binary;
            s.values = fm::test::sampleValues(type, 60);
            fm::test::writeFile(dir / "t.vtk", s.bytes());
            SCOPED_TRACE(std::string(vtkType(type)) + (binary ? " binary" : " ascii"));
            const fm::Volume v = fm::readVolume(dir / "t.vtk");
            EXPECT_EQ(v.dims, glm::ivec3(3, 4, 5));
            expectValues(v, s.values);
        }
}

TEST(VtkReader, GeometryKeywordsAndOptionalParts) {
    const fs::path dir = fm::test::scratchDir("vtk_geometry");
    VtkSpec s;
    s.geometry = "SPACING 0.5 0.75 2\nORIGIN -1 2.5 100\n";
    s.scalarsExtra = " 1";
    s.lookupTable = false;  // some writers omit it; data follows SCALARS directly
    fm::test::writeFile(dir / "g.vtk", s.bytes());
    fm::Volume v = fm::readVolume(dir / "g.vtk");
    expectVec(v.spacing, {0.5, 0.75, 2}, kVtkTextGeometryTol);
    expectVec(v.origin, {-1, 2.5, 100}, kVtkTextGeometryTol);
    EXPECT_EQ(fm::orientationCode(v.direction), "LPS");
    expectValues(v, s.values);

    // VTK 9 DIRECTION: row-major 3x3 whose columns are the axes (i along +y, j along -x).
    s.geometry = "ASPECT_RATIO 1 2 3\nDIRECTION 0 -1 0 1 0 0 0 0 1\n";
    fm::test::writeFile(dir / "d.vtk", s.bytes());
    v = fm::readVolume(dir / "d.vtk");
    expectVec(v.spacing, {1, 2, 3}, kVtkTextGeometryTol);
    expectVec(v.direction[0], {0, 1, 0}, kVtkTextGeometryTol);
    expectVec(v.direction[1], {-1, 0, 0}, kVtkTextGeometryTol);
}

TEST(VtkReader, RejectsBadFiles) {
    const fs::path dir = fm::test::scratchDir("vtk_bad");
    auto check = [&](const VtkSpec& s, const std::string& name, const std::string& fragment) {
        const fs::path p = dir / name;
        fm::test::writeFile(p, s.bytes());
        expectError([&] { fm::readLegacyVtk(p); }, p, fragment);
    };
    VtkSpec s;
    s.points = "61";
    check(s, "points.vtk", "POINT_DATA 61 does not match");
    s.points = "60";
    s.geometry = "SPACING 1 nan 1\n";
    check(s, "nan.vtk", "not finite");
    s.geometry = "SPACING 1 0 1\n";
    check(s, "zero.vtk", "spacing must be positive");
    s.geometry = "SPACING 1 1\n";
    check(s, "short_spacing.vtk", "needs 3 values");
    s.geometry = "";
    s.dims = "100000 100000 100000";
    s.points = "1000000000000000";
    check(s, "absurd.vtk", "exceed the supported maximum");
    s.dims = "300 300 300";
    s.points = "27000000";
    check(s, "promised.vtk", "truncated");
    s.binary = false;
    check(s, "promised_ascii.vtk", "truncated");
    s.binary = true;
    s.dims = "3 4 5";
    s.points = "60";
    {
        Bytes b = s.bytes();
        b.erase(b.end() - 1, b.end());
        fm::test::writeFile(dir / "truncated.vtk", b);
        expectError([&] { fm::readLegacyVtk(dir / "truncated.vtk"); }, dir / "truncated.vtk",
                    "truncated");
    }
    s.scalarsExtra = " 3";
    check(s, "components.vtk", "one scalar component");
    s.scalarsExtra = "";
    {
        const fs::path p = dir / "other.vtk";
        fm::test::writeFile(
            p, "# vtk DataFile Version 3.0\nx\nASCII\nDATASET POLYDATA\nPOINTS 0 float\n");
        expectError([&] { fm::readLegacyVtk(p); }, p, "STRUCTURED_POINTS");
        fm::test::writeFile(p,
                            "# vtk DataFile Version 3.0\nx\nASCII\nDATASET STRUCTURED_POINTS\n"
                            "DIMENSIONS 1 1 1\nPOINT_DATA 1\nSCALARS s long\n1\n");
        expectError([&] { fm::readLegacyVtk(p); }, p, "unsupported VTK scalar type");
        fm::test::writeFile(p,
                            "# vtk DataFile Version 3.0\nx\nASCII\nDATASET STRUCTURED_POINTS\n"
                            "DIMENSIONS 2 1 1\nPOINT_DATA 2\nSCALARS s float\n1 x\n");
        expectError([&] { fm::readLegacyVtk(p); }, p, "is not a number");
        fm::test::writeFile(p,
                            "# vtk DataFile Version 3.0\nx\nBINARY\nDATASET STRUCTURED_POINTS\n");
        expectError([&] { fm::readLegacyVtk(p); }, p, "DIMENSIONS");
    }
}

}  // namespace

// The STL, PLY and OBJ readers: round trips through our writer, hand-written files in the
// variants other tools write, and refusals of bad files (fm::Error naming the file and field).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <string>

#include "common/TestData.h"
#include "common/TestMeshes.h"
#include "core/Error.h"
#include "model/MeshFile.h"
#include "model/MeshWriter.h"
#include "model/WeldVertices.h"

namespace {

namespace fs = std::filesystem;
using Bytes = std::vector<std::uint8_t>;

void writeText(const fs::path& p, const std::string& s) {
    std::ofstream(p, std::ios::binary) << s;
}
void writeBytes(const fs::path& p, const Bytes& b) {
    std::ofstream(p, std::ios::binary).write(reinterpret_cast<const char*>(b.data()), b.size());
}
template <class T>
void append(Bytes& b, T v, bool bigEndian = false) {
    std::uint8_t raw[sizeof(T)];
    std::memcpy(raw, &v, sizeof(T));
    if (bigEndian)
        for (std::size_t i = 0; i < sizeof(T); ++i) b.push_back(raw[sizeof(T) - 1 - i]);
    else
        b.insert(b.end(), raw, raw + sizeof(T));
}

// The same geometry: every triangle's corners, as positions (order-independent of indexing).
void expectSameTriangles(const fm::Mesh& a, const fm::Mesh& b) {
    ASSERT_EQ(a.triangles.size(), b.triangles.size());
    for (std::size_t t = 0; t < a.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k)
            EXPECT_EQ(a.positions[a.triangles[t][k]], b.positions[b.triangles[t][k]]) << t << " " << k;
}

std::string expectError(const fs::path& p) {
    try {
        fm::readMeshFile(p);
    } catch (const fm::Error& e) {
        EXPECT_NE(std::string(e.what()).find(p.filename().string()), std::string::npos)
            << "message does not name the file: " << e.what();
        return e.what();
    }
    ADD_FAILURE() << p << " was accepted";
    return "";
}

TEST(MeshReader, RoundTripThroughOurWriter) {
    const fs::path dir = fm::test::scratchDir("mesh_reader_roundtrip");
    const fm::Mesh sphere = fm::test::uvSphereMesh({1.5f, -2.f, 3.f}, 10.f, 8, 12);
    for (const char* ext : {".stl", ".ply", ".obj"}) {
        const fs::path p = dir / (std::string("sphere") + ext);
        fm::writeMesh(sphere, p);
        const fm::Mesh back = fm::readMeshFile(p);
        expectSameTriangles(sphere, back);
        const fm::Mesh welded = fm::weldVertices(back);
        EXPECT_EQ(welded.positions.size(), sphere.positions.size()) << ext;
    }
}

TEST(MeshReader, AsciiStlLikeStlwrite) {
    const fs::path p = fm::test::scratchDir("mesh_reader_ascii_stl") / "tri.stl";
    writeText(p,
              "solid Created by stlwrite.m 09-Apr-2020 13:39:07\n"
              "facet normal 0.0000000E+00 0.0000000E+00 1.0000000E+00\nouter loop\n"
              "vertex 0.0000000E+00 0.0000000E+00 0.0000000E+00\n"
              "vertex 1.0000000E+00 0.0000000E+00 0.0000000E+00\n"
              "vertex 0.0000000E+00 2.5000000E+00 -1.0E-01\nendloop\nendfacet\n"
              "  FACET NORMAL 0 0 1\r\n OUTER LOOP\r\n VERTEX 1 0 0\r\n VERTEX 1 1 0\r\n"
              " VERTEX +0 1 0\r\n ENDLOOP\r\n ENDFACET\r\n"
              "endsolid Created by stlwrite.m\n");
    const fm::Mesh m = fm::readMeshFile(p);
    ASSERT_EQ(m.triangles.size(), 2u);
    EXPECT_EQ(m.positions.size(), 6u);
    EXPECT_EQ(m.positions[2], glm::vec3(0.f, 2.5f, -0.1f));
    EXPECT_EQ(m.positions[4], glm::vec3(1.f, 1.f, 0.f));
}

// SolidWorks and some CAD exporters write the keywords upper-case, "SOLID" included; editors on
// Windows may put a UTF-8 byte-order mark first. Both are ASCII STL, not a corrupt binary.
TEST(MeshReader, AsciiStlInUpperCaseAndWithByteOrderMark) {
    const fs::path dir = fm::test::scratchDir("mesh_reader_upper_stl");
    const std::string body =
        "SOLID PART1\nFACET NORMAL 0 0 1\nOUTER LOOP\nVERTEX 0 0 0\nVERTEX 1 0 0\nVERTEX 0 1 0\n"
        "ENDLOOP\nENDFACET\nENDSOLID PART1\n";
    writeText(dir / "upper.stl", body);
    writeText(dir / "bom.stl", "\xEF\xBB\xBF" + body);
    for (const char* name : {"upper.stl", "bom.stl"}) {
        const fm::Mesh m = fm::readMeshFile(dir / name);
        ASSERT_EQ(m.triangles.size(), 1u) << name;
        EXPECT_EQ(m.positions[1], glm::vec3(1.f, 0.f, 0.f)) << name;
    }
}

TEST(MeshReader, BinaryStlIsDetectedBySizeEvenWithSolidHeader) {
    Bytes b(80, ' ');
    std::memcpy(b.data(), "solid binary but says solid", 27);
    append<std::uint32_t>(b, 1);
    for (float f : {0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 3.f, 0.f, 0.f, 0.f, 4.f, 0.f}) append(b, f);
    append<std::uint16_t>(b, 0);
    const fs::path p = fm::test::scratchDir("mesh_reader_binary_stl") / "one.stl";
    writeBytes(p, b);
    const fm::Mesh m = fm::readMeshFile(p);
    ASSERT_EQ(m.triangles.size(), 1u);
    EXPECT_EQ(m.positions[1], glm::vec3(3, 0, 0));
    EXPECT_EQ(m.positions[2], glm::vec3(0, 4, 0));

    // One byte short: not binary by size, not ASCII either (no facet keyword): refused.
    b.pop_back();
    const fs::path q = p.parent_path() / "short.stl";
    writeBytes(q, b);
    expectError(q);
    // No "solid" and a count that disagrees with the size: the message gives both sizes.
    b[0] = 'x';
    const fs::path r = p.parent_path() / "count.stl";
    writeBytes(r, b);
    const std::string msg = expectError(r);
    EXPECT_NE(msg.find("84 + 50 * 1 = 134"), std::string::npos) << msg;
    EXPECT_NE(msg.find("133"), std::string::npos) << msg;
}

TEST(MeshReader, BinaryStlNanAndAbsurdCount) {
    Bytes b(80, 0);
    append<std::uint32_t>(b, 1);
    for (int i = 0; i < 12; ++i) append(b, i == 7 ? std::numeric_limits<float>::quiet_NaN() : 1.f);
    append<std::uint16_t>(b, 0);
    const fs::path dir = fm::test::scratchDir("mesh_reader_binary_bad");
    writeBytes(dir / "nan.stl", b);
    EXPECT_NE(expectError(dir / "nan.stl").find("facet 0 vertex 1"), std::string::npos);
    Bytes huge(80, 0);
    append<std::uint32_t>(huge, 0xffffffffu);
    writeBytes(dir / "huge.stl", huge);
    expectError(dir / "huge.stl");
}

TEST(MeshReader, AsciiStlErrors) {
    const fs::path dir = fm::test::scratchDir("mesh_reader_ascii_bad");
    const std::string good =
        "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
        "endloop\nendfacet\nendsolid t\n";
    writeText(dir / "truncated.stl", good.substr(0, good.size() - 30));
    expectError(dir / "truncated.stl");
    std::string nan = good;
    nan.replace(nan.find("vertex 1 0 0"), 12, "vertex 1 nan 0");
    writeText(dir / "nan.stl", nan);
    const std::string msg = expectError(dir / "nan.stl");
    EXPECT_NE(msg.find("line 5"), std::string::npos) << msg;
    EXPECT_NE(msg.find("facet 0 vertex 1"), std::string::npos) << msg;
    std::string quad = good;
    quad.replace(quad.find("endloop"), 7, "vertex 1 1 0\nendloop");
    writeText(dir / "quad.stl", quad);
    expectError(dir / "quad.stl");
    writeText(dir / "empty.stl", "solid nothing\nendsolid nothing\n");
    expectError(dir / "empty.stl");
    writeText(dir / "model.xyz", good);
    expectError(dir / "model.xyz");
    expectError(dir / "missing.stl");
}

TEST(MeshReader, PlyAsciiWithExtraPropertiesAndQuads) {
    const fs::path p = fm::test::scratchDir("mesh_reader_ply_ascii") / "quad.ply";
    writeText(p,
              "ply\nformat ascii 1.0\ncomment made by hand\nelement vertex 4\n"
              "property float x\nproperty float y\nproperty float z\nproperty uchar red\n"
              "element face 1\nproperty list uchar int vertex_indices\nproperty float quality\n"
              "element edge 1\nproperty int vertex1\nproperty int vertex2\nend_header\n"
              "0 0 0 255\n2 0 0 0\n2 3 0 9\n0 3 0.5 1\n4 0 1 2 3 0.5\n0 1\n");
    const fm::Mesh m = fm::readMeshFile(p);
    ASSERT_EQ(m.triangles.size(), 2u);  // the quad fanned
    EXPECT_EQ(m.triangles[0], glm::uvec3(0, 1, 2));
    EXPECT_EQ(m.triangles[1], glm::uvec3(0, 2, 3));
    EXPECT_EQ(m.positions[3], glm::vec3(0, 3, 0.5f));
}

Bytes binaryPly(bool bigEndian, std::uint32_t faceCount, int badIndex = -1) {
    std::string header = std::string("ply\nformat ") +
                         (bigEndian ? "binary_big_endian" : "binary_little_endian") +
                         " 1.0\nelement vertex 3\nproperty double x\nproperty double y\n"
                         "property double z\nproperty short flags\nelement face " +
                         std::to_string(faceCount) +
                         "\nproperty list uchar uint vertex_indices\nend_header\n";
    Bytes b(header.begin(), header.end());
    const double v[3][3] = {{0, 0, 0}, {1.25, 0, 0}, {0, -2, 7}};
    for (const auto& p : v) {
        for (double c : p) append(b, c, bigEndian);
        append<std::int16_t>(b, -5, bigEndian);
    }
    if (faceCount >= 1) {
        b.push_back(3);
        for (std::uint32_t i : {0u, 1u, badIndex >= 0 ? std::uint32_t(badIndex) : 2u})
            append(b, i, bigEndian);
    }
    return b;
}

TEST(MeshReader, PlyBinaryBothEndians) {
    const fs::path dir = fm::test::scratchDir("mesh_reader_ply_binary");
    for (bool big : {false, true}) {
        const fs::path p = dir / (big ? "be.ply" : "le.ply");
        writeBytes(p, binaryPly(big, 1));
        const fm::Mesh m = fm::readMeshFile(p);
        ASSERT_EQ(m.triangles.size(), 1u);
        EXPECT_EQ(m.positions[1], glm::vec3(1.25f, 0, 0));
        EXPECT_EQ(m.positions[2], glm::vec3(0, -2, 7));
    }
    writeBytes(dir / "index.ply", binaryPly(false, 1, 3));
    EXPECT_NE(expectError(dir / "index.ply").find("vertex 3 of 3"), std::string::npos);
    // A face count far beyond the bytes left is refused before anything is allocated.
    writeBytes(dir / "count.ply", binaryPly(false, 90000000));
    EXPECT_NE(expectError(dir / "count.ply").find("face"), std::string::npos);
    Bytes cut = binaryPly(true, 1);
    cut.resize(cut.size() - 2);
    writeBytes(dir / "cut.ply", cut);
    expectError(dir / "cut.ply");
}

TEST(MeshReader, ObjPolygonsSlashesAndNegativeIndices) {
    const fs::path p = fm::test::scratchDir("mesh_reader_obj") / "m.obj";
    writeText(p,
              "# comment\nmtllib x.mtl\no thing\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0 1.0\n"
              "vt 0 0\nvn 0 0 1\ng side\ns off\nf 1/1/1 2/1/1 3//1 4\n"
              "v 0 0 1\nf -5 -4 -1\n");
    const fm::Mesh m = fm::readMeshFile(p);
    ASSERT_EQ(m.triangles.size(), 3u);
    EXPECT_EQ(m.triangles[1], glm::uvec3(0, 2, 3));
    EXPECT_EQ(m.triangles[2], glm::uvec3(0, 1, 4));
    const fs::path dir = p.parent_path();
    writeText(dir / "range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n");
    EXPECT_NE(expectError(dir / "range.obj").find("line 4"), std::string::npos);
    writeText(dir / "neg.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -4\n");
    expectError(dir / "neg.obj");
    writeText(dir / "nan.obj", "v 0 0 0\nv 1 inf 0\nv 0 1 0\nf 1 2 3\n");
    EXPECT_NE(expectError(dir / "nan.obj").find("vertex 2"), std::string::npos);
    writeText(dir / "two.obj", "v 0 0 0\nv 1 0 0\nf 1 2\n");
    expectError(dir / "two.obj");
}

}  // namespace

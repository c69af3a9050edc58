// Mesh files read back byte by byte: binary PLY and STL, text OBJ.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "common/TestData.h"
#include "core/Error.h"
#include "model/MeshWriter.h"

namespace {

// A unit tetrahedron, outward counter-clockwise faces.
fm::Mesh tetrahedron() {
    fm::Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    m.normals = {{-0.57735f, -0.57735f, -0.57735f}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    return m;
}

std::string readText(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

template <class T>
T at(const std::string& bytes, std::size_t offset) {
    T v;
    std::memcpy(&v, bytes.data() + offset, sizeof v);
    return v;
}

TEST(MeshWriter, BinaryPlyHoldsPositionsNormalsAndFaces) {
    const auto dir = fm::test::scratchDir("mesh_writer_ply");
    const fm::Mesh m = tetrahedron();
    fm::writeMesh(m, dir / "t.ply");
    const std::string bytes = readText(dir / "t.ply");
    const std::string endHeader = "end_header\n";
    const std::size_t body = bytes.find(endHeader);
    ASSERT_NE(body, std::string::npos);
    const std::string header = bytes.substr(0, body);
    EXPECT_NE(header.find("format binary_little_endian 1.0"), std::string::npos);
    EXPECT_NE(header.find("element vertex 4"), std::string::npos);
    EXPECT_NE(header.find("property float nx"), std::string::npos);
    EXPECT_NE(header.find("element face 4"), std::string::npos);
    const std::size_t start = body + endHeader.size();
    ASSERT_EQ(bytes.size(), start + 4 * 24 + 4 * 13);
    for (int v = 0; v < 4; ++v)
        for (int a = 0; a < 3; ++a) {
            EXPECT_EQ(at<float>(bytes, start + v * 24 + a * 4), m.positions[v][a]);
            EXPECT_EQ(at<float>(bytes, start + v * 24 + 12 + a * 4), m.normals[v][a]);
        }
    const std::size_t faces = start + 4 * 24;
    for (int f = 0; f < 4; ++f) {
        EXPECT_EQ(static_cast<unsigned char>(bytes[faces + f * 13]), 3);
        for (int k = 0; k < 3; ++k)
            EXPECT_EQ(at<std::uint32_t>(bytes, faces + f * 13 + 1 + k * 4), m.triangles[f][k]);
    }
    EXPECT_FALSE(std::filesystem::exists(dir / "t.ply.tmp-fluoromatch"));
}

TEST(MeshWriter, BinaryStlHasOutwardFacetNormals) {
    const auto dir = fm::test::scratchDir("mesh_writer_stl");
    const fm::Mesh m = tetrahedron();
    fm::writeMesh(m, dir / "t.STL");  // extension case does not matter
    const std::string bytes = readText(dir / "t.STL");
    ASSERT_EQ(bytes.size(), 84u + 4u * 50u);
    EXPECT_EQ(at<std::uint32_t>(bytes, 80), 4u);
    // Facet 3 is the slanted face x + y + z = 1: unit normal (1,1,1)/sqrt(3), outward.
    const std::size_t f3 = 84 + 3 * 50;
    constexpr float kUnitTolerance = 1e-6f;  // float normalisation
    for (int a = 0; a < 3; ++a)
        EXPECT_NEAR(at<float>(bytes, f3 + a * 4), 1.0f / std::sqrt(3.0f), kUnitTolerance);
    // Its second vertex is mesh vertex 2 = (0, 1, 0).
    EXPECT_EQ(at<float>(bytes, f3 + 24 + 4), 1.0f);
    // Facet 0 (z = 0 plane) points down.
    EXPECT_NEAR(at<float>(bytes, 84 + 8), -1.0f, kUnitTolerance);
}

TEST(MeshWriter, ObjListsVerticesNormalsAndOneBasedFaces) {
    const auto dir = fm::test::scratchDir("mesh_writer_obj");
    fm::writeMesh(tetrahedron(), dir / "t.obj");
    std::istringstream in(readText(dir / "t.obj"));
    int v = 0, vn = 0, f = 0;
    std::string line, lastFace;
    while (std::getline(in, line)) {
        if (line.rfind("v ", 0) == 0) ++v;
        if (line.rfind("vn ", 0) == 0) ++vn;
        if (line.rfind("f ", 0) == 0) {
            ++f;
            lastFace = line;
        }
    }
    EXPECT_EQ(v, 4);
    EXPECT_EQ(vn, 4);
    EXPECT_EQ(f, 4);
    EXPECT_EQ(lastFace, "f 2//2 3//3 4//4");
}

TEST(MeshWriter, RefusesUnknownExtensionsAndBadIndicesWithoutTouchingTheTarget) {
    const auto dir = fm::test::scratchDir("mesh_writer_bad");
    EXPECT_THROW(fm::writeMesh(tetrahedron(), dir / "t.xyz"), fm::Error);
    EXPECT_THROW(fm::checkMeshPath("mesh"), fm::Error);
    fm::Mesh bad = tetrahedron();
    bad.triangles[0].x = 99;
    {
        std::ofstream keep(dir / "keep.ply");
        keep << "previous";
    }
    EXPECT_THROW(fm::writeMesh(bad, dir / "keep.ply"), fm::Error);
    EXPECT_EQ(readText(dir / "keep.ply"), "previous");
    EXPECT_THROW(fm::writeMesh(tetrahedron(), dir / "no-such-folder" / "t.ply"), fm::Error);
}

}  // namespace

// Random corruption of small valid mesh files (binary and ASCII STL, binary and ASCII PLY,
// OBJ): every reader must return a mesh with valid indices or throw fm::Error. Never crash,
// hang, trip a sanitizer or throw anything else.
#include <gtest/gtest.h>

#include <fstream>
#include <iostream>
#include <iterator>
#include <random>

#include "common/TestData.h"
#include "common/TestMeshes.h"
#include "core/Error.h"
#include "model/MeshFile.h"
#include "model/MeshModel.h"
#include "model/MeshWriter.h"

namespace {

namespace fs = std::filesystem;
using Bytes = std::vector<std::uint8_t>;

constexpr int kCases = 500;  // per file: at least 500 cases for every reader (issue 35)
constexpr unsigned kSeed = 20261201u;

Bytes readAll(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return Bytes(std::istreambuf_iterator<char>(in), {});
}

Bytes mutate(const Bytes& original, std::size_t headerSize, std::mt19937& rng) {
    Bytes b = original;
    auto pick = [&](std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng); };
    const std::size_t header = std::max<std::size_t>(1, std::min(headerSize, b.size()));
    switch (pick(4)) {
        case 0:
        case 1: {
            for (std::size_t f = 0, n = 1 + pick(4); f < n && !b.empty(); ++f)
                b[pick(2) == 0 ? pick(b.size()) : pick(header)] = static_cast<std::uint8_t>(pick(256));
            break;
        }
        case 2:
            b.resize(pick(b.size() + 1));
            break;
        default: {
            static const char* kTokens[] = {"9", "99999999", "-1", "nan", "0", " ", "\n", "inf",
                                            "1e39", "-", ".", "4294967296", "/", "endsolid",
                                            "facet", "end_header", "f", "v", "3", "255"};
            const std::string t = kTokens[pick(sizeof kTokens / sizeof *kTokens)];
            const std::size_t at = pick(b.size() > 0 ? b.size() : 1);
            b.insert(b.begin() + static_cast<std::ptrdiff_t>(std::min(at, b.size())), t.begin(), t.end());
            break;
        }
    }
    return b;
}

void fuzz(const fs::path& file, std::size_t headerSize) {
    const Bytes original = readAll(file);
    ASSERT_NO_THROW(fm::readMeshFile(file)) << file;
    std::mt19937 rng(kSeed);
    int loaded = 0, refused = 0;
    for (int c = 0; c < kCases; ++c) {
        const Bytes b = mutate(original, headerSize, rng);
        try {
            // In memory: the same parsers as readMeshFile, without the disk.
            const std::string ext = file.extension().string();
            const fm::Mesh m = ext == ".stl"   ? fm::readStlBytes(b, file.string())
                               : ext == ".ply" ? fm::readPlyBytes(b, file.string())
                                               : fm::readObjBytes(b, file.string());
            for (const auto& t : m.triangles)
                for (int k = 0; k < 3; ++k) ASSERT_LT(t[k], m.positions.size()) << file << " case " << c;
            fm::ModelLoadOptions o;
            o.silhouetteOnly = true;
            try {
                fm::makeMeshModel(m, file.string(), o);  // welding and topology survive any mesh
            } catch (const fm::Error&) {
            }
            ++loaded;
        } catch (const fm::Error&) {
            ++refused;
        } catch (const std::exception& e) {
            ADD_FAILURE() << file << " case " << c << ": non-fm exception: " << e.what();
        }
    }
    std::cout << "[ fuzz     ] " << file.filename().string() << ": " << loaded << " loaded, " << refused
              << " refused\n";
    EXPECT_GT(loaded, 0) << file;
    EXPECT_GT(refused, 0) << file;
}

TEST(MeshFuzz, EveryReader) {
    const fs::path dir = fm::test::scratchDir("mesh_fuzz");
    const fm::Mesh box = fm::test::boxMesh({0, 0, 0}, {1, 2, 3});
    for (const char* ext : {".stl", ".ply", ".obj"}) {
        const fs::path p = dir / (std::string("box") + ext);
        fm::writeMesh(box, p);
        fuzz(p, 200);
    }
    std::ofstream(dir / "ascii.stl")
        << "solid a\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
           "endloop\nendfacet\nfacet normal 0 0 1\nouter loop\nvertex 1 0 0\nvertex 1 1 0\n"
           "vertex 0 1 0\nendloop\nendfacet\nendsolid a\n";
    fuzz(dir / "ascii.stl", 400);
    std::ofstream(dir / "ascii.ply")
        << "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
           "property float z\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n"
           "0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n";
    fuzz(dir / "ascii.ply", 200);
}

}  // namespace

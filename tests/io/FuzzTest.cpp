// Random corruption of valid small files: every reader must either return a valid volume or
// throw fm::Error. Never crash, hang, trip a sanitizer or throw anything else. And the writers
// under a disk that fills up at a random byte.
#include <gtest/gtest.h>

#include <functional>
#include <iostream>
#include <random>
#include <sstream>

#include "IoTestFiles.h"
#include "common/TestData.h"
#include "core/Error.h"
#include "io/AtomicFile.h"
#include "io/PngWriter.h"
#include "io/ReadVolume.h"
#include "io/VolumeWriter.h"
#include "model/MeshWriter.h"

namespace {

namespace fs = std::filesystem;
using fm::test::Bytes;
using fm::test::ScalarType;

constexpr int kCasesPerFile = 600;     // the brief asks for at least 500 per reader
constexpr unsigned kSeed = 20261122u;  // fixed: failures reproduce

struct Outcome {
    int loaded = 0;
    int refused = 0;
};

// Applies one random mutation: byte changes (mostly in the first `headerSize` bytes, where
// the parser's decisions are), a truncation, or a text insertion into the header.
Bytes mutate(const Bytes& original, std::size_t headerSize, std::mt19937& rng) {
    Bytes b = original;
    auto pick = [&](std::size_t n) {
        return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng);
    };
    const std::size_t header = std::max<std::size_t>(1, std::min(headerSize, b.size()));
    switch (pick(4)) {
        case 0:
        case 1: {
            const std::size_t flips = 1 + pick(4);
            for (std::size_t f = 0; f < flips && !b.empty(); ++f) {
                const std::size_t at = pick(4) == 0 ? pick(b.size()) : pick(header);
                b[at] = static_cast<std::uint8_t>(pick(256));
            }
            break;
        }
        case 2:
            b.resize(pick(b.size() + 1));
            break;
        default: {
            static const char* kTokens[] = {
                "9", "99999", "-1",         "nan", "0", " ", "\n",  "%d",   "1e308", "-",
                ".", "65535", "4294967296", "(",   ")", ",", "inf", "LIST", "\r\n"};
            const std::string t = kTokens[pick(sizeof kTokens / sizeof *kTokens)];
            const std::size_t at = pick(header);
            if (pick(2) == 0)
                b.insert(b.begin() + static_cast<std::ptrdiff_t>(at), t.begin(), t.end());
            else
                for (std::size_t i = 0; i < t.size() && at + i < b.size(); ++i) b[at + i] = t[i];
            break;
        }
    }
    return b;
}

Outcome fuzz(const fs::path& file, const Bytes& original, std::size_t headerSize, bool gzipAfter,
             std::mt19937& rng) {
    Outcome outcome;
    for (int c = 0; c < kCasesPerFile; ++c) {
        Bytes b = mutate(original, headerSize, rng);
        if (gzipAfter) b = fm::test::gzipBytes(b);
        fm::test::writeFile(file, b);
        try {
            const fm::Volume v = fm::readVolume(file);
            v.validate("fuzzed volume");
            EXPECT_EQ(v.values.size(), v.voxelCount()) << file << " case " << c;
            ++outcome.loaded;
        } catch (const fm::Error&) {
            ++outcome.refused;
        } catch (const std::exception& e) {
            ADD_FAILURE() << file << " case " << c << ": non-fm exception: " << e.what();
        }
    }
    return outcome;
}

void fuzzAndReport(const fs::path& file, const Bytes& original, std::size_t headerSize,
                   bool gzipAfter = false) {
    std::mt19937 rng(kSeed);
    // The unmutated file must load, or the loop tests nothing.
    fm::test::writeFile(file, gzipAfter ? fm::test::gzipBytes(original) : original);
    ASSERT_NO_THROW(fm::readVolume(file)) << file;
    const Outcome o = fuzz(file, original, headerSize, gzipAfter, rng);
    EXPECT_EQ(o.loaded + o.refused, kCasesPerFile);
    std::cout << "[ fuzz     ] " << file.filename().string() << ": " << o.loaded << " loaded, "
              << o.refused << " refused\n";
    // Both outcomes occur: the mutations reach the parser's checks and its success path.
    EXPECT_GT(o.refused, 0) << file;
    EXPECT_GT(o.loaded, 0) << file;
}

std::vector<double> ramp(std::size_t n) {
    std::vector<double> v;
    for (std::size_t i = 0; i < n; ++i) v.push_back(static_cast<double>(i) * 3.0 - 20.0);
    return v;
}

TEST(Fuzz, Nifti) {
    const fs::path dir = fm::test::scratchDir("fuzz_nifti");
    fm::test::NiftiSpec s;
    s.dim = {3, 4, 3, 2};
    s.datatype = 4;  // int16
    s.values = ramp(24);
    s.sformCode = 1;
    s.srow[0][0] = 2, s.srow[1][1] = 2, s.srow[2][2] = 3, s.srow[0][3] = 7;
    fuzzAndReport(dir / "a.nii", s.bytes(), 352);
    fuzzAndReport(dir / "a.nii.gz", s.bytes(), 352, true);  // header mutations through gzip

    fm::test::NiftiSpec v2;
    v2.version = 2;
    v2.bigEndian = true;
    v2.dim = {3, 4, 3, 2};
    v2.datatype = 16;
    v2.values = ramp(24);
    v2.qformCode = 1;
    v2.quatern[2] = 0.5;
    v2.pixdim[0] = -1;
    fuzzAndReport(dir / "b.nii", v2.bytes(), 544);
    // Corruption of the compressed bytes themselves.
    fuzzAndReport(dir / "c.nii.gz", fm::test::gzipBytes(s.bytes()), 400);
}

TEST(Fuzz, MetaImage) {
    const fs::path dir = fm::test::scratchDir("fuzz_mha");
    const std::string header =
        "ObjectType = Image\nNDims = 3\nBinaryData = True\nBinaryDataByteOrderMSB = False\n"
        "CompressedData = False\nTransformMatrix = 1 0 0 0 1 0 0 0 1\nOffset = 1 2 3\n"
        "ElementSpacing = 0.5 0.5 2\nDimSize = 4 3 2\nElementType = MET_SHORT\n"
        "ElementDataFile = LOCAL\n";
    const Bytes raw = fm::test::encodeSamples(ramp(24), ScalarType::I16, false);
    fuzzAndReport(dir / "a.mha", fm::test::concat(fm::test::toBytes(header), raw), header.size());
    std::string zipped = header;
    zipped.replace(zipped.find("CompressedData = False"), 22, "CompressedData = True");
    fuzzAndReport(dir / "b.mha",
                  fm::test::concat(fm::test::toBytes(zipped), fm::test::zlibBytes(raw)),
                  zipped.size());
}

TEST(Fuzz, Nrrd) {
    const fs::path dir = fm::test::scratchDir("fuzz_nrrd");
    const std::string header =
        "NRRD0004\ntype: short\ndimension: 3\nsizes: 4 3 2\nspace: left-posterior-superior\n"
        "space directions: (0.5,0,0) (0,0.5,0) (0,0,2)\nspace origin: (1,2,3)\nendian: little\n";
    const Bytes raw = fm::test::encodeSamples(ramp(24), ScalarType::I16, false);
    fuzzAndReport(dir / "raw.nrrd",
                  fm::test::concat(fm::test::toBytes(header + "encoding: raw\n\n"), raw),
                  header.size() + 16);
    fuzzAndReport(dir / "gz.nrrd",
                  fm::test::concat(fm::test::toBytes(header + "encoding: gzip\n\n"),
                                   fm::test::gzipBytes(raw)),
                  header.size() + 16);
    std::ostringstream text;
    for (double v : ramp(24)) text << v << " ";
    fuzzAndReport(dir / "ascii.nrrd",
                  fm::test::toBytes(header + "encoding: ascii\n\n" + text.str()),
                  header.size() + 40);
    // Detached slices: only the header is fuzzed, the slice files stay.
    for (int k = 0; k < 2; ++k)
        fm::test::writeFile(dir / ("s" + std::to_string(k + 1) + ".raw"),
                            Bytes(raw.begin() + k * 24, raw.begin() + (k + 1) * 24));
    const std::string detached = header + "encoding: raw\ndata file: s%d.raw 1 2 1\n";
    fuzzAndReport(dir / "d.nhdr", fm::test::toBytes(detached), detached.size());
}

TEST(Fuzz, LegacyVtk) {
    const fs::path dir = fm::test::scratchDir("fuzz_vtk");
    const std::string header =
        "# vtk DataFile Version 1.0\ntitle\nBINARY\nDATASET STRUCTURED_POINTS\nDIMENSIONS 4 3 2\n"
        "ASPECT_RATIO 1.0 1.0 2.0\nORIGIN 0.0 0.0 0.0\nPOINT_DATA 24\n"
        "SCALARS scalars unsigned_short\nLOOKUP_TABLE default\n";
    fuzzAndReport(dir / "b.vtk",
                  fm::test::concat(fm::test::toBytes(header),
                                   fm::test::encodeSamples(ramp(24), ScalarType::I16, true)),
                  header.size());
    std::string ascii = header;
    ascii.replace(ascii.find("BINARY"), 6, "ASCII");
    std::ostringstream text;
    for (double v : ramp(24)) text << v << " ";
    fuzzAndReport(dir / "a.vtk", fm::test::toBytes(ascii + text.str()), ascii.size() + 40);
}

}  // namespace

// The writers' failure paths: every writer, with the disk filling up after a random number of
// bytes (the AtomicFile hook), either writes exactly what it writes unhindered or throws
// fm::Error naming the file, keeping the old file and leaving no temporary behind.

TEST(Fuzz, WritersUnderAFillingDisk) {
    const fs::path dir = fm::test::scratchDir("fuzz_writers");
    fm::Volume volume = fm::Volume::allocate({12, 10, 8});
    for (std::size_t n = 0; n < volume.values.size(); ++n)
        volume.values[n] = static_cast<float>(n % 97) * 3.5f - 100.0f;
    fm::Image image(48, 32);
    for (std::size_t n = 0; n < image.pixels.size(); ++n)
        image.pixels[n] = static_cast<float>((n * 37) % 255);
    fm::Mesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    mesh.normals = {{-1, -1, -1}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    mesh.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    const std::vector<std::pair<std::string, std::function<void(const fs::path&)>>> writers = {
        {"a.png", [&](const fs::path& p) { fm::writePng(image, p, 0.0f, 255.0f); }},
        {"a.mha", [&](const fs::path& p) { fm::writeMetaImage(volume, p, true); }},
        {"b.mha", [&](const fs::path& p) { fm::writeMetaImage(volume, p, false); }},
        {"a.nii.gz", [&](const fs::path& p) { fm::writeNifti(volume, p); }},
        {"a.nii", [&](const fs::path& p) { fm::writeNifti(volume, p); }},
        {"a.ply", [&](const fs::path& p) { fm::writeMesh(mesh, p); }},
        {"a.stl", [&](const fs::path& p) { fm::writeMesh(mesh, p); }},
        {"a.obj", [&](const fs::path& p) { fm::writeMesh(mesh, p); }},
        {"d.mha", [&](const fs::path& p) { fm::writeImage(image, p); }},
    };
    std::mt19937 rng(kSeed);
    int refused = 0, written = 0;
    for (const auto& [name, write] : writers) {
        SCOPED_TRACE(name);
        const fs::path reference = dir / ("reference-" + name);
        write(reference);
        const Bytes expected = fm::test::readFile(reference);
        fs::remove(reference);
        const fs::path target = dir / name;
        for (int trial = 0; trial < 40; ++trial) {
            fm::test::writeFile(target, std::string("old"));
            const std::uintmax_t room =
                std::uniform_int_distribution<std::uintmax_t>(0, expected.size() + 8)(rng);
            fm::io::setWriteLimitForTesting(room);
            try {
                write(target);
                fm::io::setWriteLimitForTesting(std::nullopt);
                ASSERT_GE(room, expected.size());
                ASSERT_TRUE(fm::test::readFile(target) == expected) << "room " << room;
                ++written;
            } catch (const fm::Error& e) {
                fm::io::setWriteLimitForTesting(std::nullopt);
                ASSERT_LT(room, expected.size());
                ASSERT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
                ASSERT_EQ(fm::test::readFile(target), fm::test::toBytes("old")) << "room " << room;
                ++refused;
            }
            int entries = 0;
            for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++entries;
            ASSERT_EQ(entries, 1) << "a temporary was left behind (room " << room << ")";
            fs::remove(target);
        }
    }
    std::cout << "writers under a filling disk: " << written << " written, " << refused
              << " refused\n";
    EXPECT_GT(refused, 0);
    EXPECT_GT(written, 0);
}

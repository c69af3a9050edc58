// Random corruption of trial files (Autoscoper .cfg and our JSON): the readers either return a
// trial or throw fm::Error. Never crash, hang, trip a sanitizer or throw anything else.
#include <fstream>
#include <random>

#include <gtest/gtest.h>

#include "common/TestData.h"
#include "core/Error.h"
#include "trial/Trial.h"

namespace {

namespace fs = std::filesystem;

constexpr int kCasesPerFile = 500;
constexpr unsigned kSeed = 20261201u;  // fixed: failures reproduce

std::string mutate(const std::string& original, std::mt19937& rng) {
    std::string s = original;
    auto pick = [&](std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng); };
    static const char* kTokens[] = {"9", "-1", "nan", "1e999", " ", "\n", "\"", "{", "}", "[",
                                    "]", ",", ":", "Version 1.0", "VoxelSize", "\\", "0", "\r"};
    switch (pick(3)) {
        case 0:
            for (std::size_t f = 0, n = 1 + pick(4); f < n && !s.empty(); ++f)
                s[pick(s.size())] = static_cast<char>(pick(256));
            break;
        case 1: s.resize(pick(s.size() + 1)); break;
        default: s.insert(pick(s.size() + 1), kTokens[pick(sizeof kTokens / sizeof *kTokens)]);
    }
    return s;
}

void fuzz(const std::string& good, const std::string& name) {
    // One folder per file kind: ctest -j runs the two tests at once, and scratchDir empties it.
    const fs::path dir = fm::test::scratchDir("trial_fuzz_" + fs::path(name).extension().string().substr(1));
    std::mt19937 rng(kSeed);
    int loaded = 0, refused = 0;
    for (int i = 0; i < kCasesPerFile; ++i) {
        const fs::path p = dir / name;
        std::ofstream(p, std::ios::binary) << mutate(good, rng);
        try {
            fm::readTrial(p);
            ++loaded;
        } catch (const fm::Error&) {
            ++refused;
        }
    }
    EXPECT_EQ(loaded + refused, kCasesPerFile);
    EXPECT_GT(refused, kCasesPerFile / 10) << "the mutations must break most files";
}

TEST(TrialFuzz, AutoscoperConfigNeverCrashes) {
    fuzz("Version 1.1\nmayaCam_csv a.txt\nmayaCam_csv b.txt\nCameraRootDir f1\nCameraRootDir f2\n"
         "VolumeFile v.tif\nVolumeFlip 0 1 0\nVoxelSize 0.4 0.4 0.6\nRenderResolution 512 512\n"
         "OptimizationOffsets 0.1 0.1 0.1 0.1 0.1 0.1\n",
         "t.cfg");
}

TEST(TrialFuzz, TrialJsonNeverCrashes) {
    fuzz("{\"name\": \"w\", \"cameras\": [{\"name\": \"c1\", \"calibration\": \"a.txt\", \"frames\": \"f\"}],"
         " \"bones\": [{\"name\": \"r\", \"volume\": \"r.tif\", \"voxel_size\": [0.4, 0.4, 0.6], \"flip\": [0, 0, 0]}],"
         " \"render_resolution\": [512, 512], \"keyframes\": {\"r\": [{\"frame\": 0, \"volume_frame\": \"autoscoper\","
         " \"world_from_volume\": [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1]}]}}",
         "t.json");
}

}  // namespace

// Random corruption of valid calibration texts: every reader returns a valid result
// or throws fm::Error. Never a crash, a hang, a sanitizer report or another exception.
#include <gtest/gtest.h>

#include <iostream>
#include <random>

#include "camera/CameraFile.h"
#include "core/Error.h"

namespace {

constexpr int kCases = 300;
constexpr unsigned kSeed = 20261201u;

std::string mutate(const std::string& original, std::mt19937& rng) {
    std::string s = original;
    auto pick = [&](std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng); };
    static const char* kTokens[] = {"9", "-1", "nan", "0", " ", "\n", ",", "inf", "1e308", "\r\n",
                                    "image size", "abc", "-", ".", "NOT_OPTIMIZED", "1e-320"};
    switch (pick(4)) {
        case 0:
            for (std::size_t f = 0, n = 1 + pick(3); f < n && !s.empty(); ++f)
                s[pick(s.size())] = static_cast<char>(pick(256));
            break;
        case 1:
            s.resize(pick(s.size() + 1));
            break;
        case 2:
            if (!s.empty()) s.erase(pick(s.size()), 1 + pick(8));
            break;
        default:
            s.insert(pick(s.size() + 1), kTokens[pick(sizeof kTokens / sizeof *kTokens)]);
    }
    return s;
}

template <class Read>
void fuzz(const char* name, const std::string& original, Read read) {
    std::mt19937 rng(kSeed);
    ASSERT_NO_THROW(read(original)) << name;
    int loaded = 0, refused = 0;
    for (int c = 0; c < kCases; ++c) {
        const std::string text = mutate(original, rng);
        try {
            read(text);
            ++loaded;
        } catch (const fm::Error&) {
            ++refused;
        } catch (const std::exception& e) {
            ADD_FAILURE() << name << " case " << c << ": non-fm exception " << e.what();
        }
    }
    std::cout << "[ fuzz     ] " << name << ": " << loaded << " loaded, " << refused << " refused\n";
    EXPECT_GT(loaded, 0) << name;
    EXPECT_GT(refused, 0) << name;
}

TEST(CalibrationFuzz, Readers) {
    auto camera = [](const std::string& t) {
        const fm::CameraReadResult r = fm::parseCameraText(t, "fuzz", glm::ivec2(1024, 1024));
        r.camera.validate("fuzzed camera");
        (void)fm::toProjectionGeometry(r.camera);
    };
    fuzz("MayaCam 2.0",
         "image size\n1760,1760\n\ncamera matrix\n6167.35,0,803.74\n0,6165.63,865.69\n0,0,1\n\n"
         "rotation\n1,0,0\n0,1,0\n0,0,1\n\ntranslation\n-16.6\n-77.8\n901.3\n",
         camera);
    fuzz("MayaCam 1.0", "10,20,-900\n1,2,3\n0,0,-500\n512,512,5000\n0.1,0,0\n", camera);
    fuzz("JT_INTCALIB", "JT_INTCALIB\n1198\n0\n0\n0.373\n", camera);
}

}  // namespace

// Random corruption of valid pose tables (.jts, .tra): a valid result or fm::Error, never a
// crash, a hang, a sanitizer report or another exception.
#include <gtest/gtest.h>

#include <iostream>
#include <random>

#include "core/Error.h"
#include "pose/AutoscoperTra.h"
#include "pose/JointTrackPoses.h"

namespace {

constexpr int kCases = 300;
constexpr unsigned kSeed = 20261201u;

std::string mutate(const std::string& original, std::mt19937& rng) {
    std::string s = original;
    auto pick = [&](std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng); };
    static const char* kTokens[] = {"9", "-1", "nan", "NaN", "0", " ", "\n", ",", "inf", "1e308",
                                    "\r\n", "abc", "-", ".", "NOT_OPTIMIZED", "1e-320", "\t"};
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
        try {
            read(mutate(original, rng));
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

TEST(PoseFuzz, Readers) {
    fuzz("JT_EULER_312",
         "JT_EULER_312\n x_tran, y_tran, z_tran, z_rot, x_rot, y_rot\n"
         "18.52191, 19.69514, -1027.713, -26.69708, -7.419319, -0.2587041\nNOT_OPTIMIZED\n",
         [](const std::string& t) { (void)fm::parseJointTrackPoses(t, "fuzz"); });
    fuzz("tra matrix",
         "1,0,0,5,0,1,0,6,0,0,1,7,0,0,0,1\nNaN,NaN,NaN,NaN,NaN,NaN,NaN,NaN,NaN,NaN,NaN,NaN,NaN,NaN,NaN,NaN\n"
         "0,-1,0,5,1,0,0,6,0,0,1,7,0,0,0,1\n",
         [](const std::string& t) {
             const fm::TraFile f = fm::parseTra(t, "fuzz");
             for (const auto& frame : f.frames)
                 for (const auto& p : frame)
                     if (p) p->validate("fuzzed pose");
         });
    fuzz("tra xyzypr", "1 2 3 4 5 6\n7 8 9 10 11 12\nnan nan nan nan nan nan\n",
         [](const std::string& t) { (void)fm::parseTra(t, "fuzz", fm::TraForm::Xyzypr); });
}

}  // namespace

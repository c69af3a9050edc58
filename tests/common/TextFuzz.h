#pragma once
// Random corruption of small text files (calibrations, pose tables): `fuzzText` runs `read` on
// `cases` mutations of `original` (byte changes, truncation, deletion, token insertion) and
// expects a result or fm::Error, never another exception; both outcomes must occur.
#include <gtest/gtest.h>

#include <iostream>
#include <random>
#include <string>

#include "core/Error.h"

namespace fm::test {

inline std::string mutateText(const std::string& original, std::mt19937& rng) {
    std::string s = original;
    auto pick = [&](std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng); };
    static const char* kTokens[] = {"9", "-1", "nan", "NaN", "0", " ", "\n", ",", "inf", "1e308", "\r\n",
                                    "image size", "abc", "-", ".", "NOT_OPTIMIZED", "1e-320", "\t"};
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
void fuzzText(const char* name, const std::string& original, Read read, int cases = 500,
              unsigned seed = 20261201u) {
    std::mt19937 rng(seed);
    ASSERT_NO_THROW(read(original)) << name;
    int loaded = 0, refused = 0;
    for (int c = 0; c < cases; ++c) {
        try {
            read(mutateText(original, rng));
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

}  // namespace fm::test

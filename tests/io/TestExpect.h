#pragma once
// Shared expectations for the io tests.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "core/Error.h"
#include "volume/Volume.h"

namespace fm::test {

inline void expectValues(const fm::Volume& v, const std::vector<double>& values) {
    ASSERT_EQ(v.values.size(), values.size());
    for (std::size_t n = 0; n < values.size(); ++n)
        ASSERT_EQ(v.values[n], static_cast<float>(values[n])) << "sample " << n;
}

inline void expectVec(const glm::dvec3& a, const glm::dvec3& b, double tol) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

// Expects an fm::Error whose message names the file and contains `fragment`.
template <typename F>
void expectError(F&& f, const std::filesystem::path& file, const std::string& fragment) {
    try {
        f();
        ADD_FAILURE() << "no fm::Error for " << file << " (expected '" << fragment << "')";
    } catch (const fm::Error& e) {
        const std::string msg = e.what();
        EXPECT_NE(msg.find(file.filename().string()), std::string::npos) << msg;
        EXPECT_NE(msg.find(fragment), std::string::npos) << msg;
    }
}

}  // namespace fm::test

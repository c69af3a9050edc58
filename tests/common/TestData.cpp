#include "common/TestData.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <gtest/gtest.h>

namespace fm::test {

std::filesystem::path repoDir() { return FM_SOURCE_DIR; }

std::filesystem::path sharedDataDir() {
    if (const char* env = std::getenv("FM_DATA_DIR"); env && *env) return env;
    return repoDir().parent_path() / "shared" / "data";
}

bool underCI() {
    const char* ci = std::getenv("CI");
    return ci && std::string(ci) == "true";
}

bool sharedDataBesideRepo() {
    std::error_code ec;
    return std::filesystem::equivalent(sharedDataDir(), repoDir().parent_path() / "shared" / "data", ec);
}

std::filesystem::path scratchDir(const std::string& name) {
    auto dir = std::filesystem::path(FM_BINARY_DIR) / "test-scratch" / name;
    // One folder per test: ctest runs the tests of a fixture in parallel processes, and two of
    // them emptying the same folder raced (MeshTrialInput's t.json, seen once in 746 tests).
    // Named by a hash of the test's suite and name, 8 hex digits: the whole name made a socket
    // path too long for sun_path (108 bytes) in AtomicFile's test.
    if (const auto* test = ::testing::UnitTest::GetInstance()->current_test_info()) {
        std::uint32_t hash = 2166136261u;  // FNV-1a: the same folder for a test on every run
        for (const char* p : {test->test_suite_name(), ".", test->name()})
            for (; *p; ++p) hash = (hash ^ static_cast<unsigned char>(*p)) * 16777619u;
        char id[9];
        std::snprintf(id, sizeof id, "%08x", hash);
        dir /= id;
    }
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

}  // namespace fm::test

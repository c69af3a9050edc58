#include "common/TestData.h"

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
    if (const auto* test = ::testing::UnitTest::GetInstance()->current_test_info()) {
        std::string id = std::string(test->test_suite_name()) + "." + test->name();
        for (char& c : id)
            if (c == '/') c = '_';
        dir /= id;
    }
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

}  // namespace fm::test

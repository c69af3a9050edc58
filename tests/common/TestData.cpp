#include "common/TestData.h"

#include <cstdlib>
#include <string>

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
    const auto dir = std::filesystem::path(FM_BINARY_DIR) / "test-scratch" / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

}  // namespace fm::test

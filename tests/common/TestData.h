#pragma once
// Where the tests find data: the repository's own data/ and the shared real data
// (FM_DATA_DIR, default ../shared/data beside the repository).
#include <filesystem>

#include <gtest/gtest.h>

namespace fm::test {

std::filesystem::path repoDir();
std::filesystem::path sharedDataDir();
// True when running under CI (CI=true): missing shared data is then a failure, not a skip.
bool underCI();
// True when the shared data is the one beside the repository (../shared/data), as the shipped
// trials (data/trials/) name it.
bool sharedDataBesideRepo();
// A fresh scratch folder for one test (under the build tree: `name`, then a hash of the running
// test's suite and name, so tests running in parallel never share one), emptied on creation.
std::filesystem::path scratchDir(const std::string& name);

}  // namespace fm::test

// Use at the start of a test that needs ../shared/data/<relative>: skips with a clear message
// when absent, fails under CI=true.
#define FM_REQUIRE_SHARED_DATA(relative)                                                    \
    do {                                                                                    \
        const auto fm_path_ = ::fm::test::sharedDataDir() / (relative);                    \
        if (!std::filesystem::exists(fm_path_)) {                                           \
            if (::fm::test::underCI()) FAIL() << "shared data missing under CI: " << fm_path_; \
            GTEST_SKIP() << "shared data not found: " << fm_path_                           \
                         << " (set FM_DATA_DIR to the folder that holds it)";               \
        }                                                                                   \
    } while (0)

#pragma once
// The ASan + UBSan build (`bash scripts/test --sanitize`, FM_SANITIZE) runs ~5x slower: a test
// that repeats a workload (frames tracked, starts, restarts, fuzz cases) repeats it fewer times
// there, every code path and every assertion kept. The CLI scripts get theirs from ctest's
// ENVIRONMENT under FM_SANITIZE (e.g. FM_CONFIRMED_SEEDS, app/CMakeLists.txt).

namespace fm::test {

#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kSanitizerBuild = true;
#else
inline constexpr bool kSanitizerBuild = false;
#endif

}  // namespace fm::test

// keepFreedMemoryForReuse (core/HeapReuse.h): after it, a large block (40 MB: a 1760 x 1760 x 3
// float volume slab, or several frames) comes from the heap, not from a mapping of its own that
// free hands back to the kernel (glibc's mallinfo2 counts mapped bytes). glibc maps such a block
// by default (its dynamic threshold never rises above 32 MiB), so the setting is what changes it.
#include <cstdlib>
#include <vector>

#include <gtest/gtest.h>

#include "core/HeapReuse.h"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace {

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kSanitized = true;  // ASan's allocator replaces glibc's
#else
constexpr bool kSanitized = false;
#endif

TEST(HeapReuse, ALargeBlockComesFromTheHeap) {
#if defined(__GLIBC__)
    if (kSanitized) GTEST_SKIP() << "ASan's allocator replaces glibc's malloc";
    constexpr std::size_t kFrame = 40u << 20;
    auto mapped = [] { return mallinfo2().hblkhd; };
    const std::size_t before = mapped();
    void* p = std::malloc(kFrame);
    ASSERT_NE(p, nullptr);
    const bool mappedByDefault = mapped() >= before + kFrame;
    std::free(p);
    fm::keepFreedMemoryForReuse();
    const std::size_t after = mapped();
    void* q = std::malloc(kFrame);
    ASSERT_NE(q, nullptr);
    EXPECT_LT(mapped(), after + kFrame) << "a 40 MB block was still mapped on its own";
    std::free(q);
    EXPECT_TRUE(mappedByDefault);  // the setting made the difference
#else
    GTEST_SKIP() << "not glibc";
#endif
}

}  // namespace

#include "core/LargeAllocation.h"

#include <new>

#ifdef __linux__
#include <sys/mman.h>
#endif

namespace fm {
namespace {

constexpr std::size_t kHugePage = std::size_t{2} << 20;
constexpr std::size_t kLargeFrom = std::size_t{4} << 20;

std::size_t roundedToHugePages(std::size_t bytes) {
    return (bytes + kHugePage - 1) / kHugePage * kHugePage;
}

}  // namespace

void* allocateLarge(std::size_t bytes) {
    if (bytes < kLargeFrom) return ::operator new(bytes);
    const std::size_t rounded = roundedToHugePages(bytes);
    void* p = ::operator new (rounded, std::align_val_t{kHugePage});
#ifdef __linux__
    // Advice only: where huge pages are disabled this fails and ordinary pages are used.
    (void)madvise(p, rounded, MADV_HUGEPAGE);
#endif
    return p;
}

void deallocateLarge(void* p, std::size_t bytes) noexcept {
    if (!p) return;
    if (bytes < kLargeFrom)
        ::operator delete(p);
    else
        ::operator delete (p, std::align_val_t{kHugePage});
}

}  // namespace fm

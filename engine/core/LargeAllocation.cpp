#include "core/LargeAllocation.h"

#include <cstdint>
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

void* allocateMapped(std::size_t bytes) {
#ifdef __linux__
    if (bytes < kLargeFrom) return ::operator new(bytes);
    // Map one huge page more than needed, then unmap the ends to leave an aligned block.
    const std::size_t rounded = roundedToHugePages(bytes);
    void* mapped = mmap(nullptr, rounded + kHugePage, PROT_READ | PROT_WRITE,
                        MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (mapped == MAP_FAILED) throw std::bad_alloc();
    const auto start = reinterpret_cast<std::uintptr_t>(mapped);
    const std::uintptr_t begin = (start + kHugePage - 1) / kHugePage * kHugePage;
    const std::uintptr_t end = begin + rounded, mappedEnd = start + rounded + kHugePage;
    if (begin > start) munmap(mapped, begin - start);
    if (mappedEnd > end) munmap(reinterpret_cast<void*>(end), mappedEnd - end);
    // Advice only: where huge pages are disabled this fails and ordinary pages are used.
    (void)madvise(reinterpret_cast<void*>(begin), rounded, MADV_HUGEPAGE);
    return reinterpret_cast<void*>(begin);
#else
    return allocateLarge(bytes);
#endif
}

void deallocateMapped(void* p, std::size_t bytes) noexcept {
#ifdef __linux__
    if (!p) return;
    if (bytes < kLargeFrom)
        ::operator delete(p);
    else
        munmap(p, roundedToHugePages(bytes));
#else
    deallocateLarge(p, bytes);
#endif
}

}  // namespace fm

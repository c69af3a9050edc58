#pragma once
// Memory for large arrays that are written once right after allocation (volume-sized scratch,
// mesh output). From 4 MiB up, blocks are aligned to 2 MiB and, on Linux, marked for
// transparent huge pages: first touching them then takes one page fault per 2 MiB instead of
// one per 4 KiB. On a 42 M-voxel CT the 4 KiB faults cost marching cubes about a third of its
// time (docs/marching-cubes.md).
#include <cstddef>
#include <memory>
#include <type_traits>

namespace fm {

// Uninitialised memory, suitably aligned for any object type; throws std::bad_alloc.
void* allocateLarge(std::size_t bytes);
// Frees memory from allocateLarge; `bytes` must be the size it was allocated with.
void deallocateLarge(void* p, std::size_t bytes) noexcept;

// Memory for arrays read many times in scattered order (a DRR volume, ~170 MB for a head CT):
// from 4 MiB up a mapping of its own, 2 MiB-aligned and marked for huge pages before its first
// touch. allocateLarge's blocks come from the heap, whose pages may already be 4 KiB ones
// (fluoromatch keeps freed memory for reuse): the GE head then got 63 of its 170 MB in huge
// pages, and a walk that prefetches each ray's voxels paid a TLB miss for most of them
// (docs/drr.md, "Prefetching on large volumes"). Off Linux, allocateLarge.
void* allocateMapped(std::size_t bytes);
// Frees memory from allocateMapped; `bytes` must be the size it was allocated with.
void deallocateMapped(void* p, std::size_t bytes) noexcept;

struct LargeDeleter {
    std::size_t bytes = 0;
    void operator()(void* p) const noexcept { deallocateLarge(p, bytes); }
};

// An array of n trivially constructible T, left uninitialised.
template <class T>
using LargeBuffer = std::unique_ptr<T[], LargeDeleter>;

template <class T>
LargeBuffer<T> makeLargeBuffer(std::size_t n) {
    static_assert(std::is_trivially_default_constructible_v<T>);
    const std::size_t bytes = n * sizeof(T);
    return LargeBuffer<T>(static_cast<T*>(allocateLarge(bytes)), LargeDeleter{bytes});
}

// std::allocator (elements value-initialised) with its memory from allocateMapped.
template <class T>
struct MappedAllocator : std::allocator<T> {
    template <class U>
    struct rebind {
        using other = MappedAllocator<U>;
    };
    MappedAllocator() noexcept = default;
    template <class U>
    MappedAllocator(const MappedAllocator<U>&) noexcept {}
    T* allocate(std::size_t n) { return static_cast<T*>(allocateMapped(n * sizeof(T))); }
    void deallocate(T* p, std::size_t n) noexcept { deallocateMapped(p, n * sizeof(T)); }
};

}  // namespace fm

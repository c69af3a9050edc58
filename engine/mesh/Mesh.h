#pragma once
// An indexed triangle mesh in world millimetres (the volume's frame), shared vertices,
// counter-clockwise triangles seen from outside (normals point out of the bone).
#include <cstdint>
#include <memory>
#include <new>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "core/LargeAllocation.h"

namespace fm {

// std::allocator, except that resize() default-initialises instead of zeroing and large blocks
// come from allocateLarge: marching cubes sizes its output once and then writes every element
// on several threads, so a zeroing pass on one thread first (and the page faults it takes) is
// wasted work.
template <class T>
struct DefaultInitAllocator : std::allocator<T> {
    template <class U>
    struct rebind {
        using other = DefaultInitAllocator<U>;
    };
    DefaultInitAllocator() noexcept = default;
    template <class U>
    DefaultInitAllocator(const DefaultInitAllocator<U>&) noexcept {}
    T* allocate(std::size_t n) { return static_cast<T*>(allocateLarge(n * sizeof(T))); }
    void deallocate(T* p, std::size_t n) noexcept { deallocateLarge(p, n * sizeof(T)); }
    template <class U>
    void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
        ::new (static_cast<void*>(p)) U;
    }
    template <class U, class... Args>
    void construct(U* p, Args&&... args) {
        ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
    }
};

// Growing one of these with resize(n) leaves the new elements unset: write them all.
template <class T>
using MeshArray = std::vector<T, DefaultInitAllocator<T>>;

struct Mesh {
    MeshArray<glm::vec3> positions;
    MeshArray<glm::vec3> normals;          // per vertex, unit, outward
    MeshArray<glm::uvec3> triangles;       // indices into positions
    MeshArray<std::uint32_t> component;    // per triangle: connected-component label (optional)

    std::size_t vertexCount() const { return positions.size(); }
    std::size_t triangleCount() const { return triangles.size(); }
};

}  // namespace fm

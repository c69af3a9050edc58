// fm::allocateLarge: small and large blocks are usable, large ones 2 MiB aligned; MeshArray
// (which allocates through it) behaves as a vector. fm::allocateMapped (DRR volumes) the same.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <vector>

#include "core/LargeAllocation.h"
#include "mesh/Mesh.h"

namespace {

TEST(LargeAllocation, SmallAndLargeBlocksHoldWhatIsWritten) {
    for (std::size_t bytes :
         {std::size_t{1}, std::size_t{4096}, std::size_t{4} << 20, (std::size_t{9} << 20) + 3}) {
        auto buffer = fm::makeLargeBuffer<std::uint8_t>(bytes);
        ASSERT_NE(buffer.get(), nullptr);
        std::memset(buffer.get(), 0xab, bytes);
        EXPECT_EQ(buffer[0], 0xab);
        EXPECT_EQ(buffer[bytes - 1], 0xab);
        if (bytes >= (std::size_t{4} << 20)) {
            EXPECT_EQ(reinterpret_cast<std::uintptr_t>(buffer.get()) % (std::size_t{2} << 20), 0u)
                << bytes << " bytes";
        }
    }
}

TEST(LargeAllocation, MeshArraysGrowCopyAndCompareLikeVectors) {
    fm::MeshArray<glm::vec3> a;
    a.resize(500000);  // 6 MB: a large block
    for (std::size_t i = 0; i < a.size(); ++i) a[i] = glm::vec3(float(i), 1.0f, 2.0f);
    a.push_back(glm::vec3(-1.0f));
    fm::MeshArray<glm::vec3> b = a;
    EXPECT_TRUE(a == b);
    b.resize(10);  // shrinking keeps the first elements
    EXPECT_EQ(b[9], glm::vec3(9.0f, 1.0f, 2.0f));
    EXPECT_EQ(a.back(), glm::vec3(-1.0f));
    b = std::move(a);
    EXPECT_EQ(b.size(), 500001u);
}

// Vectors in mapped memory: value-initialised, large blocks 2 MiB aligned (their own huge-page
// mapping), copies and moves as for std::vector; every byte up to the end is writable (the
// aligned block is cut from a larger mapping).
TEST(LargeAllocation, MappedVectorsAreZeroedAlignedAndCopyLikeVectors) {
    for (std::size_t n : {std::size_t{3}, std::size_t{1} << 20, (std::size_t{5} << 20) + 1}) {
        std::vector<float, fm::MappedAllocator<float>> a(n);
        EXPECT_EQ(a.front(), 0.0f);
        EXPECT_EQ(a.back(), 0.0f);
        if (n * sizeof(float) >= (std::size_t{4} << 20)) {
            EXPECT_EQ(reinterpret_cast<std::uintptr_t>(a.data()) % (std::size_t{2} << 20), 0u)
                << n << " floats";
        }
        for (std::size_t i = 0; i < n; ++i) a[i] = float(i % 1000);
        std::vector<float, fm::MappedAllocator<float>> b = a;
        EXPECT_TRUE(a == b);
        b.assign(n, 2.5f);
        EXPECT_EQ(b[n - 1], 2.5f);
        EXPECT_EQ(a[n - 1], float((n - 1) % 1000));
        a = std::move(b);
        EXPECT_EQ(a[0], 2.5f);
    }
}

}  // namespace

// fm::parallelFor: fixed chunks (results never depend on scheduling), the persistent worker
// pool, nested and concurrent calls, and exceptions.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>
#include <set>
#include <thread>
#include <utility>
#include <vector>

#include "core/Error.h"
#include "core/Parallel.h"

namespace {

TEST(Parallel, CoversEveryIndexOnceWithFixedChunks) {
    for (int threads : {1, 2, 3, 8}) {
        std::vector<int> hits(1000, 0);
        fm::parallelFor(
            1000, threads,
            [&](int b, int e) {
                for (int i = b; i < e; ++i) hits[i] += 1;
            },
            4);
        for (int h : hits) ASSERT_EQ(h, 1);
    }
}

TEST(Parallel, ChunkBoundariesDependOnlyOnCountAndThreads) {
    // Chunk c covers [c * count / chunks, (c + 1) * count / chunks) with chunks = threads x 4.
    for (int threads : {1, 2, 3}) {
        std::mutex m;
        std::set<std::pair<int, int>> seen;
        fm::parallelFor(
            103, threads,
            [&](int b, int e) {
                std::lock_guard<std::mutex> lock(m);
                seen.insert({b, e});
            },
            4);
        const int chunks = threads * 4;
        std::set<std::pair<int, int>> expected;
        for (int c = 0; c < chunks; ++c)
            expected.insert({c * 103 / chunks, (c + 1) * 103 / chunks});
        EXPECT_EQ(seen, expected) << threads << " threads";
    }
}

TEST(Parallel, NeverRunsOnMoreThreadsThanAskedFor) {
    // A call with 4 threads leaves 3 pooled workers; a later 2-thread call may use only one.
    fm::parallelFor(4, 4, [](int, int) {});
    for (int repeat = 0; repeat < 20; ++repeat) {
        std::mutex m;
        std::set<std::thread::id> ids;
        fm::parallelFor(
            64, 2,
            [&](int, int) {
                std::this_thread::sleep_for(std::chrono::microseconds(200));
                std::lock_guard<std::mutex> lock(m);
                ids.insert(std::this_thread::get_id());
            },
            8);
        ASSERT_LE(ids.size(), 2u);
    }
}

TEST(Parallel, NestedCallsRunInlineAndCoverEverything) {
    std::vector<std::atomic<int>> hits(40 * 50);
    fm::parallelFor(40, 2, [&](int b, int e) {
        for (int i = b; i < e; ++i)
            fm::parallelFor(50, 2, [&](int b2, int e2) {
                for (int j = b2; j < e2; ++j) hits[i * 50 + j] += 1;
            });
    });
    for (const auto& h : hits) ASSERT_EQ(h.load(), 1);
}

TEST(Parallel, ConcurrentCallersEachGetAllTheirIndices) {
    // Two threads call at once: one gets the pool, the other its own threads; both complete.
    std::vector<int> a(5000, 0), b(5000, 0);
    auto fill = [](std::vector<int>& v) {
        for (int repeat = 0; repeat < 50; ++repeat)
            fm::parallelFor(
                static_cast<int>(v.size()), 2,
                [&](int lo, int hi) {
                    for (int i = lo; i < hi; ++i) v[i] += 1;
                },
                4);
    };
    std::thread other([&] { fill(b); });
    fill(a);
    other.join();
    for (int x : a) ASSERT_EQ(x, 50);
    for (int x : b) ASSERT_EQ(x, 50);
}

TEST(Parallel, RethrowsExceptionsFromWorkersAndStaysUsable) {
    EXPECT_THROW(fm::parallelFor(10, 2,
                                 [](int b, int) {
                                     if (b > 0) throw fm::Error("boom");
                                 }),
                 fm::Error);
    EXPECT_THROW(fm::parallelFor(10, 1, [](int, int) { throw fm::Error("boom"); }), fm::Error);
    std::atomic<int> sum{0};
    fm::parallelFor(100, 2, [&](int b, int e) { sum += e - b; });
    EXPECT_EQ(sum.load(), 100);
}

}  // namespace

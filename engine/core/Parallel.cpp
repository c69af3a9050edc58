#include "core/Parallel.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace fm {

int defaultThreadCount() {
    const unsigned n = std::thread::hardware_concurrency();
    return n == 0 ? 1 : static_cast<int>(n);
}

void parallelFor(int count, int threads, const std::function<void(int, int)>& body,
                 int chunksPerThread) {
    if (count <= 0) return;
    if (threads <= 0) threads = defaultThreadCount();
    threads = std::min(threads, count);
    const int chunks = std::min(count, threads * std::max(1, chunksPerThread));
    auto chunkBegin = [&](int c) {
        return static_cast<int>(static_cast<long long>(c) * count / chunks);
    };
    if (threads == 1) {
        for (int c = 0; c < chunks; ++c) body(chunkBegin(c), chunkBegin(c + 1));
        return;
    }
    std::atomic<int> next{0};
    std::exception_ptr failure;
    std::mutex failureMutex;
    auto worker = [&] {
        for (int c = next++; c < chunks; c = next++) {
            try {
                body(chunkBegin(c), chunkBegin(c + 1));
            } catch (...) {
                std::lock_guard<std::mutex> lock(failureMutex);
                if (!failure) failure = std::current_exception();
            }
        }
    };
    std::vector<std::thread> pool;
    pool.reserve(threads - 1);
    for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
    worker();
    for (auto& t : pool) t.join();
    if (failure) std::rethrow_exception(failure);
}

}  // namespace fm

#pragma once
// Deterministic parallel loop: [0, count) is cut into fixed contiguous chunks that depend only
// on count and the thread count, so results never depend on scheduling.
#include <functional>

namespace fm {

// Number of threads to use when the caller asks for 0 ("all cores").
int defaultThreadCount();

// Calls body(begin, end) for contiguous chunks covering [0, count), on up to `threads` threads
// (0 = defaultThreadCount()). Chunk c covers [c*count/chunks, (c+1)*count/chunks).
// `chunksPerThread` > 1 gives load balancing while staying deterministic: chunk boundaries are
// fixed, only which thread runs a chunk varies, and chunks must write disjoint outputs.
// Exceptions thrown by body are rethrown on the calling thread.
void parallelFor(int count, int threads, const std::function<void(int begin, int end)>& body,
                 int chunksPerThread = 1);

}  // namespace fm

#include "core/Parallel.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace fm {
namespace {

// True on a thread while it runs chunks of a parallelFor: a parallelFor called from inside a
// body runs its chunks inline (same chunk boundaries, so the same result) instead of waiting
// for workers that are busy with the outer loop.
thread_local bool tRunningChunks = false;

// One parallelFor call. Lives on the caller's stack; workers touch it only between joining
// (under the pool mutex, while the job is open) and leaving (active back to 0).
struct Job {
    const std::function<void(int, int)>* body = nullptr;
    int count = 0;
    int chunks = 0;
    std::atomic<int> next{0};
    int helpersWanted = 0;  // threads - 1: never more threads than the caller asked for
    int helpersJoined = 0;      // guarded by the pool mutex, as are the two below
    std::atomic<int> active{0};  // changed under the mutex; read without it while spinning
    bool closed = false;
    std::exception_ptr failure;
    std::mutex failureMutex;

    void runChunks() {
        const bool outer = tRunningChunks;
        tRunningChunks = true;
        for (int c = next++; c < chunks; c = next++) {
            const int begin = static_cast<int>(static_cast<long long>(c) * count / chunks);
            const int end = static_cast<int>(static_cast<long long>(c + 1) * count / chunks);
            try {
                (*body)(begin, end);
            } catch (...) {
                std::lock_guard<std::mutex> lock(failureMutex);
                if (!failure) failure = std::current_exception();
                next = chunks;  // the call fails anyway: hand out no further chunks
            }
        }
        tRunningChunks = outer;
    }
};

// A hint to the core that this is a wait loop (x86 PAUSE; elsewhere nothing).
inline void spinPause() {
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#endif
}

// Worker threads kept between calls: starting threads for every call cost about 35 us per
// parallelFor here, a tenth of a small marching-cubes run and a visible share of a DRR frame.
class WorkerPool {
  public:
    ~WorkerPool() {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            shutdown_ = true;
        }
        wake_.notify_all();
        for (auto& t : workers_) t.join();
    }

    // Runs the job with up to job.helpersWanted workers. Returns false without running
    // anything when another thread's job holds the pool.
    bool run(Job& job) {
        std::unique_lock<std::mutex> submit(submitMutex_, std::try_to_lock);
        if (!submit.owns_lock()) return false;
        {
            std::lock_guard<std::mutex> lock(mutex_);
            while (static_cast<int>(workers_.size()) < job.helpersWanted)
                workers_.emplace_back([this] { workerLoop(); });
            job_ = &job;
            ++generation_;
        }
        wake_.notify_all();
        job.runChunks();
        std::unique_lock<std::mutex> lock(mutex_);
        job.closed = true;
        job_ = nullptr;
        if (job.active != 0) {
            // The workers are finishing their last chunks: wait for them awake (see spinUntil).
            lock.unlock();
            spinUntil([&] { return job.active.load(std::memory_order_acquire) == 0; });
            lock.lock();
        }
        done_.wait(lock, [&] { return job.active == 0; });
        return true;
    }

  private:
    void workerLoop() {
        std::uint64_t seen = 0;
        std::unique_lock<std::mutex> lock(mutex_);
        for (;;) {
            if (generation_.load(std::memory_order_relaxed) == seen && !shutdown_) {
                lock.unlock();
                spinUntil([&] { return generation_.load(std::memory_order_relaxed) != seen; });
                lock.lock();
            }
            wake_.wait(lock, [&] { return shutdown_ || generation_ != seen; });
            if (shutdown_) return;
            seen = generation_;
            Job* job = job_;
            if (!job || job->closed || job->helpersJoined >= job->helpersWanted) continue;
            ++job->helpersJoined;
            ++job->active;
            lock.unlock();
            job->runChunks();
            lock.lock();
            if (--job->active == 0) done_.notify_all();
        }
    }

    // Waits awake, up to kSpinTime, until done() (a new job for a worker, the helpers gone for
    // the caller) before the condition variable puts the thread to sleep: the passes of one
    // algorithm follow each other within microseconds, and a sleeping thread took 40-60 us to
    // wake here (a VM with 2 cores), most of a small pass. (Yielding instead of PAUSE cost
    // about 8 us per wake-up here.) After kSpinTime it sleeps: an idle app uses no CPU.
    template <class Done>
    static void spinUntil(Done done) {
        const auto until = std::chrono::steady_clock::now() + kSpinTime;
        for (int i = 1; !done(); ++i) {
            spinPause();
            if (i % 64 == 0 && std::chrono::steady_clock::now() >= until) return;
        }
    }
    static constexpr std::chrono::microseconds kSpinTime{100};

    std::mutex submitMutex_;  // one job at a time
    std::mutex mutex_;
    std::condition_variable wake_, done_;
    std::vector<std::thread> workers_;
    Job* job_ = nullptr;
    std::atomic<std::uint64_t> generation_{0};  // written under mutex_, also read in spins
    bool shutdown_ = false;
};

WorkerPool& pool() {
    static WorkerPool instance;
    return instance;
}

// Fallback while the pool serves another caller thread: threads of our own, as before.
void runOnFreshThreads(Job& job, int threads) {
    std::vector<std::thread> helpers;
    helpers.reserve(threads - 1);
    for (int t = 1; t < threads; ++t) helpers.emplace_back([&] { job.runChunks(); });
    job.runChunks();
    for (auto& t : helpers) t.join();
}

}  // namespace

int defaultThreadCount() {
    const unsigned n = std::thread::hardware_concurrency();
    return n == 0 ? 1 : static_cast<int>(n);
}

void parallelFor(int count, int threads, const std::function<void(int, int)>& body,
                 int chunksPerThread) {
    if (count <= 0) return;
    if (threads <= 0) threads = defaultThreadCount();
    threads = std::min(threads, count);
    Job job;
    job.body = &body;
    job.count = count;
    job.chunks = std::min(count, threads * std::max(1, chunksPerThread));
    job.helpersWanted = threads - 1;
    if (threads == 1 || tRunningChunks)
        job.runChunks();
    else if (!pool().run(job))
        runOnFreshThreads(job, threads);
    if (job.failure) std::rethrow_exception(job.failure);
}

}  // namespace fm

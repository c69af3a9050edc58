#include "MpiTransport.h"

#include <algorithm>
#include <chrono>
#include <climits>
#include <string>
#include <thread>

#include <mpi.h>

#include "core/Error.h"

namespace fm::distributed {

MpiTransport::MpiTransport() {
    int provided = MPI_THREAD_SINGLE;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
    if (provided < MPI_THREAD_FUNNELED)
        throw Error("MPI: the library does not support worker threads (MPI_THREAD_FUNNELED)");
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
    // The ranks sharing this host's memory (MPI-3), so --threads 0 can split its cores.
    MPI_Comm host;
    MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, rank_, MPI_INFO_NULL, &host);
    MPI_Comm_size(host, &ranksOnHost_);
    MPI_Comm_free(&host);
}

MpiTransport::~MpiTransport() {
    int finalized = 0;
    MPI_Finalized(&finalized);
    if (!finalized) MPI_Finalize();
}

void MpiTransport::gather(std::span<const std::byte> mine, std::span<std::byte> all) {
    if (mine.size() > static_cast<std::size_t>(INT_MAX))
        throw Error("MPI: one gather of " + std::to_string(mine.size()) +
                    " bytes exceeds the 2 GiB a single MPI count can hold");
    const int bytes = static_cast<int>(mine.size());
    MPI_Request request = MPI_REQUEST_NULL;
    MPI_Igather(mine.data(), bytes, MPI_BYTE, rank_ == 0 ? all.data() : nullptr, bytes, MPI_BYTE,
                0, MPI_COMM_WORLD, &request);
    // Waited for by polling with pauses, not in MPI_Wait: Open MPI's blocking calls spin, so a rank
    // whose jobs are done took a core from the ranks still working (and from their threads) on a
    // host with fewer cores than ranks and threads. The pauses grow to 5 ms, next to jobs of seconds.
    auto pause = std::chrono::microseconds(50);
    for (int done = 0;;) {
        MPI_Test(&request, &done, MPI_STATUS_IGNORE);
        if (done) return;
        std::this_thread::sleep_for(pause);
        pause = std::min(2 * pause, std::chrono::microseconds(5000));
    }
}

void MpiTransport::abortAll(int exitCode) {
    int finalized = 0;
    MPI_Finalized(&finalized);
    if (size_ > 1 && !finalized) MPI_Abort(MPI_COMM_WORLD, exitCode);
}

}  // namespace fm::distributed

#include "MpiTransport.h"

#include <climits>
#include <string>

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
    MPI_Gather(mine.data(), bytes, MPI_BYTE, rank_ == 0 ? all.data() : nullptr, bytes, MPI_BYTE,
               0, MPI_COMM_WORLD);
}

void MpiTransport::abortAll(int exitCode) {
    int finalized = 0;
    MPI_Finalized(&finalized);
    if (size_ > 1 && !finalized) MPI_Abort(MPI_COMM_WORLD, exitCode);
}

}  // namespace fm::distributed

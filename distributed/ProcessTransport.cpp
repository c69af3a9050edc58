#include "ProcessTransport.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "core/Error.h"
#include "core/Parallel.h"
#ifdef FM_WITH_MPI
#include "MpiTransport.h"
#endif

namespace fm::distributed {

namespace {
int envInt(const char* name) {
    const char* v = std::getenv(name);
    if (!v || !*v) return -1;
    char* end = nullptr;
    const long n = std::strtol(v, &end, 10);
    return (*end == 0 && n >= 0 && n < 1000000) ? static_cast<int>(n) : -1;
}
Transport* gStarted = nullptr;  // the transport processTransport() handed out, if any
}  // namespace

int launcherProcessCount() {
    if (const int n = envInt("OMPI_COMM_WORLD_SIZE"); n > 0) return n;
    if (const int n = envInt("PMI_SIZE"); n > 0) return n;
    // PMIx gives a rank but no size variable; the size is known after MPI_Init.
    if (envInt("PMIX_RANK") >= 0) return 1;
    return 0;
}

bool builtWithMpi() {
#ifdef FM_WITH_MPI
    return true;
#else
    return false;
#endif
}

Transport& processTransport() {
    const int launched = launcherProcessCount();
#ifdef FM_WITH_MPI
    if (launched > 0) {
        static MpiTransport mpi;
        gStarted = &mpi;
        return mpi;
    }
#else
    // Without MPI every started process would do all the work and write the same outputs.
    if (launched > 1)
        throw Error("started by an MPI launcher with " + std::to_string(launched) +
                    " processes, but this fluoromatch was built without MPI (install "
                    "libopenmpi-dev and rebuild, or run it without mpirun)");
#endif
    static LocalTransport local;
    return local;
}

void endRunAfterError(int exitCode) {
    if (gStarted) gStarted->abortAll(exitCode);
}

void silenceStandardOutput() {
    std::fflush(stdout);
    if (!std::freopen("/dev/null", "w", stdout))
        throw Error("cannot send standard output to /dev/null");
}

int threadsPerRank(const Transport& transport, int requested) {
    if (requested > 0) return requested;
    return std::max(1, defaultThreadCount() / std::max(1, transport.ranksOnThisHost()));
}

}  // namespace fm::distributed

#pragma once
// The transport of this process: MPI when the executable was built with MPI and started by an
// MPI launcher (mpirun/mpiexec, srun), otherwise one local process. MPI is initialised on the
// first call (only commands that distribute work call it) and finalised at exit.
//
// "Started by a launcher" is read from the environment before MPI_Init, so that a plain run
// never initialises MPI: OMPI_COMM_WORLD_SIZE (Open MPI), PMIX_RANK (PMIx: Open MPI 4+, srun
// --mpi=pmix), PMI_SIZE (MPICH Hydra, srun --mpi=pmi2).
#include "Transport.h"
#include "core/Error.h"

namespace fm::distributed {

Transport& processTransport();

// The launcher's process count read from the environment (0: not started by a launcher).
int launcherProcessCount();

// Threads for each rank when the user asked for 0 ("all cores"): this host's cores shared
// between the ranks on it, never the whole host's count for every rank.
int threadsPerRank(const Transport& transport, int requested);

// Thrown by a command once every rank has finished its jobs and some jobs failed: the run then
// ends normally, non-zero, instead of aborting the other ranks.
class JobsFailed : public Error {
  public:
    using Error::Error;
};

// For main(): after any other error, which perhaps only this rank met (a file it could not
// read or write), end every rank of a distributed run so that none waits for this one. Does
// nothing when no distributed run was started.
void endRunAfterError(int exitCode);

// For ranks other than 0: a command's report is printed once, by rank 0, so the others send
// their standard output to /dev/null (warnings and errors on standard error stay).
void silenceStandardOutput();

// True in a build with MPI.
bool builtWithMpi();

}  // namespace fm::distributed

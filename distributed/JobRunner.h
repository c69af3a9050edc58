#pragma once
// Indexed jobs -> fixed-size result records -> rank 0 writes. The one mechanism behind every
// distributed command (evaluate: one job per registration; batch DRRs: one per pose;
// track: one per bone x keyframe segment).
//
//   runIndexedJobs(transport, jobCount, sizeof(Record),
//       [&](int job, std::span<std::byte> record) { ...compute job, fill record... },
//       [&](int job, std::span<const std::byte> record) { ...rank 0: write it... });
//
// Assignment is static and cyclic: job j runs on rank j % size (no coordinator, no messages
// while jobs run). Jobs run in rounds so that rank 0 never holds more than `maxRoundBytes` of
// records; after each round rank 0 gets every record of the round (one gather) and passes them
// to the sink in job order (a single process has rounds of one job: the sink sees each job as
// soon as it ends). So the sink sees the same records in the same order whatever the
// rank count, provided a job's result depends only on its index (derive its seed with
// jobSeed(seed, job), never from the rank). A record starts zeroed, so bytes a job does not
// write are the same everywhere. Records are copied byte for byte: every host of a run must
// share the data layout (same executable on the same architecture).
//
// Failures: a job that throws is reported (job, rank, message) and the rank goes on with its
// other jobs; a sink that throws on rank 0 fails that job the same way. The caller decides
// what a failure means (the commands write what succeeded and exit non-zero naming the jobs).
// A crash (signal) is not caught: the launcher then ends the whole run.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "Transport.h"

namespace fm::distributed {

struct JobFailure {
    int job = 0;
    int rank = 0;
    std::string message;
};

using JobBody = std::function<void(int job, std::span<std::byte> record)>;
using RecordSink = std::function<void(int job, std::span<const std::byte> record)>;
// Called on every rank after each of its own jobs: done and total count this rank's jobs.
using JobDone = std::function<void(int job, int done, int total)>;

inline constexpr std::size_t kDefaultRoundBytes = std::size_t(64) << 20;
inline constexpr std::size_t kMaxRecordBytes = std::size_t(1) << 30;
inline constexpr std::size_t kFailureMessageBytes = 240;  // longer messages are cut

// Collective: every rank calls it with the same jobCount and recordBytes. Returns the failures
// of every job on rank 0 (in job order), this rank's own elsewhere. Throws fm::Error for a
// negative count or a record larger than kMaxRecordBytes.
std::vector<JobFailure> runIndexedJobs(Transport& transport, int jobCount, std::size_t recordBytes,
                                       const JobBody& body, const RecordSink& sink,
                                       const JobDone& done = {},
                                       std::size_t maxRoundBytes = kDefaultRoundBytes);

// Bytes one job moves to rank 0: its record plus the slot header (state, job, message).
std::size_t bytesPerJob(std::size_t recordBytes);

// The jobs rank `rank` of `size` runs: ceil((jobCount - rank) / size).
int jobsOfRank(int jobCount, int rank, int size);

// "job 3 (rank 1): message; job 7 (rank 1): message".
std::string describeFailures(const std::vector<JobFailure>& failures);

// A job's own seed from the run's seed and the job index (SplitMix64 output of both), so that
// results never depend on which rank ran the job.
std::uint64_t jobSeed(std::uint64_t seed, std::uint64_t job);

}  // namespace fm::distributed

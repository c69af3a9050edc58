// The indexed-job runner over this process's transport. Run plainly (ctest) it is one process;
// tests/distributed/mpi_runs_test.sh also runs this executable under mpirun with 2 and 3 ranks,
// where every assertion must hold as well: records reach rank 0 complete and in job order, job
// j runs on rank j % size, failures name their job and rank and the other jobs still finish.
#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <span>
#include <string>
#include <vector>

#include "core/Error.h"
#include "distributed/JobRunner.h"
#include "distributed/ProcessTransport.h"

namespace fm::distributed {
namespace {

struct Record {
    std::int64_t job;
    std::int64_t square;
    std::int64_t ranOn;
};

// Runs `count` jobs whose record is (job, job^2, rank); returns what rank 0's sink saw.
std::vector<Record> runSquares(int count, std::size_t roundBytes, std::vector<JobFailure>* failures,
                               int failEvery = 0, int sinkFailsAt = -1) {
    Transport& t = processTransport();
    std::vector<Record> seen;
    std::vector<int> doneCalls;
    const auto f = runIndexedJobs(
        t, count, sizeof(Record),
        [&](int job, std::span<std::byte> record) {
            // Records arrive zeroed.
            for (std::byte b : record) ASSERT_EQ(b, std::byte{0});
            if (failEvery > 0 && job % failEvery == 1)
                throw Error("bad job " + std::to_string(job));
            const Record r{job, std::int64_t(job) * job, t.rank()};
            std::memcpy(record.data(), &r, sizeof r);
        },
        [&](int job, std::span<const std::byte> record) {
            EXPECT_EQ(t.rank(), 0) << "only rank 0 receives records";
            if (job == sinkFailsAt) throw Error("disk full");
            Record r;
            std::memcpy(&r, record.data(), sizeof r);
            EXPECT_EQ(r.job, job);
            seen.push_back(r);
        },
        [&](int job, int done, int total) {
            EXPECT_EQ(job % t.size(), t.rank());
            EXPECT_EQ(total, jobsOfRank(count, t.rank(), t.size()));
            doneCalls.push_back(done);
        },
        roundBytes);
    // Every rank ran exactly its share, counted 1, 2, ...
    EXPECT_EQ(static_cast<int>(doneCalls.size()), jobsOfRank(count, t.rank(), t.size()));
    for (std::size_t i = 0; i < doneCalls.size(); ++i) EXPECT_EQ(doneCalls[i], int(i) + 1);
    if (failures) *failures = f;
    return seen;
}

TEST(JobRunner, JobsOfRankSplitsCyclically) {
    EXPECT_EQ(jobsOfRank(10, 0, 3), 4);  // 0 3 6 9
    EXPECT_EQ(jobsOfRank(10, 1, 3), 3);  // 1 4 7
    EXPECT_EQ(jobsOfRank(10, 2, 3), 3);  // 2 5 8
    EXPECT_EQ(jobsOfRank(2, 2, 3), 0);
    EXPECT_EQ(jobsOfRank(0, 0, 1), 0);
    EXPECT_EQ(jobsOfRank(7, 0, 1), 7);
}

TEST(JobRunner, RecordsReachRankZeroInJobOrder) {
    std::vector<JobFailure> failures;
    for (std::size_t roundBytes : {kDefaultRoundBytes, std::size_t(1)}) {  // one round; 1 job/rank
        const auto seen = runSquares(17, roundBytes, &failures);
        EXPECT_TRUE(failures.empty()) << describeFailures(failures);
        if (processTransport().rank() != 0) {
            EXPECT_TRUE(seen.empty());
            continue;
        }
        ASSERT_EQ(seen.size(), 17u);
        for (int j = 0; j < 17; ++j) {
            EXPECT_EQ(seen[j].job, j);
            EXPECT_EQ(seen[j].square, std::int64_t(j) * j);
            EXPECT_EQ(seen[j].ranOn, j % processTransport().size());
        }
    }
}

TEST(JobRunner, FailedJobsAreNamedAndTheOthersFinish) {
    std::vector<JobFailure> failures;
    const auto seen = runSquares(14, 1, &failures, /*failEvery=*/4);  // jobs 1, 5, 9, 13 throw
    const int size = processTransport().size();
    const int rank = processTransport().rank();
    std::vector<int> expected;
    for (int j : {1, 5, 9, 13})
        if (rank == 0 || j % size == rank) expected.push_back(j);
    ASSERT_EQ(failures.size(), expected.size()) << describeFailures(failures);
    for (std::size_t i = 0; i < failures.size(); ++i) {
        EXPECT_EQ(failures[i].job, expected[i]);
        EXPECT_EQ(failures[i].rank, expected[i] % size);
        EXPECT_EQ(failures[i].message, "bad job " + std::to_string(expected[i]));
    }
    if (rank == 0) {
        ASSERT_EQ(seen.size(), 10u);  // every job that did not throw
        for (const Record& r : seen) EXPECT_NE(r.job % 4, 1);
        EXPECT_NE(describeFailures(failures).find("job 5 (rank " + std::to_string(5 % size) +
                                                  "): bad job 5"),
                  std::string::npos);
    }
}

TEST(JobRunner, AFailingWriteFailsThatJobOnly) {
    std::vector<JobFailure> failures;
    const auto seen = runSquares(6, kDefaultRoundBytes, &failures, 0, /*sinkFailsAt=*/2);
    if (processTransport().rank() != 0) {
        EXPECT_TRUE(failures.empty());
        return;
    }
    ASSERT_EQ(failures.size(), 1u);
    EXPECT_EQ(failures[0].job, 2);
    EXPECT_EQ(failures[0].rank, 0);
    EXPECT_EQ(failures[0].message, "writing: disk full");
    EXPECT_EQ(seen.size(), 5u);
}

TEST(JobRunner, LongMessagesAreCut) {
    Transport& t = processTransport();
    const auto failures = runIndexedJobs(
        t, 1, 8, [](int, std::span<std::byte>) { throw Error(std::string(1000, 'x')); },
        [](int, std::span<const std::byte>) {});
    if (t.rank() != 0) return;
    ASSERT_EQ(failures.size(), 1u);
    EXPECT_EQ(failures[0].message, std::string(kFailureMessageBytes - 1, 'x'));
}

TEST(JobRunner, NoJobsAndBadSizes) {
    Transport& t = processTransport();
    int calls = 0;
    auto count = [&](int, std::span<std::byte>) { ++calls; };
    auto sink = [&](int, std::span<const std::byte>) { ++calls; };
    EXPECT_TRUE(runIndexedJobs(t, 0, 16, count, sink).empty());
    EXPECT_EQ(calls, 0);
    EXPECT_THROW(runIndexedJobs(t, -1, 16, count, sink), Error);
    EXPECT_THROW(runIndexedJobs(t, 3, kMaxRecordBytes + 1, count, sink), Error);
    EXPECT_EQ(calls, 0);
}

TEST(JobRunner, JobSeedIsSplitMixOfSeedThenIndex) {
    // Values from an independent SplitMix64 (Python): next(next(seed) ^ job). next(0) is the
    // published first output of SplitMix64 seeded with 0, 0xe220a8397b1dcdaf.
    EXPECT_EQ(jobSeed(1, 0), 0x5e41ab087439611eull);
    EXPECT_EQ(jobSeed(1, 1), 0xe9fd6049d65af21eull);
    EXPECT_EQ(jobSeed(42, 7), 0x16062d6c1339e500ull);
}

TEST(JobRunner, ThreadsPerRankNeverExceedTheHost) {
    LocalTransport local;
    EXPECT_EQ(threadsPerRank(local, 3), 3);
    EXPECT_GE(threadsPerRank(local, 0), 1);
    Transport& t = processTransport();
    EXPECT_GE(threadsPerRank(t, 0), 1);
    EXPECT_GE(t.ranksOnThisHost(), 1);
    EXPECT_LE(t.ranksOnThisHost(), t.size());
}

TEST(JobRunner, TransportMatchesTheLauncher) {
    Transport& t = processTransport();
    const int launched = launcherProcessCount();
    if (launched == 0) {
        EXPECT_EQ(t.size(), 1);
        EXPECT_STREQ(t.name(), "single process");
    } else if (builtWithMpi()) {
        EXPECT_STREQ(t.name(), "MPI");
        if (const char* n = std::getenv("OMPI_COMM_WORLD_SIZE")) {
            EXPECT_EQ(t.size(), std::atoi(n));
        }
    }
    EXPECT_GE(t.rank(), 0);
    EXPECT_LT(t.rank(), t.size());
}

}  // namespace
}  // namespace fm::distributed

#include "JobRunner.h"

#include <algorithm>
#include <cstring>
#include <exception>

#include "core/Error.h"
#include "core/Random.h"

namespace fm::distributed {

namespace {

// A slot on the wire: header, then the job's record.
enum class SlotState : std::int32_t { Empty = 0, Done = 1, Failed = 2 };
struct SlotHeader {
    SlotState state = SlotState::Empty;
    std::int32_t job = -1;
    char message[kFailureMessageBytes] = {};
};

void setMessage(SlotHeader& h, const std::string& message) {
    const std::size_t n = std::min(message.size(), kFailureMessageBytes - 1);
    std::memcpy(h.message, message.data(), n);
    h.message[n] = 0;
}

std::string errorText(std::exception_ptr e) {
    try {
        std::rethrow_exception(e);
    } catch (const std::exception& x) {
        return x.what();
    } catch (...) {
        return "unknown exception";
    }
}

}  // namespace

std::size_t bytesPerJob(std::size_t recordBytes) { return sizeof(SlotHeader) + recordBytes; }

int jobsOfRank(int jobCount, int rank, int size) {
    return jobCount > rank ? (jobCount - rank + size - 1) / size : 0;
}

std::vector<JobFailure> runIndexedJobs(Transport& transport, int jobCount, std::size_t recordBytes,
                                       const JobBody& body, const RecordSink& sink,
                                       const JobDone& done, std::size_t maxRoundBytes) {
    if (jobCount < 0) throw Error("jobs: negative job count");
    if (recordBytes > kMaxRecordBytes)
        throw Error("jobs: a record of " + std::to_string(recordBytes) + " bytes exceeds " +
                    std::to_string(kMaxRecordBytes));
    const int rank = transport.rank();
    const int size = transport.size();
    const std::size_t slotBytes = bytesPerJob(recordBytes);
    // Jobs per rank per round: rank 0's buffer (size * perRank slots) stays within the limit.
    // One process waits for nobody: its rounds are single jobs, so the sink sees each at once.
    const std::size_t fit =
        size == 1 ? 1 : maxRoundBytes / (slotBytes * static_cast<std::size_t>(size));
    const int perRank = static_cast<int>(std::clamp<std::size_t>(
        fit, 1, static_cast<std::size_t>(std::max(1, jobsOfRank(jobCount, 0, size)))));
    const int roundSpan = perRank * size;
    const int myTotal = jobsOfRank(jobCount, rank, size);

    std::vector<std::byte> mine(slotBytes * perRank);
    std::vector<std::byte> all(rank == 0 ? slotBytes * roundSpan : 0);
    std::vector<JobFailure> failures;
    int myDone = 0;
    for (int base = 0; base < jobCount; base += roundSpan) {
        std::fill(mine.begin(), mine.end(), std::byte{0});
        for (int i = 0; i < perRank; ++i) {
            const int job = base + i * size + rank;
            if (job >= jobCount) break;
            std::byte* slot = mine.data() + slotBytes * i;
            SlotHeader header;
            header.job = job;
            try {
                body(job, std::span<std::byte>(slot + sizeof(SlotHeader), recordBytes));
                header.state = SlotState::Done;
            } catch (...) {
                header.state = SlotState::Failed;
                setMessage(header, errorText(std::current_exception()));
                std::memset(slot + sizeof(SlotHeader), 0, recordBytes);
                if (rank != 0) failures.push_back({job, rank, header.message});
            }
            std::memcpy(slot, &header, sizeof header);
            ++myDone;
            if (done) done(job, myDone, myTotal);
        }
        transport.gather(mine, all);
        if (rank != 0) continue;
        for (int job = base; job < std::min(jobCount, base + roundSpan); ++job) {
            const int offset = job - base;
            const int from = offset % size;
            const std::byte* slot =
                all.data() + slotBytes * (static_cast<std::size_t>(from) * perRank + offset / size);
            SlotHeader header;
            std::memcpy(&header, slot, sizeof header);
            header.message[kFailureMessageBytes - 1] = 0;
            if (header.state != SlotState::Done || header.job != job) {
                failures.push_back({job, from,
                                    header.state == SlotState::Failed
                                        ? std::string(header.message)
                                        : "no result received"});
                continue;
            }
            try {
                sink(job, std::span<const std::byte>(slot + sizeof(SlotHeader), recordBytes));
            } catch (...) {
                failures.push_back({job, 0, "writing: " + errorText(std::current_exception())});
            }
        }
    }
    return failures;
}

std::string describeFailures(const std::vector<JobFailure>& failures) {
    std::string out;
    for (const JobFailure& f : failures) {
        if (!out.empty()) out += "; ";
        out += "job " + std::to_string(f.job) + " (rank " + std::to_string(f.rank) + "): " +
               f.message;
    }
    return out;
}

std::uint64_t jobSeed(std::uint64_t seed, std::uint64_t job) {
    // Rng(x).next() is SplitMix64's output function of x: mix the seed, then the index.
    return Rng(Rng(seed).next() ^ job).next();
}

}  // namespace fm::distributed

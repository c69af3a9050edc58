#pragma once
// How the processes of one run talk: the only place where a distributed run and a
// single-process run differ. Everything above it (distributed/JobRunner.h, the commands) is the
// same code for both. Implementations: LocalTransport (one process, always built) and
// MpiTransport (distributed/MpiTransport.cpp, only when CMake found MPI).
#include <cstddef>
#include <cstring>
#include <span>

namespace fm::distributed {

class Transport {
  public:
    virtual ~Transport() = default;
    virtual int rank() const = 0;  // 0 .. size()-1; rank 0 alone writes outputs
    virtual int size() const = 0;
    virtual int ranksOnThisHost() const = 0;  // to share the host's cores between them
    virtual const char* name() const = 0;
    // Collective (every rank calls it with the same byte count): rank 0 receives every rank's
    // `mine`, in rank order, in `all` (size() * mine.size() bytes); `all` is unused elsewhere.
    virtual void gather(std::span<const std::byte> mine, std::span<std::byte> all) = 0;
    // Ends every process of the run with `exitCode` (after an error that perhaps only this
    // process saw, so that no other waits for it forever). Returns only for one process.
    virtual void abortAll(int exitCode) = 0;
};

// One process: rank 0 of 1.
class LocalTransport final : public Transport {
  public:
    int rank() const override { return 0; }
    int size() const override { return 1; }
    int ranksOnThisHost() const override { return 1; }
    const char* name() const override { return "single process"; }
    void gather(std::span<const std::byte> mine, std::span<std::byte> all) override {
        if (!mine.empty()) std::memcpy(all.data(), mine.data(), mine.size());
    }
    void abortAll(int) override {}
};

}  // namespace fm::distributed

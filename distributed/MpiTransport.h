#pragma once
// The Transport over MPI (plain MPI-3 C API: Open MPI and MPICH alike). Built only when CMake
// found MPI (FM_WITH_MPI). MPI is initialised by the constructor (MPI_THREAD_FUNNELED: worker
// threads compute, only the main thread calls MPI) and finalised by the destructor.
#include "Transport.h"

namespace fm::distributed {

class MpiTransport final : public Transport {
  public:
    MpiTransport();
    ~MpiTransport() override;
    MpiTransport(const MpiTransport&) = delete;
    MpiTransport& operator=(const MpiTransport&) = delete;

    int rank() const override { return rank_; }
    int size() const override { return size_; }
    int ranksOnThisHost() const override { return ranksOnHost_; }
    const char* name() const override { return "MPI"; }
    void gather(std::span<const std::byte> mine, std::span<std::byte> all) override;
    void abortAll(int exitCode) override;  // MPI_Abort when there are other ranks

  private:
    int rank_ = 0;
    int size_ = 1;
    int ranksOnHost_ = 1;
};

}  // namespace fm::distributed

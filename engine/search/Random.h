#pragma once
// Random numbers that are the same on every platform for a given seed. std::mt19937_64 is
// fully specified by the standard, but std::uniform_real_distribution and
// std::normal_distribution are not (libstdc++ and libc++ give different streams), so the
// distributions are written out here.
#include <cstdint>
#include <random>

namespace fm {

class Rng {
  public:
    explicit Rng(std::uint64_t seed) : engine_(seed) {}

    // Uniform in [0, 1): the top 53 bits of one 64-bit draw.
    double uniform() { return double(engine_() >> 11) * 0x1.0p-53; }
    // Uniform in [lo, hi).
    double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
    // Uniform integer in [0, n) (n > 0), by rejection so that it is unbiased.
    std::uint64_t below(std::uint64_t n);
    // Standard normal, Box-Muller (both values of a pair are used).
    double normal();
    // A sub-stream seed: lets parallel or nested users draw without sharing a generator.
    std::uint64_t split() { return engine_(); }

  private:
    std::mt19937_64 engine_;
    bool hasSpare_ = false;
    double spare_ = 0.0;
};

}  // namespace fm

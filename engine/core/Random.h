#pragma once
// Random numbers that are the same on every platform and standard library for a given seed.
// The engine is Steele, Lea and Flood's SplitMix64 (the seeding generator of xoshiro): tiny,
// fast, and it passes BigCrush. The distributions are written out here because
// std::uniform_real_distribution and std::normal_distribution are not specified bit for bit
// (libstdc++ and libc++ give different streams).
#include <cstdint>

namespace fm {

class Rng {
  public:
    explicit Rng(std::uint64_t seed) : state_(seed) {}

    // The next 64 random bits.
    std::uint64_t next() {
        std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    // Uniform in [0, 1): the top 53 bits of one draw.
    double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
    // Uniform in [lo, hi).
    double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
    // Uniform integer in [0, n) (n > 0), by rejection so that it is unbiased.
    std::uint64_t below(std::uint64_t n);
    // Standard normal, Box-Muller (both values of a pair are used).
    double normal();
    // A sub-stream seed: lets parallel or nested users draw without sharing a generator.
    std::uint64_t split() { return next(); }

  private:
    std::uint64_t state_;
    bool hasSpare_ = false;
    double spare_ = 0.0;
};

}  // namespace fm

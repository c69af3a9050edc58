#pragma once
// Wall milliseconds since a moment: what the commands' timing lines print.
#include <chrono>

namespace fm::cli {

inline double msSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace fm::cli

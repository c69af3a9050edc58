#include "mesh/ClassifyRow.h"

#include <algorithm>
#include <limits>

namespace fm::mc {
namespace {

// Written so that the compiler vectorises both loops: a byte compare per value, and the
// minimum in 8 independent lanes as a select (std::min returns a reference and compiled to
// branches).
[[gnu::always_inline]] inline float classify(const float* src, std::uint8_t* dst, int width,
                                             float iso) {
    for (int x = 0; x < width; ++x) dst[x] = src[x] >= iso;
    float lane[8];
    std::fill(lane, lane + 8, std::numeric_limits<float>::infinity());
    int x = 0;
    for (; x + 8 <= width; x += 8)
        for (int k = 0; k < 8; ++k) lane[k] = src[x + k] < lane[k] ? src[x + k] : lane[k];
    for (; x < width; ++x) lane[0] = src[x] < lane[0] ? src[x] : lane[0];
    float lowest = lane[0];
    for (int k = 1; k < 8; ++k) lowest = lane[k] < lowest ? lane[k] : lowest;
    return lowest;
}

}  // namespace

float classifyRowPortable(const float* src, std::uint8_t* dst, int width, float iso) {
    return classify(src, dst, width, iso);
}

#if defined(__x86_64__) && defined(__GNUC__)
// Twice the values per instruction of the portable build: the pass took 1.3 cycles per voxel
// with SSE2, which kept it from reaching memory speed on volumes held in the cache.
__attribute__((target("avx2"))) float classifyRowAvx2(const float* src, std::uint8_t* dst,
                                                      int width, float iso) {
    return classify(src, dst, width, iso);
}

bool classifyRowAvx2Available() {
    static const bool available = __builtin_cpu_supports("avx2");
    return available;
}
#else
float classifyRowAvx2(const float* src, std::uint8_t* dst, int width, float iso) {
    return classify(src, dst, width, iso);
}

bool classifyRowAvx2Available() {
    return false;
}
#endif

float classifyRow(const float* src, std::uint8_t* dst, int width, float iso) {
    static const auto row = classifyRowAvx2Available() ? classifyRowAvx2 : classifyRowPortable;
    return row(src, dst, width, iso);
}

}  // namespace fm::mc

#pragma once
// Marching cubes' first pass over the voxels, one row at a time: inside (1) where a value is at
// or above the isovalue, else 0 (NaN too), and the row's smallest value (NaN never chosen;
// +inf for a row of NaN). Two builds of the same code: the portable one (SSE2 on x86-64) and
// one for AVX2, chosen once at run time; their outputs are identical.
#include <cstdint>

namespace fm::mc {

float classifyRow(const float* src, std::uint8_t* dst, int width, float iso);

// Both builds, for the test that compares them (the AVX2 one runs only where the CPU has it).
float classifyRowPortable(const float* src, std::uint8_t* dst, int width, float iso);
float classifyRowAvx2(const float* src, std::uint8_t* dst, int width, float iso);
bool classifyRowAvx2Available();

}  // namespace fm::mc

#pragma once
// Freed large blocks stay in the process's heap for the next allocation. A registration makes
// and drops image-sized buffers at every evaluation and every frame (a 1760 x 1760 float frame
// is 12 MB); by default glibc maps each block from the kernel and gives it back on free, and
// every page is faulted in again when it is next written (tracking the wrist radius: 0.55 ->
// 0.35 s of system time for 3 frames). The peak is unchanged: this only keeps what was taken.
// Call once at the start of a program (fluoromatch, the benchmarks); a no-op off glibc.
namespace fm {

void keepFreedMemoryForReuse();

}  // namespace fm

#pragma once
// The largest world coordinate or length (mm) any geometry may use: a kilometre. Far beyond any
// scanner, C-arm or CT, and small enough that every product and sum the geometry and DRR code
// forms (squared lengths, projections over 16384-pixel films) stays finite in double: a value
// that passes these checks can never turn into inf or NaN on the way to an output.
namespace fm {

inline constexpr double kMaxWorldMm = 1e6;

}  // namespace fm

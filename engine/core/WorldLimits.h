#pragma once
// The largest world coordinate or length (mm) any geometry may use: 1e15 mm (a billion km).
// Absurd for any scanner, yet far-away sources and films stay testable; what matters is that
// every product and sum the geometry and DRR code forms (squared lengths ~1e30, times film
// pixel counts ~1e34) stays far inside double range, so a value that passes these checks can
// never turn into inf or NaN on the way to an output. 1e308 is finite, but not this.
namespace fm {

inline constexpr double kMaxWorldMm = 1e15;

}  // namespace fm

// `doublet bench --plot FILE.png`: cost (time / fp32, log scale) against accuracy (bits) per mode,
// one point per op and mode, drawn with the demos' PNG writer (no text: the axes and colours are
// explained in docs/performance.md).
//   x: bits, 20 to 56 (grid every 4 bits; thicker at 24, 48 and 53);
//   y: time / fp32 from 0.1x to 1000x, log scale (grid at each decade; thicker at 1x);
//   colour per mode: fp32 blue, rte orange, df64-fast purple, df64 red, native green;
//   lavapipe rows as filled squares, GLES rows as hollow squares.
// Bits per mode: fp32 24 (its upper bound), native 53, df64 the op's figure in docs/accuracy.md
// (ops without one are left out), rte and df64-fast left out (not measured per op yet).
#pragma once

#include <string>

#include "bench/bench.hpp"

namespace doublet::bench {

// Empty on success, else why the file could not be written. *points: how many were drawn.
std::string write_cost_plot(const BenchReport&, const std::string& path, int* points = nullptr);

}  // namespace doublet::bench

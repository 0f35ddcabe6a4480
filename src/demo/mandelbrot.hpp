// `doublet demo mandelbrot`: one deep-zoom view computed with a double-precision compute shader in
// each mode (fp32, df64 on Mesa GLES; native fp64 on lavapipe), side by side, and how many pixels
// agree with native double.
#pragma once

#include <string>
#include <vector>

#include "demo/modes.hpp"

namespace doublet::demo {

struct MandelbrotOptions {
  std::vector<Mode> modes = all_modes();
  // On the real axis near -1.75: structure down to 1e-12 per pixel that escapes within 1000
  // iterations, so the comparison is not of all-black interiors. (In filament-dense views, e.g.
  // 0.001643721971153,-0.822467633298876, df64 agrees on ~97%: chaotic orbits amplify the
  // difference between its ~48 bits and double's 53 until some counts differ.)
  double center_x = -1.7497591451303665, center_y = 0.0;
  std::vector<double> zooms = {1e-7, 1e-12};  // complex-plane units per pixel, one picture each
  int width = 256, height = 256;
  int max_iterations = 1000;
  std::string out_dir;  // empty: measure only
};

struct MandelbrotModeResult {
  Mode mode = Mode::Fp32;
  double equal_to_native = -1;  // fraction of pixels with native's iteration count; -1 without native
  std::string device;
};

struct MandelbrotView {
  double zoom = 0;
  std::vector<MandelbrotModeResult> modes;
  int native_distinct_counts = 0;  // different iteration counts in native's picture (detail shown)
  std::string file;  // picture written, if any
};

struct MandelbrotResult {
  bool ok = false;
  std::string error;
  std::vector<MandelbrotView> views;
};

MandelbrotResult run_mandelbrot(const MandelbrotOptions&);

// The demo's compute shader as an application would write it (doubles, GLSL ES 3.10).
extern const char* const kMandelbrotComputeShader;

}  // namespace doublet::demo

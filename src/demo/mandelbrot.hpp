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
  // Seahorse valley: detail at every scale, so wrong coordinates show.
  double center_x = -0.743643887037151, center_y = 0.131825904205330;
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

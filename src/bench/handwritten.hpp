// `doublet bench --handwritten`: doublet's lowering against a hand-written float-float library of
// the kind users copy into their shaders today (luma.gl's fp64 module is the model: vec2 (hi, lo)
// values, one function per operation, a `uniform float ONE` multiplied into the steps a compiler
// could fold, Dekker's split). The library is written here from the published algorithms
// (handwritten.cpp, kHandwrittenLibrary), not copied. Everything runs on Mesa GLES in one run:
// per-op dependent chains and the deep-zoom Mandelbrot, time next to accuracy.
#pragma once

#include <string>
#include <vector>

namespace doublet::bench {

struct HandwrittenOptions {
  int elements = 16384;   // per-op kernels: invocations
  int steps = 1024;       // per-op kernels: dependent steps (multiple of 8)
  int warmup = 2;
  int repetitions = 7;
  int mandelbrot_size = 128;          // pixels per side
  int mandelbrot_iterations = 1000;
  double mandelbrot_zoom = 1e-12;     // complex-plane units per pixel
  std::vector<std::string> ops;       // empty: all of handwritten_ops()
};

const std::vector<std::string>& handwritten_ops();  // add sub mul div sqrt mulf addf sqr pow2 mandelbrot

struct HandwrittenRow {
  std::string op;
  std::string variant;       // "handwritten", "doublet es310", "doublet es310 -O0", ...
  bool ok = false;
  std::string note;
  std::vector<double> seconds;
  double median_seconds = 0, min_seconds = 0;
  double speedup_median = 0, speedup_min = 0;  // handwritten time / this time, same op and run
  // Accuracy: per-op kernels: bits (-log2 of the worst relative error after 8 dependent steps,
  // against a long double host reference on the same inputs); Mandelbrot: fraction of pixels
  // whose iteration count equals native fp64's (lavapipe).
  double bits = 0;
  double agree = -1;
  size_t spirv_instructions = 0;
};

struct HandwrittenReport {
  HandwrittenOptions options;
  std::string command;
  std::string device;
  std::vector<HandwrittenRow> rows;
};

bool run_handwritten(const HandwrittenOptions&, HandwrittenReport*, std::string* error);
std::string format_handwritten_markdown(const HandwrittenReport&);

// The hand-written library (GLSL ES 3.10 text, no #version line) and the per-op / Mandelbrot
// shaders built on it; exposed for tests.
extern const char* const kHandwrittenLibrary;
std::string handwritten_kernel(const std::string& op, int steps);
std::string double_kernel(const std::string& op, int steps);  // the same kernel with doubles (#version 450)
// Worst-case accuracy in bits of a per-op kernel's text (either of the two above, or its lowering;
// 8 steps) on Mesa GLES over `elements` inputs, against the long double host reference.
// Returns < 0 and sets *error when the run fails.
double kernel_bits(const std::string& op, const std::string& glsl, int elements, std::string* error);

}  // namespace doublet::bench

// `doublet bench --compile-time`: what a driver takes to turn a shader into its first result, per
// precision mode, on lavapipe and Mesa GLES, for a loop-scaling series (N double operations per
// iteration of a loop the compiler cannot unroll) and for the shaders of a corpus directory (each
// fed as `doublet verify` feeds it, with its FILE.json spec). The browser's share (Chromium WebGL2 and WebGPU)
// is tools/browser/compile-time-suite.mjs. docs/performance.md, "Compile time", shows the output.
#pragma once

#include <string>
#include <vector>

#include "doublet/doublet.hpp"
#include "runner/runner.hpp"

namespace doublet::bench {

struct CompileTimeOptions {
  std::vector<int> ops{1, 2, 4, 8, 16, 32, 64};
  // fp32 (the float twin), native (fp64 as written, lavapipe only) and the compiler's modes.
  std::vector<std::string> modes{"fp32", "native", "df64-fast", "df64", "df64-int", "exact"};
  std::vector<runner::Backend> backends{runner::Backend::Vulkan, runner::Backend::Gles};
  Target target = Target::Es310;
  int rounds = 3;  // each shader compiled this many times, interleaved; the fastest is kept
  // Directories of shaders (x.vert, x.frag, x.comp, x.geom, x.tesc, x.tese; x.json beside one is its
  // verify spec, DIR/include its headers): each shader timed per mode too, one sample each.
  std::vector<std::string> corpus_dirs;
};

struct CompileTimeRow {
  int ops = 0;         // the loop series' row, or
  std::string shader;  // a corpus shader's file name (ops 0)
  std::string mode;
  runner::Backend backend = runner::Backend::Vulkan;
  bool ok = false, not_applicable = false;
  std::string error;
  double compile_seconds = 0;  // time to the first result (its dispatch or draw included), the fastest round
};

// The series' compute shader with `ops` double operations per iteration.
std::string compile_time_kernel(int ops);
std::vector<CompileTimeRow> run_compile_time_bench(const CompileTimeOptions&, std::string* devices);
std::string format_compile_time_markdown(const CompileTimeOptions&, const std::vector<CompileTimeRow>&,
                                         const std::string& command, const std::string& devices);

}  // namespace doublet::bench

// Timed compute dispatches for `doublet bench`: one compiled program, one set of buffers, the same
// dispatch submitted warm-up + repetition times, each repetition timed on the device where the
// driver can (kept apart from runner.hpp so the functional runner stays untouched by benchmarking).
#pragma once

#include <string>
#include <vector>

#include "runner/runner.hpp"

namespace doublet::runner {

struct TimedResult {
  bool ok = false;
  std::string error;
  std::string device;
  // How `seconds` was measured: "vkCmdWriteTimestamp", "GL_EXT_disjoint_timer_query" or
  // "glFinish-bracketed CPU time".
  std::string clock;
  std::vector<double> seconds;                // one per repetition; warm-up runs are not included
  // Wall-clock seconds from the GLSL text to the end of the first dispatch (warm-up or not): the
  // compile (glslang to SPIR-V and the pipeline on Vulkan; glCompileShader/glLinkProgram on GLES),
  // the driver's code generation (llvmpipe may defer it to the first dispatch), uploads and that
  // dispatch. `doublet bench --compile-time` subtracts a dispatch from it.
  double first_result_seconds = 0;
  std::vector<std::vector<uint8_t>> buffers;  // read back after the last repetition
};

// Compilation and pipeline creation happen before the first (warm-up) dispatch and are not timed.
// Buffers are uploaded once; every repetition runs on what the previous one left in them.
TimedResult run_compute_timed(Backend, const ComputeJob& job, int warmup, int repetitions);

}  // namespace doublet::runner

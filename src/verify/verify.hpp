// doublet_verify: runs a user's double shader natively (fp64 on lavapipe) and lowered (float-float on
// lavapipe and/or Mesa GLES), compares every output and reports per-output accuracy. The CLI
// `doublet verify` is a thin layer over verify(); docs/verify.md describes behaviour and JSON.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "doublet/doublet.hpp"
#include "runner/runner.hpp"
#include "verify/metrics.hpp"
#include "verify/probe.hpp"
#include "verify/sabotage.hpp"
#include "verify/spec.hpp"

namespace doublet::verify {

struct VerifyOptions {
  Options lower;  // stage, target, file name, defines, include dirs; guard is set from `sabotage`
  uint64_t samples = 1024;
  uint64_t seed = 1;
  Spec spec;                          // --spec file plus --range entries
  std::optional<double> min_bits;     // default threshold for every output
  std::vector<runner::Backend> backends{runner::Backend::Vulkan, runner::Backend::Gles};
  Sabotage sabotage = Sabotage::None;
  // No threshold given: outputs of a float-float mode (df64, df64-fast, df64-int) must be
  // measurably better than the same shader demoted to float (OutputStats::float_median_bits), so a
  // collapse to float precision (a guard the driver did not honour) never passes. Costs a second run.
  bool judge_against_float = false;
};

// The lowered shader on one backend, against the native one.
struct BackendRun {
  runner::Backend backend{};
  std::string driver;            // renderer that ran the lowered shader
  std::string reference_driver;  // renderer that ran the native fp64 shader
  Probe probe;
  std::vector<OutputStats> outputs;
  std::string error;             // non-empty: the run failed on the driver
};

struct VerifyReport {
  std::string shader, stage, target, mode = "default", sabotage;
  uint64_t samples = 0, seed = 0, dispatches = 0;
  std::string input_error;  // non-empty: bad input (shader, spec, options): nothing ran
  std::vector<std::string> notes;  // inputs left at zero, outputs not compared, skipped backends
  uint64_t inputs_beyond_float_range = 0;  // finite input values fed to both shaders as +-Inf
  std::vector<std::string> inputs; // "u (uniform double)", "x[] (buffer In, dvec2)", ...
  std::vector<BackendRun> runs;
  std::string lowered_glsl;

  bool driver_failed() const;
  bool passed() const;  // every output meets its min_bits (no threshold: always) and nothing failed
};

VerifyReport verify(std::string_view source, const VerifyOptions& options);

// The first dispatch or draw a verify run would make, native and lowered, not run: what
// `doublet bench --compile-time --corpus` times (docs/performance.md). One sample; inputs drawn
// from options.spec and options.seed as verify() draws them. Compute stages fill the compute
// jobs, the others the graphics jobs (GraphicsJob::stage says which stage); `error` is set (and
// nothing else) when the shader does not lower or its interface cannot be fed.
struct FirstJobs {
  std::string error;
  runner::ComputeJob native_compute, lowered_compute;
  runner::GraphicsJob native_graphics, lowered_graphics;
};
FirstJobs first_jobs(std::string_view source, const VerifyOptions& options);

}  // namespace doublet::verify

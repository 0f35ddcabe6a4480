// `doublet bench`: throughput of each operation (or of a user's compute shader) per precision
// mode on lavapipe and Mesa GLES, timed on the device (runner/timed_compute.hpp), with every
// ratio taken between measurements of the same run. docs/modes.md shows the output.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "bench/variants.hpp"
#include "runner/runner.hpp"

namespace doublet::bench {

struct BenchOptions {
  std::vector<std::string> ops;                // kernels() ops; ignored when shader_path is set
  std::vector<Mode> modes{Mode::Fp32, Mode::Df64, Mode::Native};
  std::vector<runner::Backend> backends{runner::Backend::Vulkan, runner::Backend::Gles};
  Target target = Target::Es320;               // df64 lowering target (its default guard)
  int elements = 16384;                        // invocations per dispatch
  int steps = 0;                               // dependent operations per invocation; 0: each kernel's default_steps
  int warmup = 2;                              // dispatches run and discarded before timing
  int repetitions = 7;                         // timed dispatches; the median is reported
  std::string shader_path;                     // non-empty: bench this compute shader with doubles
  std::string shader_source;                   // its text: includes expanded, "#version 450" (user_shader.hpp)
};

struct Measurement {
  std::string op;                  // kernel op, or the shader's file name
  runner::Backend backend = runner::Backend::Vulkan;
  Mode mode = Mode::Fp32;
  bool ok = false;
  bool not_applicable = false;     // the backend cannot run this mode (native on GLES): not a failure
  int steps = 1;                   // dependent operations per invocation
  std::string note;                // why it did not run / failed
  std::vector<double> seconds;     // per repetition
  double median_seconds = 0;
  double min_seconds = 0;          // least disturbed by other load on a shared machine
  double ops_per_second = 0;       // kernels: steps × elements / median; shaders: invocations / median
  std::optional<double> time_vs_fp32;    // median / fp32's median, same op and backend
  std::optional<double> time_vs_native;  // median / native's median, same op (native from lavapipe)
  bool finite_output = true;       // kernels: every stored value finite
  ShaderSize size;
  // Kernels: float operations per step in the variant's SPIR-V (bench/opcount.hpp); -1 unknown.
  double emitted_flops_per_step = -1;
  // Kernels: -log2 of the worst relative error of kUnroll steps against native fp64 on lavapipe
  // (same inputs; capped at 53, which the native row itself scores); -1 not measured.
  double bits = -1;
};

struct BenchReport {
  BenchOptions options;
  std::string command;                          // as typed, for the docs
  std::map<std::string, std::string> devices;   // backend name → device
  std::map<std::string, std::string> clocks;    // backend name → how time was measured
  std::vector<Measurement> rows;
  std::vector<std::string> notes;               // e.g. skipped ops
};

// Runs everything the options ask for. Fails (returns false, *error) only on bad options;
// driver failures become rows with ok == false and a note.
bool run_bench(const BenchOptions& options, BenchReport* report, std::string* error);

const char* backend_key(runner::Backend);  // "vulkan" / "gles"

std::string format_markdown(const BenchReport&);
std::string format_json(const BenchReport&);   // keys documented in docs/modes.md

}  // namespace doublet::bench

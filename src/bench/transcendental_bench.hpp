// `doublet bench --transcendentals [--peer-luma]`: exp log sin cos tan on doubles, time per call and
// bits, in one run: fp32's float built-ins, doublet's df64 rules, the same algorithms in native fp64
// (lavapipe), and with --peer-luma luma.gl's fp64 module (transcendental_kernels.hpp says what each
// variant runs). Every ratio is between medians of the same run; bits are -log2 of the worst
// relative error over the accuracy inputs against the host's long double libm. docs/transcendentals.md
// shows the output.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "bench/transcendental_kernels.hpp"
#include "doublet/doublet.hpp"
#include "runner/runner.hpp"

namespace doublet::bench {

struct TranscendentalOptions {
  std::vector<std::string> functions = transcendental_functions();
  std::vector<runner::Backend> backends{runner::Backend::Vulkan, runner::Backend::Gles};
  Target target = Target::Es320;  // df64 lowering target (its default guard)
  int elements = 16384;           // invocations per timed dispatch
  int steps = 256;                // dependent calls per invocation (multiple of 8): fp32 dispatches of ~5 ms
  int warmup = 2;
  int repetitions = 7;            // the median is reported
  int accuracy_samples = 4096;    // inputs per accuracy domain (multiple of 64)
  bool peer_luma = false;
};

struct TranscendentalRow {
  std::string function;
  runner::Backend backend = runner::Backend::Vulkan;
  TranscendentalVariant variant = TranscendentalVariant::Fp32;
  bool ok = false;
  bool not_applicable = false;  // native on GLES
  std::string note;
  std::vector<double> seconds;
  double median_seconds = 0;
  double ns_per_call = 0;      // median / (elements × steps)
  double ns_per_call_min = 0;  // the fastest repetition, least disturbed by other load
  bool finite_output = true;
  std::optional<double> vs_fp32, vs_native, vs_luma;  // time / that variant's time, same run
  double bits = -1, bits_wide = -1;                    // -1: not measured (bits_wide: sin/cos/tan only)
  std::string worst;                                   // the Main domain's worst input
};

struct TranscendentalReport {
  TranscendentalOptions options;
  std::string command;
  std::map<std::string, std::string> devices, clocks;  // backend key → device / how time was measured
  std::string luma_version;
  std::vector<TranscendentalRow> rows;
  std::vector<std::string> notes;
};

bool run_transcendental_bench(const TranscendentalOptions&, TranscendentalReport*, std::string* error);
std::string format_transcendental_markdown(const TranscendentalReport&);

// One accuracy run (also what tests/numeric/luma_peer_test.cpp asserts on). `guard` applies to the
// df64 lowering (GuardKind::None is the sabotage).
struct AccuracyRun {
  bool ok = false;
  bool not_applicable = false;
  std::string error;
  double min_bits = 0;
  std::string worst;  // input, result and reference of the worst case
};
AccuracyRun transcendental_accuracy(const std::string& function, TranscendentalVariant, runner::Backend, Target,
                                    Domain, int samples, GuardKind guard = GuardKind::Auto);

}  // namespace doublet::bench

// `doublet bench --compiler`: the compiler's own speed. A generated, deterministic double-heavy
// compute shader (about 5,000 lines) is lowered by doublet::lower several times, and parsed by
// glslang alone (the front end's exact setup: desktop 4.50 compatibility, no client, same
// resources and messages) as many times, interleaved in one run; the ratio of the medians is the
// figure (goal: lowering within 1.5x of a parse). The re-validation of the output that
// doublet::lower performs (a glslang parse of the emitted text in the target profile) is timed
// on its own too, as part of the breakdown.
#pragma once

#include <string>
#include <vector>

#include <doublet/doublet.hpp>

namespace doublet::bench {

// A #version 450 compute shader with `lines` lines (approximately), doubles everywhere:
// + - * / sqrt, dot, length, float widening, constants, vectors, loops, user functions.
std::string generate_compiler_shader(int lines, unsigned seed = 1);

struct CompilerOptions {
  int lines = 5000;
  int repetitions = 9;
  Target target = Target::Es320;
  // Further sizes (lines) timed in the same run, for how the cost grows (--scaling).
  std::vector<int> scaling_lines;
};

// One size of the scaling table: minima over the repetitions (at most 3 per size).
struct ScalingRow {
  int lines = 0;
  double parse_seconds = 0, lower_seconds = 0;
  std::vector<std::pair<std::string, double>> phase_seconds;  // of the fastest lowering
};

struct CompilerReport {
  std::string command;
  int lines = 0;               // lines of the generated input
  size_t input_bytes = 0, output_bytes = 0;
  std::vector<double> parse_seconds, lower_seconds, lower_unoptimized_seconds, validate_seconds;
  // Per phase of doublet::lower (Result::phase_seconds), every repetition, in phase order.
  std::vector<std::pair<std::string, std::vector<double>>> phase_seconds;
  double parse_median = 0, lower_median = 0, lower_unoptimized_median = 0, validate_median = 0;
  double parse_min = 0, lower_min = 0;
  double ratio_median = 0, ratio_min = 0;  // lower / parse
  std::vector<ScalingRow> scaling;
  bool ok = false;
  std::string error;
};

bool run_compiler_bench(const CompilerOptions&, CompilerReport*);
std::string format_compiler_markdown(const CompilerReport&);

}  // namespace doublet::bench

// The differential tester's oracles (docs/robustness.md, "Differential testing"): relations between
// runs of one program that need no expected output.
//   exact   — --mode exact is bit-identical to native fp64 built with NoContraction (lavapipe and
//             Mesa GLES, through doublet::verify), NaN payloads and the signs of zeros apart;
//   int     — --mode df64-int returns the same pairs as df64 on every sample where native's value
//             is finite and within float-float's range (the integer and the guarded float
//             error-free transformations are the same functions);
//   bound   — on a continuous program (no comparison, branch, loop or built-in that jumps; compute or
//             vertex), `doublet plan`'s error model bounds every output of df64: the measured
//             max |df64 - native| stays within the planner's df64 estimate plus its binary64
//             estimate (native's own rounding), for the spec's input ranges. This tests the planner
//             as much as the lowering;
//   guard   — the same bound for the df64 lowering with the uniform guard (es310 without
//             GL_EXT_gpu_shader5: the indexed df_guard, no `precise`) on both drivers: a driver
//             that sees through the guard folds error terms and leaves the bound;
//   targets — the df64 lowerings for es310, es320 and glsl450 give the same pairs on lavapipe, and
//             (with webgpu, compute programs) the wgsl lowering in Chromium's WebGPU the same pairs
//             within 2^-40 relative (WGSL's f32 division is not correctly rounded there).
// Every lowering must succeed: the programs are valid GLSL 4.50, so a refusal is a finding too.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace doublet::difftest {

struct Finding {
  std::string oracle;  // "exact", "int", "bound", "guard", "targets", "lowering"
  std::string detail;  // one paragraph: what differs, where, one sample's values
};

struct CheckOptions {
  uint64_t samples = 256;
  std::vector<std::string> oracles{"exact", "int", "bound", "guard", "targets"};
  bool skip_exact = false;  // the program uses a built-in native does not compute as IEEE
  bool webgpu = false;      // also run the wgsl lowering in Chromium (targets)
  // Passes left out of every lowering (Options::skip_passes): a bug put back on purpose, to show
  // that the oracles find it (docs/robustness.md, "Differential testing").
  std::vector<std::string> skip_passes;
  // verify's sabotage, applied to the mode exact, df64-int and uniform-guard runs and to a df64 run
  // of its own for the bound oracle (the other runs are references): each oracle must then report a
  // finding (drop-guard: the guard oracle).
  std::string sabotage = "none";
};

struct CheckResult {
  std::string invalid;                // non-empty: the program itself does not compile natively
  std::vector<std::string> checked;   // oracles that ran to a verdict
  std::vector<Finding> findings;
  std::vector<std::string> notes;     // what was left unchecked and why (a documented refusal)
  std::vector<std::pair<std::string, double>> seconds;  // wall time per verify run ("exact es310", ...)
  uint64_t excused_int_zero_signs = 0;  // int: df64-int's +0 against df64's -0 or the reverse (oracles.cpp)
  uint64_t excused_zero_signs = 0;  // exact: +0 against native's -0 or the reverse (oracles.cpp)
};

// The program compiles as native fp64 GLSL 4.50 the way verify runs it (stage "comp", "vert" or
// "frag"); else *error says why.
bool compiles_natively(const std::string& glsl, const std::string& stage, std::string* error);

// True when the program has nothing that jumps (comparisons, ?:, branches, loops, returns, rounding
// to integers, ...): the planner's linear error model applies to it (docs/plan.md, "Limits").
bool is_continuous(const std::string& glsl);

// `stage`: "comp", "vert" or "frag".
CheckResult check(const std::string& glsl, const std::string& spec_json, const std::string& stage,
                  const CheckOptions& options);

// check() in a forked child that is killed after `seconds`: a driver whose compiler never ends on a
// program (LLVM's loop analysis in llvmpipe has taken over 15 minutes on a generated vertex shader)
// or crashes costs that program, not the run. `timed_out` says it was killed or died; the result
// is then empty. The calling process must not have started a driver (fork keeps one thread).
CheckResult check_in_child(const std::string& glsl, const std::string& spec_json, const std::string& stage,
                           const CheckOptions& options, double seconds, bool* timed_out);

}  // namespace doublet::difftest

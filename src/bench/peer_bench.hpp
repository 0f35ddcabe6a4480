// `doublet bench --peer-mesa-fp64 FILE`: mode exact against Mesa's soft-fp64 (float64.glsl, made
// plain GLSL ES 3.10 by bench/mesa_fp64.hpp), native fp64 and fp32, in one run, on lavapipe and
// on Mesa GLES. Per op (add sub mul div sqrt): a dependent chain timed per variant (in up to 3
// rounds over the variants, so load from elsewhere hits all alike), and a bit-identity check
// of one application of the op to special, boundary and random inputs against native fp64 on
// lavapipe. docs/modes.md ("exact") shows the output.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "doublet/doublet.hpp"
#include "runner/runner.hpp"

namespace doublet::bench {

struct PeerOptions {
  std::string peer_path;            // Mesa's float64.glsl (scripts/fetch-mesa-fp64)
  std::vector<std::string> ops{"add", "sub", "mul", "div", "sqrt"};
  std::vector<runner::Backend> backends{runner::Backend::Vulkan, runner::Backend::Gles};
  Target target = Target::Es310;    // lowering target of fp32 and exact
  int elements = 16384;             // invocations per timed dispatch
  int steps = 512;                  // dependent operations per invocation (multiple of 8)
  int warmup = 2;
  int repetitions = 7;
  int check_inputs = 1 << 16;       // inputs of the bit-identity check per op
};

const std::vector<std::string>& peer_ops();      // add sub mul div sqrt
const std::vector<std::string>& peer_variants();  // fp32 exact mesa native

struct PeerTiming {
  std::string op, variant;
  runner::Backend backend = runner::Backend::Vulkan;
  bool ok = false;
  bool not_applicable = false;  // native on GLES
  std::string note;
  std::vector<double> seconds;
  double median_seconds = 0, min_seconds = 0;
  size_t spirv_instructions = 0;
};

// One application of the op to every check input, compared bit for bit with native fp64 on lavapipe.
struct PeerBits {
  std::string op, variant;  // exact or mesa
  runner::Backend backend = runner::Backend::Vulkan;
  bool ok = false;
  std::string note;
  size_t inputs = 0;
  size_t differing = 0;     // results whose 64 bits differ from native's
  size_t nan_only = 0;      // of those, both NaN (payload or sign differs)
  size_t one_ulp = 0;       // of those, finite and one unit in the last place apart
  size_t flushed = 0;       // of those, zero where native gives a subnormal
  std::string example;      // the first differing non-NaN result: "a, b: got X, native Y" (hex)
};

struct PeerReport {
  PeerOptions options;
  std::string command;
  std::string peer_source;                      // FILE.source as scripts/fetch-mesa-fp64 wrote it
  std::map<std::string, std::string> devices;   // backend name → device (clock)
  std::vector<PeerTiming> timings;
  std::vector<PeerBits> bits;
};

// Fails (false, *error) when FILE cannot be read or adapted, or the native reference cannot run;
// a variant that fails on a driver becomes a row with ok == false.
bool run_peer_bench(const PeerOptions&, PeerReport*, std::string* error);
std::string format_peer_markdown(const PeerReport&);

// The shaders, exposed for tests. `library` is adapt_mesa_fp64's output.
std::string mesa_chain_kernel(const std::string& op, int steps, const std::string& library);
std::string mesa_check_shader(const std::string& op, const std::string& library);
std::string double_check_shader(const std::string& op);  // #version 450 with doubles
std::vector<uint64_t> peer_check_inputs(size_t count);    // (a, b) bit patterns, interleaved
// One application of a check shader (r[i] from ab[i]) on `backend`, results as bit patterns.
bool run_check_shader(runner::Backend, const std::string& glsl, const std::vector<uint64_t>& ab,
                      std::vector<uint64_t>* results, std::string* error);
// That run of `glsl` compared with `native` (run_check_shader of double_check_shader on lavapipe).
PeerBits compare_with_native(const std::string& op, const std::string& variant, runner::Backend, const std::string& glsl,
                             const std::vector<uint64_t>& ab, const std::vector<uint64_t>& native);

}  // namespace doublet::bench

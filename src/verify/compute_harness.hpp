// Feeds a compute shader pair (native fp64 text, lowered float-float text) with the same inputs and
// reads every output back bit-exactly from its SSBO. Both shaders are used as written: inputs are
// the loose uniforms and the members of non-writeonly buffer blocks, outputs the members of
// non-readonly blocks, all found by glslang reflection; the manifest maps split names (X_hi/X_lo).
//
// Sampling (docs/verify.md): when the only inputs and outputs are runtime-sized arrays, one
// dispatch covers all samples (one invocation per element); otherwise every sample is a dispatch
// of spec.groups workgroups with its own uniforms and buffers, runtime arrays sized
// spec.array_length (default: the invocations of a dispatch).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "doublet/doublet.hpp"
#include "runner/runner.hpp"
#include "verify/metrics.hpp"
#include "verify/spec.hpp"

namespace doublet::verify {

class ComputeHarness {
 public:
  // Reflects both shaders and plans buffers and dispatches. Empty on success, else an input error.
  std::string plan(const std::string& native_glsl, const std::string& lowered_glsl, const Manifest& manifest,
                   const Spec& spec, uint64_t samples);
  void generate(uint64_t seed);  // deterministic in seed

  std::vector<runner::ComputeJob> native_jobs() const { return jobs(true); }
  std::vector<runner::ComputeJob> lowered_jobs() const { return jobs(false); }

  // One OutputStats per output component (or hi/lo pair), worst inputs described.
  std::vector<OutputStats> compare(const std::vector<runner::ComputeResult>& native,
                                   const std::vector<runner::ComputeResult>& lowered,
                                   std::optional<double> default_min_bits) const;

  const std::vector<std::string>& notes() const { return notes_; }
  uint64_t inputs_beyond_float_range() const { return beyond_float_range_; }
  std::vector<std::string> describe_inputs() const;
  uint64_t dispatches() const { return dispatches_; }

 private:
  // A numeric value in a shader: a loose uniform, or a buffer member (an array of `elements`).
  struct Slot {
    bool is_uniform = false;
    std::string name;
    bool is_double = false;
    char scalar = 'f';  // 'f', 'd', or an int/uint/bool uniform's 'i', 'u', 'b'
    int components = 0;
    int binding = -1;
    uint32_t offset = 0, stride = 0, elements = 1;
  };
  // One input or output as the user declared it, and where it lives in each shader.
  struct Variable {
    std::string name;
    Slot native;
    std::vector<Slot> lowered;  // one slot, or hi and lo slots when split
    InputSpec input;
    OutputSpec output;
  };

  std::vector<runner::ComputeJob> jobs(bool native) const;
  std::string describe_sample(uint64_t dispatch, uint32_t invocation) const;  // the inputs it read
  std::string add_variable(const runner::ShaderInterface& native_if, const runner::ShaderInterface& lowered_if,
                           const Manifest& manifest, bool is_uniform, const std::string& name, bool as_input);

  std::string native_glsl_, lowered_glsl_;
  bool words_ = false;  // mode exact/rte-exact: doubles travel as binary64 words (words.hpp)
  std::vector<Variable> inputs_, outputs_;
  std::vector<std::string> notes_;
  uint64_t beyond_float_range_ = 0;  // input values fed as +-Inf (InputGenerator)
  std::vector<InputRelation> relations_;  // scene relations, applied after drawing
  uint32_t array_length_ = 1;  // elements of runtime arrays
  uint32_t groups_[3] = {1, 1, 1};
  uint64_t dispatches_ = 1;
  size_t native_buffers_ = 0, lowered_buffers_ = 0;
  std::vector<uint32_t> native_sizes_, lowered_sizes_;  // bytes per binding
  // values_[dispatch][input] = elements × components doubles, already representable.
  std::vector<std::vector<std::vector<double>>> values_;
};

}  // namespace doublet::verify

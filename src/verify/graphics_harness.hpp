// Feeds a vertex or fragment shader pair (native fp64 text, lowered float-float text) with the same
// inputs and reads every output back bit-exactly (runner::run_graphics_batch: the stage's in/out
// variables go through storage buffers, so neither attributes nor interpolation touch the values).
// Inputs: every float/double `in` variable (one value per sample) and loose float/double uniform
// (scalars, vectors, matrices; one value per draw). Outputs: every float/double `out` variable and
// gl_Position. The manifest maps split names (X_hi/X_lo).
//
// Sampling (docs/verify.md): without uniforms one draw covers all samples (at most 65536 per
// draw); with uniforms each draw gets its own uniform values and spec.array_length samples
// (default 64), so uniforms are sampled too.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "doublet/doublet.hpp"
#include "runner/runner.hpp"
#include "verify/metrics.hpp"
#include "verify/spec.hpp"

namespace doublet::verify {

class GraphicsHarness {
 public:
  // Reflects both shaders and plans the draws. Empty on success, else an input error.
  std::string plan(runner::GraphicsStage stage, const std::string& native_glsl, const std::string& lowered_glsl,
                   const Manifest& manifest, const Spec& spec, uint64_t samples);
  void generate(uint64_t seed);  // deterministic in seed

  std::vector<runner::GraphicsJob> native_jobs() const { return jobs(true); }
  std::vector<runner::GraphicsJob> lowered_jobs() const { return jobs(false); }

  std::vector<OutputStats> compare(const std::vector<runner::GraphicsResult>& native,
                                   const std::vector<runner::GraphicsResult>& lowered,
                                   std::optional<double> default_min_bits) const;

  const std::vector<std::string>& notes() const { return notes_; }
  uint64_t inputs_beyond_float_range() const { return beyond_float_range_; }
  std::vector<std::string> describe_inputs() const;
  uint64_t draws() const { return draws_; }

 private:
  // Where a member of a named uniform block keeps its values in one shader's block bytes: component
  // k (column k / rows, row k % rows) at offset + column * column_stride + row * its width.
  struct BlockPlace {
    uint32_t offset = 0, column_stride = 0;
    bool is_double = false;
  };
  // One input or output as the user declared it and its name(s) in the lowered shader.
  struct Variable {
    std::string name;
    bool is_uniform = false;  // one value set per draw (loose uniforms and uniform block members)
    bool is_double = false;
    int components = 0;
    std::vector<std::string> lowered;  // one name, or hi and lo names when split
    std::vector<int> word_components;  // mode exact: uints per sample of each lowered word variable
    InputSpec input;
    OutputSpec output;
    char scalar = 'f';  // 'f', 'd', or an int/uint/bool uniform's 'i', 'u', 'b'
    int columns = 1;    // matrices
    // Uniform block members: the block, and the member's place in the native block and in the
    // lowered one (hi then lo when split, from the manifest).
    std::string block;
    BlockPlace native_place;
    std::vector<BlockPlace> lowered_places;
  };
  static void write_block_member(const Variable& v, const std::vector<double>& values, bool native,
                                 std::vector<uint8_t>* bytes);
  void add_block_members(const runner::GraphicsInterface& native_if, const runner::GraphicsInterface& lowered_if,
                         const Manifest& manifest);

  std::vector<runner::GraphicsJob> jobs(bool native) const;
  std::string describe_sample(uint64_t draw, uint32_t sample) const;

  runner::GraphicsStage stage_{};
  std::string native_glsl_, lowered_glsl_;
  bool words_ = false;  // mode exact/rte-exact: doubles travel as binary64 words (words.hpp)
  std::vector<Variable> inputs_, outputs_;
  std::vector<std::string> notes_;
  uint64_t beyond_float_range_ = 0;  // input values fed as +-Inf (InputGenerator)
  std::vector<InputRelation> relations_;  // scene relations, applied after drawing
  std::map<std::string, uint32_t> native_block_sizes_, lowered_block_sizes_;  // bytes per uniform block
  uint32_t per_draw_ = 1;
  uint32_t records_ = 1;  // output records per sample (GraphicsInterface::records_per_sample)
  uint64_t draws_ = 1;
  // values_[draw][input]: components values for a uniform, per_draw × components for a stage input.
  std::vector<std::vector<std::vector<double>>> values_;
};

}  // namespace doublet::verify

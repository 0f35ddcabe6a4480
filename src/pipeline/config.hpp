// The lowering's configuration, resolved once from the public Options (docs/architecture.md,
// "Config"): every refusal of an option combination happens while it is built, for GLSL and WGSL
// alike, so that the passes only read decisions already made.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "doublet/doublet.hpp"
#include "rules/rule_library.hpp"
#include "target/target.hpp"

namespace doublet::pipeline {

// How a lowered double is stored.
enum class Representation {
  FloatFloat,     // hi + lo floats (fp32, rte, df64-fast, df64, df64-int)
  Binary64Words,  // the IEEE binary64 pattern in two uint words (exact, rte-exact)
  Native,         // kept a double (native)
};

struct Config {
  Stage stage = Stage::Vertex;
  Target output = Target::Es300;  // what the user asked for (wgsl included)
  Target target = Target::Es300;  // the GLSL profile the passes lower for (es310 under wgsl)
  const target::Facts* facts = nullptr;  // of `target`
  Mode requested_mode = Mode::Df64;  // --mode as given
  Mode mode = Mode::Df64;            // what the passes see: df64-int lowers as df64
  Representation representation = Representation::FloatFloat;
  bool integer_eft = false;          // df64-int: rules/int.glsl's error-free transformations
  rules::GuardStyle guard = rules::GuardStyle::Uniform;
  std::vector<std::string> guard_extensions;  // #extension lines the guard needs (es310 precise)
  std::vector<std::string> stage_extensions;  // #extension lines the stage needs (es310 geometry)
  std::string guard_uniform = "df_guard";
  bool optimize = true;
  bool share_exact_calls = true;
  // What the passes read of the user's options.
  std::string file_name;
  std::string hi_suffix = "_hi", lo_suffix = "_lo";
  std::vector<std::pair<std::string, Mode>> mode_for;
  bool constant_range_errors = false;
  std::vector<std::string> disabled_lints;
  bool lint_errors = false;
  // Pipeline control (Options::stop_after, skip_passes, check_ir).
  std::string stop_after;
  std::vector<std::string> skip_passes;
  bool check_ir = false;

  // The target diagnostics name: the user's (wgsl, not its GLSL ES 3.10 intermediate).
  std::string target_name() const { return target::facts(output).name; }

  bool binary64_words() const { return representation == Representation::Binary64Words; }
  bool native() const { return representation == Representation::Native; }
  // The uniform guard as an array read at a non-constant index (rules::EmitRequest::indexed_guard):
  // every GLSL target but ES 1.00, whose fragment shaders index uniform arrays by constants only;
  // not WGSL, whose printer gathers the guard into its uniform buffer as one f32 (the indexed read
  // there, an array of 16-byte stride, cost 25-30% of a loop kernel's time in Chromium's WebGPU:
  // docs/accuracy.md).
  bool indexed_guard() const { return guard == rules::GuardStyle::Uniform && guard_array_allowed(); }
  // Float-float code without the uniform guard (`precise`, or df64-int's none) reads the words of
  // the shader's double uniforms less an indexed zero uniform (the guard's declaration, read as the
  // indexed guard is), so that no condition is computed from uniforms and constants alone: a
  // driver that specialises a shader on such uniforms (lavapipe) can take minutes on float-float
  // code (docs/accuracy.md, "Lavapipe's inliner on the user's own uniforms"). GLSL from ES 3.00 on.
  bool reads_uniforms_through_guard() const {
    return representation == Representation::FloatFloat && guard != rules::GuardStyle::Uniform && guard_array_allowed();
  }
  // Whether the guard, where anything reads it, is the array read at a non-constant index.
  bool guard_is_indexed() const { return indexed_guard() || reads_uniforms_through_guard(); }
  // GLSL from ES 3.00 on (and desktop), not WGSL: where the guard may be an indexed array.
  bool guard_array_allowed() const { return !target::facts(output).wgsl && !(facts->es && facts->version < 300); }
};

// The Config of `options`, or nullopt with the refusal in `diags`.
std::optional<Config> resolve_config(const Options& options, std::vector<Diagnostic>& diags);

// The Options the front end reads for `config` (no `precise` through GL_EXT_gpu_shader5 under wgsl).
Options frontend_options(const Options& options, const Config& config);

}  // namespace doublet::pipeline

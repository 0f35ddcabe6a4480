// The shader each mode runs, derived from one double-precision compute shader:
//   fp32   — every double type demoted to its float counterpart (what users ship without doublet);
//   df64   — doublet::lower with its default guard for the target (float-float);
//   native — the original text (fp64 on lavapipe; GLES has no doubles).
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include "doublet/doublet.hpp"
#include "runner/runner.hpp"

namespace doublet::bench {

enum class Mode { Fp32, Df64, Native };
const char* mode_name(Mode);
std::optional<Mode> parse_mode(const std::string&);

struct Variant {
  std::string glsl;   // empty when the mode cannot run (see note)
  std::string note;   // why not, e.g. the lowering's diagnostics
  bool not_applicable = false;  // the backend cannot run this mode at all (not a failure)
};

// `source` is a "#version 450" compute shader with doubles. `target` is the df64 lowering target
// (es310/es320/glsl450); fp32 text uses "#version 320 es" so both backends take it as-is.
Variant make_variant(Mode, runner::Backend, const std::string& source, Target target, const std::string& file_name);

// Word-wise demotion: double → float, dvecN → vecN, dmat… → mat…, and the `lf`/`LF` literal suffix dropped.
std::string demote_doubles(const std::string& source);

// Size of a variant: SPIR-V instructions as glslang compiles it (0 when it does not compile for
// Vulkan, e.g. a double shader when fp64 is missing) and non-blank, non-comment source lines.
struct ShaderSize {
  size_t spirv_instructions = 0;
  size_t glsl_lines = 0;
};
ShaderSize shader_size(const std::string& glsl);

}  // namespace doublet::bench

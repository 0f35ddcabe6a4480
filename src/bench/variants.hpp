// The shader each mode runs, derived from one double-precision compute shader:
//   fp32, rte, df64-fast, df64 — doublet::lower with that Options::mode (docs/modes.md) and the
//            target's default guard (fp32: every double demoted to float, what users ship
//            without doublet; df64: float-float with the accurate rules);
//   native — the original text (fp64 on lavapipe; GLES has no doubles).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "doublet/doublet.hpp"
#include "runner/runner.hpp"

namespace doublet::bench {

// Exact (--mode exact, IEEE binary64 in integer arithmetic) runs only when named: --modes ...,exact.
enum class Mode { Fp32, Rte, Df64Fast, Df64, Df64Int, Native, Exact };
const std::vector<Mode>& all_bench_modes();  // in that order, Exact excepted
const char* mode_name(Mode);
std::optional<Mode> parse_mode(const std::string&);

struct Variant {
  std::string glsl;   // empty when the mode cannot run (see note)
  std::string note;   // why not, e.g. the lowering's diagnostics
  bool not_applicable = false;  // the backend cannot run this mode at all (not a failure)
};

// `source` is a "#version 450" compute shader with doubles. `target` is the lowering target
// (es310/es320/glsl450) of every mode but native.
Variant make_variant(Mode, runner::Backend, const std::string& source, Target target, const std::string& file_name);


// Size of a variant: SPIR-V instructions as glslang compiles it (0 when it does not compile for
// Vulkan, e.g. a double shader when fp64 is missing) and non-blank, non-comment source lines.
struct ShaderSize {
  size_t spirv_instructions = 0;
  size_t glsl_lines = 0;
};
ShaderSize shader_size(const std::string& glsl);

}  // namespace doublet::bench

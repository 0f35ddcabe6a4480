// The checks of the printed output (docs/architecture.md, "validate").
#pragma once

#include <string>
#include <vector>

#include "pipeline/pipeline.hpp"

namespace doublet::pipeline {

// The extensions the shader enables (#extension, as glslang's preprocessor saw them), carried into
// the output where the target allows extension lines.
std::vector<std::string> extensions_to_carry(const frontend::ParsedShader& parsed, Target target);

// Re-validates state.printed.text with glslang in the target's profile (and WebGL's rules for
// webgl2); false with a diagnostic at the user's code, or an internal error, when it fails.
bool validate_output(State& state);

}  // namespace doublet::pipeline

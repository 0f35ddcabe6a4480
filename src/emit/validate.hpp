// Re-parses emitted GLSL with glslang in the target's own profile.
#pragma once

#include <string>
#include <string_view>

#include "doublet/doublet.hpp"

namespace doublet::emit {

// The #version line (no newline) of `target`'s profile: "#version 100", "#version 300 es" (webgl2
// too), "#version 450 core".
std::string version_directive(Target target);

// Empty when `text` is valid for `target`/`stage`, else glslang's log.
std::string validate(std::string_view text, Stage stage, Target target);

}  // namespace doublet::emit

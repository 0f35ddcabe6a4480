// Re-parses emitted GLSL with glslang in the target's own profile.
#pragma once

#include <string>
#include <string_view>

#include "doublet/doublet.hpp"

namespace doublet::emit {

// Empty when `text` is valid for `target`/`stage`, else glslang's log.
std::string validate(std::string_view text, Stage stage, Target target);

}  // namespace doublet::emit

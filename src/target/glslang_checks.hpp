// The target facts only glslang can answer: whether a text is valid in a target's profile, and
// probes of which built-in names and types a profile has (each cached per process). Part of the
// target table (target/target.hpp); the passes and the driver ask here, never glslang directly.
#pragma once

#include <set>
#include <string>
#include <string_view>

#include "doublet/doublet.hpp"

namespace doublet::target {

// Empty when `text` is valid for `target`/`stage`, else glslang's log.
std::string validate(std::string_view text, Stage stage, Target target);

// Whether the opaque type `name` (sampler1D, atomic_uint, ...) exists in `target`'s language.
bool opaque_type_exists(const std::string& name, Target target);

// The names in `names` that are built-in functions of `target` for `stage`.
std::set<std::string> builtin_function_names(std::set<std::string> names, Target target, Stage stage);

// The GLSL targets whose language has the built-in variable `name` in `stage`, comma-separated
// ("es300, es310, ..."); empty when none has it (a compatibility-profile name such as gl_Vertex).
std::string targets_with_builtin_variable(const std::string& name, Stage stage);

}  // namespace doublet::target

// The runtime linker: the one place where the lowered program's runtime is assembled
// (docs/architecture.md, "The runtime linker"). Passes request it as data in their Context —
// rules by name and width, generated helpers, the df_* pair types by width and matrix shape — and
// the linker emits, in this order: the pair types the rules do not define, the rules (with their
// guard), the helpers; plus the guard's entry in the manifest.
#pragma once

#include <string>
#include <vector>

#include "doublet/doublet.hpp"
#include "lower/lower.hpp"
#include "pipeline/config.hpp"

namespace doublet::pipeline {

struct LinkedRuntime {
  bool ok = true;
  // The runtime in two parts, printed one after the other before the user's types: the pair
  // types, then the guard (if a uniform) and the functions. The user's struct uniforms may go
  // between them (emit::PrintOptions::guard_uniform).
  std::string types;
  std::string text;
  std::string after_structs;  // helpers over user struct types, printed after them
  std::string guard_uniform;  // the uniform the printer must keep from being first; empty: none
  GuardInfo guard;            // for the manifest
};

// Links what `requests` asks for; on a rule the target lacks, an error at its first use.
LinkedRuntime link_runtime(const Config& config, const passes::Context& requests, std::vector<Diagnostic>& diags);

}  // namespace doublet::pipeline

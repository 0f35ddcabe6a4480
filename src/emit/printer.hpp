// The one GLSL printer, parameterised by target: version line, precision
// statements, storage spellings (attribute/varying for ES 1.00), layout
// qualifiers the target accepts, ES 1.00 built-in names.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "doublet/doublet.hpp"
#include "ir/ir.hpp"

namespace doublet::emit {

struct PrintOptions {
  Target target = Target::Es300;
  std::string target_name;  // the target diagnostics name (the user's: wgsl over es310); empty: target's
  std::vector<std::string> extensions;  // #extension NAME : require
  std::vector<std::string> user_extensions;  // the shader's own: #extension NAME : enable
  std::string runtime_types;            // the runtime's pair types, then:
  std::string runtime;                  // its guard and functions; both printed before user types
  std::string after_structs;            // helpers over user struct types, printed after them
  // The runtime's guard uniform, when it declares one. The user's loose uniforms are then declared
  // before the guard, so that the guard is never the first uniform: lavapipe, when it specialises
  // a shader on a uniform used in a branch, replaces a first-declared guard with a constant and
  // the error terms fold away (docs/accuracy.md, "The guard's place"). Numeric ones go before the
  // runtime; uniforms of struct type (whose structs may hold pair types) go after runtime_types,
  // with every user struct definition, and before the guard.
  std::string guard_uniform;
};

struct PrintResult {
  std::string text;
  std::vector<Diagnostic> diagnostics;  // constructs the target cannot express
  // Where each built-in function or gl_* variable the text names (as printed) is first used:
  // lets a re-validation error about a built-in the target lacks point at the user's code.
  struct BuiltinUse {
    ir::Loc loc;
    std::string source_name;  // as the user wrote it (texture) where the target spells it otherwise (texture2D)
  };
  std::map<std::string, BuiltinUse> builtin_first_use;
  // (line of the text, the user's place) for every global, function and statement printed with a
  // place, in text order: maps a position in the text back to the user's source (the WGSL
  // printer's diagnostics are positions in this text).
  std::vector<std::pair<int, ir::Loc>> source_lines;
};

PrintResult print(const ir::Module& module, const PrintOptions& options, const std::string& file_name);

// One expression as the printer spells it for `target` (generated helpers, tests).
std::string expression_text(const ir::ExprPtr& e, Target target);

// A float literal that reads back as exactly `value` (as a float).
std::string float_literal(float value);

}  // namespace doublet::emit

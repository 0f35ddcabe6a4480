// The transcendental extension: exp, exp2, log, log2, pow, sin, cos, tan, asin, acos, atan
// (one and two arguments), sinh, cosh, tanh on double and dvec2-4. GLSL's fp64 has none of them,
// so glslang refuses such calls; a shader whose parse fails on such a call is parsed again with
// prototypes for the double overloads in the preamble (a shader that parses
// without them is untouched: with double overloads present glslang resolves exp(1) to the double
// one). Calls that reach a prototype (no user definition) become built-in calls in the IR, which
// the lowering maps to rules/transcendental.glsl. docs/transcendentals.md.
#pragma once

#include <string>
#include <string_view>

#include "ir/ir.hpp"

namespace doublet::frontend {

// True when glslang's info log refuses a call of one of the extension's names
// ("'exp' : no matching overloaded function found"): only then is the shader parsed again.
bool refuses_transcendental(std::string_view glslang_log);

// `double exp(double x); dvec2 exp(dvec2 x); ...` for every function and width.
const std::string& transcendental_prototypes();

// One of the extension's function names ("exp", "atan", ...).
bool is_transcendental_name(std::string_view word);

// Calls of the prototypes (a function of that name that the module does not define) become
// Kind::Builtin nodes named like the GLSL function ("exp", "atan").
void mark_transcendental_calls(ir::Module& module);

}  // namespace doublet::frontend

// Mode exact per function in a float-float shader (docs/modes.md, "Exact functions"): the
// functions that --mode-for NAME=exact or `#pragma doublet mode(exact)` name compute in binary64
// words (rules/exact.glsl) while the rest of the shader stays df64. The two representations get
// distinct names in the output: df64's df_double (float hi, lo) and df_* runtime, and the exact
// part's ex_double (uint words) with rules/exact.glsl's ex_* rules and its float-float bridges
// renamed ff_*. At each call from the float-float code the arguments are converted to binary64
// (df_to_exact: the sum hi + lo rounded once) and the result back (df_from_exact: the nearest pair).
//
// An exact function takes its doubles through `in` parameters and returns at most one: it reads no
// double global and calls only exact functions among the shader's functions that involve doubles.
#pragma once

#include <map>
#include <memory>
#include <set>
#include <string>
#include <string_view>

#include "lower/lower.hpp"

namespace doublet::passes {

struct ExactPart {
  pipeline::Config config;  // the shader's, with binary64 words
  ir::Module module;        // the exact functions, lowered in binary64 words
  std::unique_ptr<Context> ctx;  // their requests of the runtime linker
  // The stub left in the shader for each exact function (lowered with the shader, for its calls)
  // and the function it stands for.
  std::map<const ir::Function*, ir::FunctionPtr> stubs;
  std::set<int> converted_widths;  // of the values converted at the calls
};

// Moves the context's exact functions into `part` and lowers them there; stubs stay behind.
// Nothing to do (and `part` stays null) when no function is exact.
bool extract_exact_functions(ir::Module& module, Context& ctx, std::unique_ptr<ExactPart>& part);

// After the shader is lowered: the stubs give way to the exact functions, and every call of one
// from the float-float code converts its arguments and its result.
bool join_exact_functions(ir::Module& module, Context& ctx, ExactPart& part);

// The exact part's runtime text with its names moved out of df64's way: the word types
// df_double/df_dvecN/df_dmat* become ex_*, every other df_ identifier (the float-float bridges,
// the generated helpers) ff_*.
std::string rename_exact_runtime(std::string_view text);

// df_to_exact/df_from_exact for every width the calls convert.
std::string exact_conversions(const ExactPart& part);

}  // namespace doublet::passes

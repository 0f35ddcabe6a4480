// Lints: warnings about shaders that are valid but probably do not do what their
// author meant (docs/robustness.md, "Lints"). They read the imported IR before the
// lowering passes change it, and the source text for what the IR no longer holds
// (literal spellings: glslang folds `0.1` into a double constant).
//
//   float-literal          a float literal whose value is not a float flows into a double
//   wasted-double          a double made from a float and turned back with no double
//                          operation between
//   smooth-double-varying  a double vertex output without `flat`
//
// Each warning ends in `[-WNAME]`; Options::disabled_lints silences, Options::lint_errors
// promotes.
#pragma once

#include <string_view>

#include "ir/ir.hpp"
#include "lower/lower.hpp"

namespace doublet::passes {

// Adds the enabled lints' diagnostics for `module`, imported from `source` (the main
// file's text), in source order.
void run_lints(const ir::Module& module, std::string_view source, Context& context);

}  // namespace doublet::passes

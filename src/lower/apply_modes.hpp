// apply_modes: precision modes (docs/modes.md) on the IR, before lower_doubles.
//
// A declaration's mode sets its storage: fp32 demotes a double variable (or parameter, or a
// function's return value) to float; rte, df64-fast and df64 keep it double (hi/lo once
// lowered). A function's mode sets the arithmetic of its body: fp32 computes in float; rte in
// float except the exact float-float subtraction of two double values, whose result is then
// rounded to float; df64-fast and df64 in float-float (df64-fast functions are listed in
// Context::fast_functions so that lower_doubles picks the cheaper rules). Where a value of
// one precision meets an operation or a destination of the other, a conversion node
// (float(x) or double(x)) is inserted; lower_doubles lowers those as for user code.
// With every declaration and function in df64 the pass changes nothing.
#pragma once

#include <vector>

#include "frontend/mode_pragmas.hpp"
#include "lower/lower.hpp"

namespace doublet::passes {

// Resolves Options::mode, Options::mode_for and the source's pragmas, then retypes.
// Errors: unknown --mode-for names, per-name native. Warnings: pragmas without a declaration.
bool apply_modes(ir::Module& module, Context& context, const std::vector<frontend::ModePragma>& pragmas);

}  // namespace doublet::passes

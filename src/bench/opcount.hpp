// Emitted float operations, counted in SPIR-V (what glslang makes of a variant's GLSL), for
// comparison with the rules' documented flop counts (docs/rules.md): OpFAdd, OpFSub, OpFMul,
// OpFDiv, OpFNegate, OpFMod/OpFRem, GLSL.std.450 extended instructions (sqrt, abs, floor, ...)
// and OpSelect with a float result, each weighted by its result's component count
// (OpDot: 2n - 1; length: 2n; OpVectorTimesScalar: n; OpMatrixTimesVector: 2 rows cols - rows).
// Counts are dynamic along main(): an OpFunctionCall counts its callee's operations along the
// callee's cheapest entry-to-return path (the rules' branches are rare special cases: the scaled
// split above 1e34, df_finish's fallback); main's own blocks are all counted once.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace doublet::bench {

// Float operations of main(), callees included; -1 when the module has no main or is malformed,
// or when a function main calls has a loop (df64-int's and mode exact's matrix helpers, mode
// exact's shared call sites): the cheapest path would skip the loop body, and its trip count is
// not counted here, so no count is better than a wrong one.
double count_main_float_ops(const std::vector<uint32_t>& spirv);

// Float operations per step of a kernel: glsl8 and glsl16 are the same kernel with 8 and 16
// steps written out in its loop; the difference / 8. -1 when either does not compile.
double float_ops_per_step(const std::string& glsl8, const std::string& glsl16);

// A kernel source (kernels.cpp / handwritten.cpp layout: kUnroll copies of the step line in the
// loop) with the step lines doubled; empty when the layout is not recognised.
std::string with_doubled_unroll(const std::string& source, const std::string& step_line);

}  // namespace doublet::bench

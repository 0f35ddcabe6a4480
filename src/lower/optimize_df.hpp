// optimize_df: whole-shader rewrites of the lowered IR (after lower_doubles), where a rule call's
// operands allow a cheaper rule of equal or better accuracy (rules/opt.glsl, docs/rules.md):
//   df_mul(a, 2^k) / df_mul(2^k, a) / df_div(a, 2^k) / df_mul_f(a, 2^k)  -> df_mul_pow2(a, p)   exact, 3 flops
//   df_mul(x, x) with x the same side-effect-free expression            -> df_sqr(x)           19 flops, bit-identical
//   df_mul(a, f) with f's lo known zero                                 -> df_mul_f2(a, f)     27 flops, 3u^2
//   df_add(a, f) / df_sub(a, f) / df_sub(f, a) with f's lo known zero   -> df_add_f(...)       11 flops, 2u^2
//   both operands' lo known zero: df_add/df_sub -> df_two_sum, df_mul -> df_two_prod        exact
//   df_sub(x, df_from_float(df_to_float(x))), x side-effect-free         -> df_from_float(x.lo) exact
//   df_to_float(df_from_float(f))                                        -> f                   exact
// The last two are GLSL's idiom for a double's low word, `x - double(float(x))` (fragment outputs
// as hi/lo floats): for a double-word x (hi = RN(hi + lo), as every rule returns and hosts split),
// float(x) is hi, and x - hi is lo exactly.
// "lo known zero": df_from_float(f), a df constant whose lo words are all 0, or a df_splat_* of one.
// A hand-written float-float library cannot do these: it sees one call at a time.
#pragma once

#include "ir/ir.hpp"
#include "lower/lower.hpp"

namespace doublet::passes {

struct OptimizeStats {
  int pow2 = 0, squares = 0, float_operands = 0, exact_pairs = 0, low_words = 0;
};

// Rewrites in place and updates context.rules_used (rules no longer called are dropped unless a
// generated helper calls them). Returns false only if the context already failed.
bool optimize_df(ir::Module& module, Context& context, OptimizeStats* stats = nullptr);

}  // namespace doublet::passes

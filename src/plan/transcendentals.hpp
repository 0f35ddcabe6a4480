// What the plan's analysis knows about the transcendental built-ins (exp exp2 log log2 pow sin cos
// tan asin acos atan atan(y, x) sinh cosh tanh): their image of an interval, a bound on their
// slope (for the sensitivities), and the absolute error of one call in each precision.
//   df64: the documented bounds of rules/transcendental.glsl (docs/transcendentals.md), relative
//         to the result, valid only over the range where that page states them (else inf).
//   exact: the same rule reached through the binary64 bridge (docs/modes.md, "Transcendentals
//         in mode exact").
//   float (fp32/rte functions): the allowances GPU specifications give the float built-ins —
//         Vulkan's "Precision of GLSL.std.450 instructions" (exp/exp2 3 + 2|x| ulp; log/log2 3 ulp
//         outside [0.5, 2], 2^-21 absolute inside; pow inherited from exp2(y log2 x)) and, for
//         the functions Vulkan 1.0 leaves undefined, the WebGPU WGSL table derived from it (sin/cos
//         2^-11 absolute on [-pi, pi], nothing outside; tan from sin/cos; atan/atan2 4096 ulp;
//         asin/acos from atan2; sinh/cosh/tanh from exp). Drivers usually do better; a plan must
//         not count on it.
#pragma once

#include <string>

#include "plan/interval.hpp"

namespace doublet::plan {

// True for the names above (atan with two arguments is atan(y, x)).
bool is_transcendental(const std::string& name);

// f applied to x (and y: pow's exponent, or atan(y, x)'s x), over whole intervals.
Interval transcendental_range(const std::string& f, int arity, Interval x, Interval y);

// max |d f / d argument(i)| over the intervals (inf when unbounded there).
double transcendental_slope(const std::string& f, int arity, size_t i, Interval x, Interval y);

// Largest absolute error of one call whose result lies in `result`: float-float rule (df64), mode
// exact's bridge through that rule (docs/modes.md: + 2u^2 + one binary64 rounding; log, log2,
// atan and atan(y, x) over all of binary64), or the float built-in (fp32 and rte functions).
double transcendental_error_df64(const std::string& f, int arity, Interval x, Interval y, Interval result);
double transcendental_error_exact(const std::string& f, int arity, Interval x, Interval y, Interval result);
double transcendental_error_float(const std::string& f, int arity, Interval x, Interval y, Interval result);

// Float operations of one call of the float-float rule (rule headers; "on the path taken").
double transcendental_flops_df64(const std::string& f, int arity);

}  // namespace doublet::plan

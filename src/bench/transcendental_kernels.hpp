// Shaders for `doublet bench --transcendentals` (transcendental_bench.hpp): for each function, a
// timing chain and a one-call accuracy kernel in four variants on the same inputs:
//   fp32   the float built-in (the double shader lowered with --mode fp32: what users ship);
//   df64   doublet's rule (the double shader lowered with --mode df64);
//   native the same algorithm as doublet's rule (reduction, polynomial degree) in native fp64, a
//          library written here (kNativeLibrary): GLSL has no double transcendentals, so this is
//          what "vs native" compares with; lavapipe only (GLES has no doubles);
//   luma   luma.gl's f_fp64 on vec2(hi, lo) (luma_peer.hpp).
#pragma once

#include <string>
#include <vector>

namespace doublet::bench {

enum class TranscendentalVariant { Fp32, Df64, Native, Luma };
const char* variant_name(TranscendentalVariant);

// exp log sin cos tan: the functions luma.gl's fp64 module has.
const std::vector<std::string>& transcendental_functions();
bool is_trig(const std::string& function);

// Where the accuracy inputs lie: Main for every function (exp: [-70, 88]; log: log-uniform
// [2^-60, 2^60]; sin/cos/tan: [-pi, pi]); Wide for sin/cos/tan only (|x| log-uniform in
// [2^-10, 2^20], both signs).
enum class Domain { Main, Wide };
const char* domain_name(const std::string& function, Domain);
// `count` inputs as float-float pairs (hi, lo), reproducible.
std::vector<float> accuracy_inputs(const std::string& function, Domain, int count);
// The host reference, long double libm (64-bit significand) on the exact input.
long double reference(const std::string& function, long double x);

// Timing chain: `steps` dependent calls per invocation over binding 0 `vec4 inp[]`, result stored in
// binding 1 `vec4 outp[]`. Each chain has a bounded fixed point (exp(-x), log(x + 2), sin(x) + 1,
// cos(x), 1 - tan(x/2)). Fp32 and Df64 get the "#version 450" double shader, to be lowered; Native
// a "#version 450" shader; Luma a "#version 310 es" shader that needs `luma_glsl` (LumaLibrary::glsl).
std::string chain_source(const std::string& function, TranscendentalVariant, int steps, const std::string& luma_glsl);
// One call per invocation on inp[i].xy (hi, lo); outp[i] holds the result: vec4(hi, lo, 0, 0), or
// for Native uvec4(unpackDouble2x32(z), 0, 0).
std::string accuracy_source(const std::string& function, TranscendentalVariant, const std::string& luma_glsl);

// The native-fp64 library (GLSL 4.50 doubles): nat_exp nat_log nat_sin nat_cos nat_tan.
extern const char* const kNativeLibrary;

}  // namespace doublet::bench

// Mode exact's transcendentals (the doublet extension: exp log exp2 log2 pow sin cos tan asin acos
// atan atan2 sinh cosh tanh) are a bridge through float-float (rules/exact.glsl ex_exp, ...): the
// binary64 input becomes a float-float pair, the df64 rule of rules/transcendental.glsl runs, the
// part of the input the pair lost is added back to first order, and the result is rounded once to
// binary64. Each function is lowered with --mode exact, run on lavapipe and on Mesa GLES, and every
// result is compared with MPFR (200 bits) on the exact binary64 input. Checks: every result within
// the documented bound (the df64 rule's + 2u^2 + 2^-53, docs/modes.md), >= 44 correct bits in the
// normal range (trig up to 2^40, at least 2^-53 |x| from k pi/2). Sabotages: dropping the residual
// correction or the low word, or the old floor(v + 0.5) trig reduction, must break them.
// DOUBLET_EXACT_TRANSCENDENTAL_SAMPLES=N sets the inputs per function (default 16384).
#include <gtest/gtest.h>
#include <mpfr.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include "doublet/doublet.hpp"
#include "exact_harness.hpp"
#include "../numeric/pio2_distance.hpp"

namespace doublet::runner::test::exact {
namespace {

constexpr double kU2 = 0x1p-48;

using Generator = std::function<void(std::mt19937_64&, double&, double&)>;

struct Family {
  const char* name;
  Generator make;
  bool normal = true;   // >= 44 bits required
  bool bounded = true;  // within the documented bound required (false: reported only)
  // If set, only inputs it accepts count towards the >= 44 bits (trig: away from k pi/2).
  bool (*normal_at)(double x) = nullptr;
};

struct Function {
  const char* name;
  const char* expr;  // GLSL over double x, y
  int (*mpfr1)(mpfr_ptr, mpfr_srcptr, mpfr_rnd_t);
  int (*mpfr2)(mpfr_ptr, mpfr_srcptr, mpfr_srcptr, mpfr_rnd_t);  // called as f(ref, x, y)
  double bound_u2;  // the df64 rule's bound in u^2 (docs/transcendentals.md) + 2u^2 for the correction
  enum { Relative, Trig, Tan, Pow } kind;
  std::vector<Family> families;
};

double uniform(std::mt19937_64& g, double lo, double hi) { return lo + (hi - lo) * (double(g() >> 11) * 0x1p-53); }
double log_uniform(std::mt19937_64& g, double lo_exp, double hi_exp, bool both_signs = true) {
  const double v = std::exp2(uniform(g, lo_exp, hi_exp));
  return both_signs && (g() & 1) ? -v : v;
}
double random_sign(std::mt19937_64& g, double v) { return (g() & 1) ? -v : v; }
// Full 53-bit significands: a float-float pair cannot hold them, so the residual correction matters.
double full(std::mt19937_64& g, double v) { return dbl((pat(v) & ~0xFFFFFull) | (g() & 0xFFFFFull)); }

// The df64 trig rule's 44-bit range (docs/transcendentals.md, Limits): x at least 2^-53 |x| from
// every multiple of pi/2; nearer, the reduction's |x| 2^-99 absolute error dominates a small result.
bool away_from_multiple_of_pio2(double x) { return distance_to_multiple_of_pio2(x) >= std::fabs(x) * 0x1p-53; }

// |x| from 2^-1074 (subnormal) to 2^-28: below float's range, f(x) rounds to x for the odd functions.
const Family kTiny = {"tiny 2^-1074..2^-28", [](auto& g, double& x, double&) { x = full(g, log_uniform(g, -1074, -28)); }};

std::vector<Function> functions() {
  const double pio2 = 1.5707963267948966;
  auto near_multiple = [pio2](std::mt19937_64& g, double& x, double&) {
    const double k = std::floor(log_uniform(g, 0, 20, false));
    x = random_sign(g, full(g, k * pio2 * (1 + uniform(g, -1, 1) * 0x1p-40)));
  };
  const std::vector<Family> trig = {
      {"|x| < pi/4", [](auto& g, double& x, double&) { x = full(g, uniform(g, -0.785, 0.785)); }},
      kTiny,
      {"|x| < 2^20", [](auto& g, double& x, double&) { x = full(g, uniform(g, -0x1p20, 0x1p20)); }},
      {"near k pi/2", near_multiple},
      {"log-uniform 2^-30..2^20", [](auto& g, double& x, double&) { x = full(g, log_uniform(g, -30, 20)); }},
      // Since the df64 reduction's k = roundEven(x 2/pi) (no floor(v + 0.5) for Mesa to reassociate
      // without `precise`, which mode exact does not emit) the bridge keeps its bits up to 2^40.
      {"2^20..2^30", [](auto& g, double& x, double&) { x = full(g, log_uniform(g, 20, 30)); }, true, true,
       away_from_multiple_of_pio2},
      {"2^30..2^40", [](auto& g, double& x, double&) { x = full(g, log_uniform(g, 30, 39.999)); }, true, true,
       away_from_multiple_of_pio2},
      // Within 16 ulps of the binary64 nearest k pi/2, k in [2^20, 2^39]: the hardest reductions;
      // 5% of them are nearer than 2^-53 |x| to k pi/2, where only the bound is required.
      {"near k pi/2, k 2^20..2^39", [pio2](auto& g, double& x, double&) {
         const double k = std::floor(log_uniform(g, 20, 39, false));
         x = random_sign(g, dbl(pat(k * pio2) + (g() % 33) - 16));
       }, true, true, away_from_multiple_of_pio2},
  };
  std::vector<Function> f;
  f.push_back({"exp", "exp(x)", mpfr_exp, nullptr, 12, Function::Relative,
               {{"[-70.5, 88.7]", [](auto& g, double& x, double&) { x = full(g, uniform(g, -70.5, 88.7)); }},
                {"|x| in [2^-40, 1]", [](auto& g, double& x, double&) { x = full(g, log_uniform(g, -40, 0)); }}}});
  f.push_back({"exp2", "exp2(x)", mpfr_exp2, nullptr, 14, Function::Relative,
               {{"[-101.5, 127.9]", [](auto& g, double& x, double&) { x = full(g, uniform(g, -101.5, 127.9)); }},
                {"|x| in [2^-40, 1]", [](auto& g, double& x, double&) { x = full(g, log_uniform(g, -40, 0)); }}}});
  const std::vector<Family> logs = {
      {"log-uniform 2^-1074..2^1024", [](auto& g, double& x, double&) { x = full(g, log_uniform(g, -1074, 1023.9, false)); }},
      {"1 + [2^-45, 2^-1]", [](auto& g, double& x, double&) { x = 1 + full(g, log_uniform(g, -45, -1)); }},
      {"1 - [2^-45, 2^-2]", [](auto& g, double& x, double&) { x = 1 - full(g, log_uniform(g, -45, -2, false)); }},
  };
  f.push_back({"log", "log(x)", mpfr_log, nullptr, 30, Function::Relative, logs});
  f.push_back({"log2", "log2(x)", mpfr_log2, nullptr, 39, Function::Relative, logs});
  f.push_back({"pow", "pow(x, y)", nullptr, mpfr_pow, 42, Function::Pow,
               {{"|y log x| < 1/2", [](auto& g, double& x, double& y) {
                  x = full(g, log_uniform(g, -20, 20, false));
                  y = full(g, uniform(g, -0.5, 0.5) / std::max(std::fabs(std::log(x)), 1e-3));
                }},
                {"|y log x| < 70", [](auto& g, double& x, double& y) {
                  x = full(g, log_uniform(g, -60, 60, false));
                  y = full(g, uniform(g, -70, 70) / std::max(std::fabs(std::log(x)), 1e-3));
                }, false}}});
  f.push_back({"sin", "sin(x)", mpfr_sin, nullptr, 22, Function::Trig, trig});
  f.push_back({"cos", "cos(x)", mpfr_cos, nullptr, 22, Function::Trig, trig});
  f.push_back({"tan", "tan(x)", mpfr_tan, nullptr, 42, Function::Tan, trig});
  f.push_back({"atan", "atan(x)", mpfr_atan, nullptr, 72, Function::Relative,
               {{"log-uniform 2^-60..2^60", [](auto& g, double& x, double&) { x = full(g, log_uniform(g, -60, 60)); }},
                {"+-1 (1 +- 2^-20)", [](auto& g, double& x, double&) { x = random_sign(g, full(g, 1 + uniform(g, -1, 1) * 0x1p-20)); }},
                kTiny}});
  f.push_back({"atan2", "atan(x, y)", nullptr, mpfr_atan2, 72, Function::Relative,
               {{"log-uniform x, y", [](auto& g, double& x, double& y) {
                  x = full(g, log_uniform(g, -60, 60));
                  y = full(g, log_uniform(g, -60, 60));
                }},
                {"log-uniform 2^-1000..2^1000", [](auto& g, double& x, double& y) {
                  x = full(g, log_uniform(g, -1000, 1000));
                  y = full(g, log_uniform(g, -1000, 1000));
                }},
                {"|x| = |y| (1 +- 2^-20)", [](auto& g, double& x, double& y) {
                  x = full(g, log_uniform(g, -30, 30));
                  y = random_sign(g, full(g, std::fabs(x) * (1 + uniform(g, -1, 1) * 0x1p-20)));
                }}}});
  const std::vector<Family> unit = {
      {"uniform [-1, 1]", [](auto& g, double& x, double&) { x = full(g, uniform(g, -1, 1)); }},
      {"near +-1", [](auto& g, double& x, double&) { x = random_sign(g, 1 - full(g, log_uniform(g, -50, -4, false))); }},
      {"near 0", [](auto& g, double& x, double&) { x = full(g, log_uniform(g, -60, -4)); }},
      kTiny,
  };
  f.push_back({"asin", "asin(x)", mpfr_asin, nullptr, 77, Function::Relative, unit});
  f.push_back({"acos", "acos(x)", mpfr_acos, nullptr, 77, Function::Relative, unit});
  const std::vector<Family> hyper = {
      {"log-uniform 2^-40..88.6", [](auto& g, double& x, double&) { x = full(g, log_uniform(g, -40, 6.469)); }},
      {"near +-0.3465", [](auto& g, double& x, double&) { x = random_sign(g, full(g, 0.3465 * (1 + uniform(g, -1, 1) * 0x1p-10))); }},
      kTiny,
  };
  f.push_back({"sinh", "sinh(x)", mpfr_sinh, nullptr, 52, Function::Relative, hyper});
  f.push_back({"cosh", "cosh(x)", mpfr_cosh, nullptr, 22, Function::Relative, hyper});
  f.push_back({"tanh", "tanh(x)", mpfr_tanh, nullptr, 52, Function::Relative,
               {{"log-uniform 2^-40..24", [](auto& g, double& x, double&) { x = full(g, log_uniform(g, -40, 4.58)); }},
                {"near +-0.17", [](auto& g, double& x, double&) { x = random_sign(g, full(g, 0.17325 * (1 + uniform(g, -1, 1) * 0x1p-10))); }},
                kTiny}});
  return f;
}

std::string shader_for(const Function& fn) {
  return std::string(R"(#version 450
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer In { uvec4 xy[]; };
layout(std430, binding = 1) writeonly buffer Out { uvec2 r[]; };
void main() {
  uint i = gl_GlobalInvocationID.x;
  double x = packDouble2x32(xy[i].xy), y = packDouble2x32(xy[i].zw);
  r[i] = unpackDouble2x32()") + fn.expr + R"();
}
)";
}

std::string lower_exact(const std::string& source, std::string* diagnostics) {
  Options options;
  options.stage = Stage::Compute;
  options.target = Target::Es310;
  options.mode = Mode::Exact;
  Result lowered = lower(source, options);
  for (const Diagnostic& d : lowered.diagnostics) *diagnostics += format_diagnostic(d) + "\n";
  return lowered.ok ? lowered.output : "";
}

size_t sample_count() {
  const char* env = std::getenv("DOUBLET_EXACT_TRANSCENDENTAL_SAMPLES");
  const long n = env ? std::atol(env) : 16384;
  return size_t(std::max(64L, (n + 63) / 64 * 64));
}

struct Inputs {
  std::vector<uint64_t> xy;  // x, y patterns per invocation
  std::vector<int> family;
};

Inputs make_inputs(const Function& fn) {
  std::mt19937_64 rng(20261126);
  Inputs in;
  for (size_t i = 0; i < sample_count(); ++i) {
    const int k = int(i % fn.families.size());
    double x = 0, y = 0;
    fn.families[size_t(k)].make(rng, x, y);
    in.xy.insert(in.xy.end(), {pat(x), pat(y)});
    in.family.push_back(k);
  }
  return in;
}

struct FamilyResult {
  size_t samples = 0, over_bound = 0, normal_samples = 0;
  double min_bits = 99, worst_ratio = 0, normal_min_bits = 99;  // normal_*: where >= 44 bits is required
  std::string worst, fewest_bits_at;
};

struct Measurement {
  std::vector<FamilyResult> families;
  double normal_min_bits = 99;
  size_t over_bound = 0;
};

// The bits of `got` against MPFR on the exact inputs, per family.
Measurement measure(const Function& fn, const Inputs& in, const std::vector<uint64_t>& got) {
  Measurement m;
  m.families.resize(fn.families.size());
  mpfr_t x, y, ref, err;
  for (mpfr_ptr p : {x, y, ref, err}) mpfr_init2(p, 200);
  for (size_t i = 0; i < in.family.size() && i < got.size(); ++i) {
    const double xd = dbl(in.xy[2 * i]), yd = dbl(in.xy[2 * i + 1]), g = dbl(got[i]);
    mpfr_set_d(x, xd, MPFR_RNDN);
    mpfr_set_d(y, yd, MPFR_RNDN);
    if (fn.mpfr1) fn.mpfr1(ref, x, MPFR_RNDN);
    else fn.mpfr2(ref, x, y, MPFR_RNDN);
    const double r = mpfr_get_d(ref, MPFR_RNDN);
    mpfr_sub_d(err, ref, g, MPFR_RNDN);
    const double abs_err = std::isfinite(g) ? std::fabs(mpfr_get_d(err, MPFR_RNDU)) : INFINITY;
    // + the smallest subnormal: a result below binary64's normal range is quantized absolutely.
    double allowed = (fn.bound_u2 * kU2 + 0x1p-53) * std::fabs(r) + 0x1p-1074;
    if (fn.kind == Function::Pow) allowed += 31 * kU2 * std::fabs(yd * std::log(xd)) * std::fabs(r);
    if (fn.kind == Function::Trig) allowed += std::fabs(xd) * 0x1p-96;
    if (fn.kind == Function::Tan) allowed += std::fabs(xd) * 0x1p-96 * (1 + r * r);
    // Relative bits where binary64 has them all (a subnormal result has fewer to give).
    const double bits = abs_err == 0 || std::fabs(r) < 0x1p-1022 ? 99 : -std::log2(abs_err / std::fabs(r));
    FamilyResult& fam = m.families[size_t(in.family[i])];
    ++fam.samples;
    const Family& family = fn.families[size_t(in.family[i])];
    if (!(abs_err <= allowed)) ++fam.over_bound, m.over_bound += family.bounded;
    if (!(bits >= fam.min_bits)) {
      fam.min_bits = std::isnan(bits) ? -1.0 : bits;
      char buf[160];
      std::snprintf(buf, sizeof buf, "x=%a y=%a got %a want %a", xd, yd, g, r);
      fam.fewest_bits_at = buf;
    }
    if (family.normal && (!family.normal_at || family.normal_at(xd))) {
      ++fam.normal_samples;
      fam.normal_min_bits = std::min(fam.normal_min_bits, std::isnan(bits) ? -1.0 : bits);
      m.normal_min_bits = std::min(m.normal_min_bits, fam.normal_min_bits);
    }
    const double ratio = abs_err == 0 ? 0 : abs_err / allowed;
    if (!(ratio <= fam.worst_ratio)) {
      fam.worst_ratio = std::isnan(ratio) ? INFINITY : ratio;
      char buf[160];
      std::snprintf(buf, sizeof buf, "x=%a y=%a got %a want %a", xd, yd, g, r);
      fam.worst = buf;
    }
  }
  for (mpfr_ptr p : {x, y, ref, err}) mpfr_clear(p);
  return m;
}

std::string report(const Function& fn, const Measurement& m) {
  std::string s;
  for (size_t k = 0; k < m.families.size(); ++k) {
    const FamilyResult& f = m.families[k];
    char line[500], range[64] = "";
    if (fn.families[k].normal_at)
      std::snprintf(range, sizeof range, " [44-bit range: n=%zu min %.2f]", f.normal_samples, f.normal_min_bits);
    std::snprintf(line, sizeof line, "  %-5s %-28s n=%6zu min bits %6.2f%s (%s)  worst err/bound %8.3g (%s)  over bound %zu\n",
                  fn.name, fn.families[k].name, f.samples, f.min_bits, range, f.fewest_bits_at.c_str(), f.worst_ratio,
                  f.worst.c_str(), f.over_bound);
    s += line;
  }
  return s;
}

class ExactTranscendentals : public ::testing::TestWithParam<Backend> {};

TEST_P(ExactTranscendentals, WithinBoundsAndAtLeast44BitsAgainstMpfr) {
  REQUIRE_BACKEND(GetParam());
  for (const Function& fn : functions()) {
    std::string diagnostics;
    const std::string glsl = lower_exact(shader_for(fn), &diagnostics);
    ASSERT_FALSE(glsl.empty()) << fn.name << ":\n" << diagnostics;
    const Inputs in = make_inputs(fn);
    const std::vector<uint64_t> got = run_words(GetParam(), glsl, in.xy, 2, 1);
    ASSERT_EQ(got.size(), in.family.size()) << fn.name;
    const Measurement m = measure(fn, in, got);
    std::cout << report(fn, m);
    EXPECT_EQ(m.over_bound, 0u) << fn.name << "\n" << report(fn, m);
    EXPECT_GE(m.normal_min_bits, 44.0) << fn.name << "\n" << report(fn, m);
  }
}

// Special values as the C library gives them (C99 Annex F.9), on binary64's whole range where the
// bridge reaches (log, log2 and atan2 everywhere; the odd functions below 2^-28), and the ends
// docs/modes.md states: float's exponent range for exp/exp2/sinh/cosh, NaN beyond 2^40 for trig.
TEST_P(ExactTranscendentals, SpecialValuesFollowCAndTheRangeEndsAreAsDocumented) {
  REQUIRE_BACKEND(GetParam());
  const double inf = INFINITY, nan = NAN, tiny = 0x1p-1074, big = 0x1.fffffffffffffp+1023;
  struct Case {
    const char* fn;
    double x, y;
    double want;  // the C library's value, or the documented one
    bool documented_deviation = false;
  };
  const std::vector<Case> cases = {
      {"exp", 0.0, 0, 1}, {"exp", -0.0, 0, 1}, {"exp", -inf, 0, 0}, {"exp", inf, 0, inf}, {"exp", nan, 0, nan},
      {"exp", 100, 0, inf, true}, {"exp", -200, 0, 0, true}, {"exp2", 200, 0, inf, true}, {"exp2", -inf, 0, 0},
      {"log", 0.0, 0, -inf}, {"log", -0.0, 0, -inf}, {"log", -1, 0, nan}, {"log", inf, 0, inf}, {"log", 1, 0, 0},
      {"log", tiny, 0, std::log(tiny)}, {"log", big, 0, std::log(big)}, {"log", 1e-300, 0, std::log(1e-300)},
      {"log2", tiny, 0, -1074}, {"log2", 0x1p-1022, 0, -1022}, {"log2", 0x1p1023, 0, 1023}, {"log2", 0.0, 0, -inf},
      {"pow", 2, 0.0, 1}, {"pow", 1, 12.5, 1}, {"pow", 0.0, 3, 0}, {"pow", 0.0, -3, inf},
      {"sin", -0.0, 0, -0.0}, {"sin", tiny, 0, tiny}, {"sin", -1e-300, 0, -1e-300}, {"sin", inf, 0, nan},
      {"sin", 0x1p40, 0, nan, true}, {"cos", 0.0, 0, 1}, {"cos", 0x1p41, 0, nan, true}, {"tan", -0.0, 0, -0.0},
      {"asin", -0.0, 0, -0.0}, {"asin", 1, 0, std::asin(1.0)}, {"acos", 1, 0, 0}, {"acos", -1, 0, std::acos(-1.0)},
      {"atan", inf, 0, std::atan(inf)}, {"atan", -inf, 0, -std::atan(inf)}, {"atan", 1e300, 0, std::atan(1e300)},
      {"atan", -tiny, 0, -tiny}, {"atan2", 1e300, 1e300, std::atan2(1e300, 1e300)},
      {"atan2", -1e-300, 3e-300, std::atan2(-1e-300, 3e-300)}, {"atan2", 1e-300, 1e300, std::atan2(1e-300, 1e300)},
      {"atan2", 0.0, -1, std::atan2(0.0, -1.0)}, {"atan2", -0.0, -1, std::atan2(-0.0, -1.0)},
      {"sinh", -0.0, 0, -0.0}, {"sinh", 100, 0, inf, true}, {"cosh", 100, 0, inf, true}, {"cosh", 0.0, 0, 1},
      {"tanh", inf, 0, 1}, {"tanh", -inf, 0, -1}, {"tanh", -0.0, 0, -0.0}, {"tanh", 1e-310, 0, 1e-310},
  };
  int failures = 0;
  for (const Function& fn : functions()) {
    Inputs in;
    std::vector<const Case*> mine;
    for (const Case& c : cases)
      if (c.fn == std::string(fn.name)) mine.push_back(&c), in.xy.insert(in.xy.end(), {pat(c.x), pat(c.y)});
    if (mine.empty()) continue;
    while (in.xy.size() < 128) in.xy.insert(in.xy.end(), {pat(1.0), pat(1.0)});  // one workgroup of 64
    std::string diagnostics;
    const std::string glsl = lower_exact(shader_for(fn), &diagnostics);
    ASSERT_FALSE(glsl.empty()) << diagnostics;
    const std::vector<uint64_t> got = run_words(GetParam(), glsl, in.xy, 2, 1);
    ASSERT_GE(got.size(), mine.size());
    for (size_t i = 0; i < mine.size(); ++i) {
      const Case& c = *mine[i];
      const double g = dbl(got[i]);
      bool ok;
      if (std::isnan(c.want)) ok = std::isnan(g);
      else if (std::isinf(c.want) || c.want == 0) ok = pat(g) == pat(c.want);
      else ok = std::fabs(g - c.want) <= std::fabs(c.want) * (fn.bound_u2 * kU2 + 0x1p-53) + 0x1p-1074;
      if (!ok) {
        ++failures;
        std::printf("[ exact ] %s(%a, %a): got %a (%016llx), want %a%s\n", c.fn, c.x, c.y, g, (unsigned long long)got[i],
                    c.want, c.documented_deviation ? " (documented)" : "");
      }
    }
  }
  EXPECT_EQ(failures, 0);
}

INSTANTIATE_TEST_SUITE_P(Drivers, ExactTranscendentals, ::testing::Values(Backend::Vulkan, Backend::Gles),
                         backend_param_name);

// The same measurement must see the bridge broken. Without the first-order correction (the
// residual the float-float pair lost set to 0) the functions whose condition number is large
// somewhere on their families break (atan, atan2, sinh and tanh stay within 2^-48 of the input's
// own error there); with the pair's low word dropped as well, every function breaks.
TEST(ExactTranscendentalSabotage, DroppingTheResidualOrTheLowWordBreaksTheBounds) {
  REQUIRE_BACKEND(Backend::Vulkan);
  const std::pair<std::string, std::string> no_residual = {"  return uintBitsToFloat(ex_to_float_bits(rest));\n}",
                                                           "  return 0.0;\n}"};
  const std::pair<std::string, std::string> no_low_word = {
      "return ff_double(uintBitsToFloat(h), uintBitsToFloat(ex_to_float_bits(rest)));",
      "return ff_double(uintBitsToFloat(h), 0.0);"};
  // The df64 trig reduction as it was before roundEven: without `precise` Mesa reassociated its
  // second + 0.5 into the first, k came out one off above 2^23 (31-35 bits); the 2^20..2^40
  // families must see it.
  const std::pair<std::string, std::string> floor_k1 = {"roundEven(t.hi)", "floor(t.hi + 0.5)"};
  const std::pair<std::string, std::string> floor_k2 = {"roundEven(f + t.lo)", "floor(f + t.lo + 0.5)"};
  struct Sabotage {
    const char* name;
    std::vector<std::pair<std::string, std::string>> edits;
    std::vector<std::string> must_break;  // empty: every function
    bool only_must_break = false;         // run only the functions in must_break
  };
  const std::vector<Sabotage> sabotages = {
      {"no residual correction", {no_residual}, {"exp", "exp2", "log", "log2", "sin", "cos", "tan", "asin", "acos"}},
      {"low word and residual dropped", {no_residual, no_low_word}, {}},
      {"floor(v + 0.5) trig reduction", {floor_k1, floor_k2}, {"sin", "cos", "tan"}, true},
  };
  for (const Sabotage& sab : sabotages) {
    for (const Function& fn : functions()) {
      const bool listed = std::find(sab.must_break.begin(), sab.must_break.end(), fn.name) != sab.must_break.end();
      if (sab.only_must_break && !listed) continue;
      std::string diagnostics;
      std::string glsl = lower_exact(shader_for(fn), &diagnostics);
      ASSERT_FALSE(glsl.empty()) << diagnostics;
      for (const auto& [from, to] : sab.edits) {
        const size_t at = glsl.find(from);
        ASSERT_NE(at, std::string::npos) << sab.name << " does not apply to " << fn.name;
        glsl.replace(at, from.size(), to);
      }
      const Inputs in = make_inputs(fn);
      const Measurement m = measure(fn, in, run_words(Backend::Vulkan, glsl, in.xy, 2, 1));
      const bool broken = m.over_bound > 0 || m.normal_min_bits < 44;
      std::cout << "[ exact ] sabotage '" << sab.name << "': " << fn.name << " " << m.over_bound
                << " over the bound, normal-range min bits " << m.normal_min_bits << "\n";
      const bool must = sab.must_break.empty() || listed;
      if (sab.only_must_break) std::cout << report(fn, m);
      if (must) EXPECT_TRUE(broken) << sab.name << " left " << fn.name << " within its bound";
    }
  }
}

}  // namespace
}  // namespace doublet::runner::test::exact

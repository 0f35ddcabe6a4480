// The transcendental extension (rules/transcendental.glsl) on real drivers: for each function a
// compute shader written with doubles is lowered by doublet and run on lavapipe and Mesa GLES
// (llvmpipe); each result is compared with MPFR (200 bits) on the exact float-float input, and
// with the host's binary64 libm as a second reference. Inputs span each function's whole range
// (log-uniform magnitudes) plus grids at its special points (multiples of pi/2, 1 for log, 0,
// the overflow thresholds). Checks: every result within its documented bound
// (docs/transcendentals.md), >= 44 correct bits in the normal range. Sabotages, each of which
// must break the bounds: no optimizer guard, doubles demoted to float (drop lo), each argument
// reduction skipped by editing the lowered text, and the old floor(v + 0.5) trigonometric
// reduction put back (it breaks without `precise`: the Uniform guard's former gap).
// DOUBLET_TRANSCENDENTAL_SAMPLES=N sets the random samples per function (default 8192).
#include <gtest/gtest.h>
#include <mpfr.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "doublet/doublet.hpp"
#include "frontend/demote.hpp"
#include "runner/runner.hpp"
#include "pio2_distance.hpp"

namespace {

using doublet::runner::Backend;
constexpr double kU2 = 0x1p-48;

struct Input {
  float xh, xl, yh, yl;
  int family;
};

struct Function {
  const char* name;
  const char* expr;  // GLSL over double x, y
  int (*mpfr_fn1)(mpfr_ptr, mpfr_srcptr, mpfr_rnd_t);
  int (*mpfr_fn2)(mpfr_ptr, mpfr_srcptr, mpfr_srcptr, mpfr_rnd_t);
  double (*host1)(double);
  double (*host2)(double, double);
  // Allowed absolute error for input (x, y) and exact result ref (docs/transcendentals.md).
  std::function<double(double x, double y, double ref)> allowed;
  // Families (by name) and a generator for each: fills x (and y) from rng.
  std::vector<std::pair<const char*, std::function<void(std::mt19937_64&, double&, double&)>>> families;
  // The normal range where >= 44 bits are required (false: bound only).
  std::function<bool(double x, double y, double ref)> normal = nullptr;
};

double uniform(std::mt19937_64& rng, double lo, double hi) {
  return lo + (hi - lo) * (static_cast<double>(rng() >> 11) * 0x1p-53);
}
double log_uniform(std::mt19937_64& rng, double lo_exp, double hi_exp, bool both_signs = true) {
  double v = std::exp2(uniform(rng, lo_exp, hi_exp));
  return both_signs && (rng() & 1) ? -v : v;
}
double rel(double c, double ref) { return c * kU2 * std::fabs(ref); }


std::vector<Function> functions() {
  const double pio2 = 1.5707963267948966;
  auto near_multiple = [pio2](std::mt19937_64& rng, double& x, double&) {
    // The float-float nearest k pi/2 (k up to 2^20), then moved by up to 2^-40 relative.
    double k = std::floor(log_uniform(rng, 0, 20, false));
    x = k * pio2 * (1 + uniform(rng, -1, 1) * 0x1p-40) * ((rng() & 1) ? -1 : 1);
  };
  std::vector<Function> f;
  f.push_back({"exp", "exp(x)", mpfr_exp, nullptr, ::exp, nullptr,
               [](double, double, double r) { return rel(10, r); },
               {{"uniform", [](auto& g, double& x, double&) { x = uniform(g, -70.5, 88.7); }},
                {"small", [](auto& g, double& x, double&) { x = log_uniform(g, -40, 0); }},
                {"k-ln2/2", [](auto& g, double& x, double&) {
                   x = (std::floor(uniform(g, -100, 127)) + 0.5) * 0.6931471805599453 + uniform(g, -1, 1) * 0x1p-30;
                   x = std::clamp(x, -70.5, 88.7);
                 }}}});
  f.push_back({"exp2", "exp2(x)", mpfr_exp2, nullptr, ::exp2, nullptr,
               [](double, double, double r) { return rel(12, r); },
               {{"uniform", [](auto& g, double& x, double&) { x = uniform(g, -101.5, 127.99); }},
                {"small", [](auto& g, double& x, double&) { x = log_uniform(g, -40, 0); }},
                {"half-integers", [](auto& g, double& x, double&) {
                   x = std::floor(uniform(g, -100, 127)) + 0.5 + uniform(g, -1, 1) * 0x1p-30;
                 }}}});
  f.push_back({"log", "log(x)", mpfr_log, nullptr, ::log, nullptr,
               [](double, double, double r) { return rel(28, r); },
               {{"log-uniform", [](auto& g, double& x, double&) { x = log_uniform(g, -125, 127.9, false); }},
                {"near-1", [](auto& g, double& x, double&) { x = 1 + log_uniform(g, -45, -1); }},
                {"near-sqrt2", [](auto& g, double& x, double&) {
                   x = std::ldexp(0.7071067811865476 * (1 + uniform(g, -1, 1) * 0x1p-30), static_cast<int>(uniform(g, -60, 60)));
                 }}}});
  f.push_back({"log2", "log2(x)", mpfr_log2, nullptr, ::log2, nullptr,
               [](double, double, double r) { return rel(37, r); },
               {{"log-uniform", [](auto& g, double& x, double&) { x = log_uniform(g, -125, 127.9, false); }},
                {"near-1", [](auto& g, double& x, double&) { x = 1 + log_uniform(g, -45, -1); }}}});
  // pow inputs with |y log x| uniform in [lo, hi] (negative side capped at -70: normal results).
  auto pow_bin = [](double lo, double hi) {
    return [lo, hi](std::mt19937_64& g, double& x, double& y) {
      x = log_uniform(g, -60, 60, false);
      const bool negative = g() & 1;
      const double z = negative ? -uniform(g, lo, std::min(hi, 70.0)) : uniform(g, lo, hi);
      y = z / std::log(x);
    };
  };
  f.push_back({"pow", "pow(x, y)", nullptr, mpfr_pow, nullptr, ::pow,
               [](double x, double y, double r) { return rel(40 + 31 * std::fabs(y * std::log(x)), r); },
               {{"|y log x| < 1/2", [](auto& g, double& x, double& y) {
                   x = log_uniform(g, -20, 20, false);
                   y = uniform(g, -0.5, 0.5) / std::max(std::fabs(std::log(x)), 1e-300);
                 }},
                // |y log x| by bins (results in the normal range): the bits fall as it grows.
                {"|y log x| 1/2-4", pow_bin(0.5, 4)},
                {"|y log x| 4-16", pow_bin(4, 16)},
                {"|y log x| 16-64", pow_bin(16, 64)},
                {"|y log x| 64-88", pow_bin(64, 88)}},
               [](double x, double y, double) { return std::fabs(y * std::log(x)) <= 0.5; }});
  auto trig_bound = [](double c) {
    return [c](double x, double, double r) { return rel(c, r) + std::fabs(x) * 0x1p-96; };
  };
  // >= 44 bits with either guard wherever x is at least 2^-53 |x| away from the nearest multiple of
  // pi/2. Nearer, the bound's absolute term (the 97-bit pi/2 and the float tail of the reduction,
  // about |x| 2^-99 measured) dominates the small result: 43.09 bits at sin x = 2^-18, x = 2^38.7.
  auto trig_normal = [](double x, double, double) {
    return std::fabs(x) < 0x1p40 && distance_to_multiple_of_pio2(x) >= std::fabs(x) * 0x1p-53;
  };
  auto near_large_multiple = [pio2](std::mt19937_64& rng, double& x, double&) {
    // The float-float nearest k pi/2 for k in [2^20, 2^39]: |x - k pi/2| ~ 2^-49 |x|, the hardest
    // cases the 48-bit input allows for the Cody-Waite reduction (the two-word k included).
    x = std::floor(log_uniform(rng, 20, 39, false)) * pio2 * ((rng() & 1) ? -1 : 1);
  };
  std::vector<std::pair<const char*, std::function<void(std::mt19937_64&, double&, double&)>>> trig_families{
      {"log-uniform", [](auto& g, double& x, double&) { x = log_uniform(g, -30, 30); }},
      {"|x|<pi/4", [](auto& g, double& x, double&) { x = uniform(g, -0.7854, 0.7854); }},
      {"|x|<2^20", [](auto& g, double& x, double&) { x = uniform(g, -0x1p20, 0x1p20); }},
      {"near-k-pi/2", near_multiple},
      {"near-k-pi/2 big", near_large_multiple},
      {"2^20-2^30", [](auto& g, double& x, double&) { x = log_uniform(g, 20, 30); }},
      {"2^30-2^34", [](auto& g, double& x, double&) { x = log_uniform(g, 30, 34); }},
      {"2^34-2^36", [](auto& g, double& x, double&) { x = log_uniform(g, 34, 36); }},
      {"2^36-2^38", [](auto& g, double& x, double&) { x = log_uniform(g, 36, 38); }},
      {"2^38-2^40", [](auto& g, double& x, double&) { x = log_uniform(g, 38, 39.99); }}};
  f.push_back({"sin", "sin(x)", mpfr_sin, nullptr, ::sin, nullptr, trig_bound(20), trig_families, trig_normal});
  f.push_back({"cos", "cos(x)", mpfr_cos, nullptr, ::cos, nullptr, trig_bound(20), trig_families, trig_normal});
  f.push_back({"tan", "tan(x)", mpfr_tan, nullptr, ::tan, nullptr,
               [](double x, double, double r) { return rel(40, r) + std::fabs(x) * 0x1p-96 * (1 + r * r); },
               trig_families, trig_normal});
  f.push_back({"atan", "atan(x)", mpfr_atan, nullptr, ::atan, nullptr,
               [](double, double, double r) { return rel(70, r); },
               {{"log-uniform", [](auto& g, double& x, double&) { x = log_uniform(g, -60, 60); }},
                {"near-1", [](auto& g, double& x, double&) { x = (1 + uniform(g, -1, 1) * 0x1p-20) * ((g() & 1) ? -1 : 1); }}}});
  f.push_back({"atan2", "atan(y, x)", nullptr, mpfr_atan2, nullptr, ::atan2,
               [](double, double, double r) { return rel(70, r); },
               {{"log-uniform", [](auto& g, double& x, double& y) {
                   x = log_uniform(g, -40, 40);
                   y = log_uniform(g, -40, 40);
                 }},
                {"near-diagonals", [](auto& g, double& x, double& y) {
                   x = log_uniform(g, -10, 10);
                   y = x * (1 + uniform(g, -1, 1) * 0x1p-20) * ((g() & 1) ? -1 : 1);
                 }},
                // The smallest results the bound is documented for (docs/transcendentals.md): below
                // about 2^-100 the pair's lo word leaves float's normal range.
                {"tiny-results", [](auto& g, double& x, double& y) {
                   x = log_uniform(g, 0, 10);
                   y = x * log_uniform(g, -100, -80);
                 }}}});
  auto unit_families = std::vector<std::pair<const char*, std::function<void(std::mt19937_64&, double&, double&)>>>{
      {"uniform", [](auto& g, double& x, double&) { x = uniform(g, -1, 1); }},
      {"near-+-1", [](auto& g, double& x, double&) { x = (1 - log_uniform(g, -45, -1, false)) * ((g() & 1) ? -1 : 1); }},
      {"near-0", [](auto& g, double& x, double&) { x = log_uniform(g, -60, -1); }}};
  f.push_back({"asin", "asin(x)", mpfr_asin, nullptr, ::asin, nullptr,
               [](double, double, double r) { return rel(75, r); }, unit_families});
  f.push_back({"acos", "acos(x)", mpfr_acos, nullptr, ::acos, nullptr,
               [](double, double, double r) { return rel(75, r); }, unit_families});
  auto hyper_families = std::vector<std::pair<const char*, std::function<void(std::mt19937_64&, double&, double&)>>>{
      {"log-uniform", [](auto& g, double& x, double&) { x = log_uniform(g, -40, 6.47); }},
      {"near-0.3465", [](auto& g, double& x, double&) { x = 0.3465 * (1 + uniform(g, -1, 1) * 0x1p-10) * ((g() & 1) ? -1 : 1); }}};
  f.push_back({"sinh", "sinh(x)", mpfr_sinh, nullptr, ::sinh, nullptr,
               [](double, double, double r) { return rel(50, r); }, hyper_families});
  f.push_back({"cosh", "cosh(x)", mpfr_cosh, nullptr, ::cosh, nullptr,
               [](double, double, double r) { return rel(20, r); }, hyper_families});
  f.push_back({"tanh", "tanh(x)", mpfr_tanh, nullptr, ::tanh, nullptr,
               [](double, double, double r) { return rel(50, r); },
               {{"log-uniform", [](auto& g, double& x, double&) { x = log_uniform(g, -40, 4.6); }},
                {"near-0.17", [](auto& g, double& x, double&) { x = 0.17325 * (1 + uniform(g, -1, 1) * 0x1p-10) * ((g() & 1) ? -1 : 1); }}}});
  return f;
}

std::string shader_for(const Function& fn) {
  return std::string(R"(#version 450
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer In { vec4 xy[]; };
layout(std430, binding = 1) writeonly buffer Out { vec2 r[]; };
void main() {
  uint i = gl_GlobalInvocationID.x;
  vec4 v = xy[i];
  double x = double(v.x) + double(v.y);
  double y = double(v.z) + double(v.w);
  double z = )") + fn.expr + R"(;
  float hi = float(z);
  r[i] = vec2(hi, float(z - double(hi)));
}
)";
}

int sample_count() {
  const char* env = std::getenv("DOUBLET_TRANSCENDENTAL_SAMPLES");
  int n = env ? std::atoi(env) : 8192;
  return std::max(64, (n + 63) / 64 * 64);
}

std::vector<Input> make_inputs(const Function& fn, int n, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<Input> in(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) {
    const int family = i % static_cast<int>(fn.families.size());
    double x = 0, y = 0;
    fn.families[static_cast<size_t>(family)].second(rng, x, y);
    float xh = static_cast<float>(x), yh = static_cast<float>(y);
    in[static_cast<size_t>(i)] = {xh, static_cast<float>(x - xh), yh, static_cast<float>(y - yh), family};
  }
  return in;
}

struct FamilyResult {
  int samples = 0, failures = 0;
  double min_bits = 99, min_bits_host = 99, worst_ratio = 0;
  std::string worst, lowest;  // the input with the largest error / bound, the one with the fewest bits
};

struct Measurement {
  std::string error;
  std::vector<FamilyResult> families;
  double normal_min_bits = 99;
  int failures = 0;
};

// How the lowered text is run: as doublet emits it, or edited by a sabotage.
using Edit = std::function<std::string(const std::string&)>;

Measurement measure(const Function& fn, Backend backend, doublet::Target target, doublet::GuardKind guard,
                    bool demote = false, const Edit& edit = nullptr) {
  Measurement m;
  std::string glsl;
  if (demote) {
    glsl = doublet::frontend::demote_doubles(shader_for(fn));
    glsl.replace(glsl.find("#version 450"), 12, "#version 310 es\nprecision highp float;");
  } else {
    doublet::Options options;
    options.stage = doublet::Stage::Compute;
    options.target = target;
    options.guard = guard;
    options.file_name = std::string(fn.name) + ".comp";
    doublet::Result lowered = doublet::lower(shader_for(fn), options);
    if (!lowered.ok) {
      for (const auto& d : lowered.diagnostics) m.error += doublet::format_diagnostic(d) + "\n";
      return m;
    }
    glsl = edit ? edit(lowered.output) : lowered.output;
    if (glsl.empty()) {
      m.error = "the sabotage edit found nothing to change";
      return m;
    }
  }
  const int n = sample_count();
  auto inputs = make_inputs(fn, n, 20261124);
  doublet::runner::ComputeJob job;
  job.glsl = glsl;
  job.buffers.resize(2);
  job.buffers[0].resize(inputs.size() * 16);
  for (size_t i = 0; i < inputs.size(); ++i) {
    const float w[4] = {inputs[i].xh, inputs[i].xl, inputs[i].yh, inputs[i].yl};
    std::memcpy(job.buffers[0].data() + i * 16, w, 16);
  }
  job.buffers[1].assign(inputs.size() * 8, 0);
  job.groups_x = static_cast<uint32_t>(n / 64);
  auto result = doublet::runner::run_compute(backend, job);
  if (!result.ok) {
    m.error = result.error;
    return m;
  }
  m.families.resize(fn.families.size());
  mpfr_t x, y, ref, got, err;
  for (mpfr_ptr p : {x, y, ref, got, err}) mpfr_init2(p, 200);
  for (size_t i = 0; i < inputs.size(); ++i) {
    const Input& in = inputs[i];
    float out[2];
    std::memcpy(out, result.buffers[1].data() + i * 8, 8);
    mpfr_set_flt(x, in.xh, MPFR_RNDN);
    mpfr_add_d(x, x, in.xl, MPFR_RNDN);  // exact at 200 bits
    mpfr_set_flt(y, in.yh, MPFR_RNDN);
    mpfr_add_d(y, y, in.yl, MPFR_RNDN);
    if (fn.mpfr_fn1) fn.mpfr_fn1(ref, x, MPFR_RNDN);
    else fn.mpfr_fn2(ref, fn.name == std::string("atan2") ? y : x, fn.name == std::string("atan2") ? x : y, MPFR_RNDN);
    const double xd = mpfr_get_d(x, MPFR_RNDN), yd = mpfr_get_d(y, MPFR_RNDN), rd = mpfr_get_d(ref, MPFR_RNDN);
    mpfr_set_flt(got, out[0], MPFR_RNDN);
    mpfr_add_d(got, got, out[1], MPFR_RNDN);
    mpfr_sub(err, got, ref, MPFR_RNDN);
    mpfr_abs(err, err, MPFR_RNDN);
    const double abs_err = mpfr_get_d(err, MPFR_RNDU);
    const double allowed = fn.allowed(xd, yd, rd);
    const double bits = abs_err == 0 ? 99 : -std::log2(abs_err / std::fabs(rd));
    const double host = fn.host1 ? fn.host1(xd) : (fn.name == std::string("atan2") ? fn.host2(yd, xd) : fn.host2(xd, yd));
    const double host_err = std::fabs(static_cast<double>(out[0]) + static_cast<double>(out[1]) - host);
    const double bits_host = host_err == 0 ? 99 : -std::log2(host_err / std::fabs(host));
    FamilyResult& fam = m.families[static_cast<size_t>(in.family)];
    ++fam.samples;
    const bool bad = !(abs_err <= allowed) || std::isnan(out[0]);
    if (bad) ++fam.failures, ++m.failures;
    fam.min_bits_host = std::min(fam.min_bits_host, bits_host);
    const double ratio = std::isnan(out[0]) ? INFINITY : abs_err / allowed;
    if (bits < fam.min_bits || std::isnan(bits)) {
      fam.min_bits = std::isnan(bits) ? -1 : bits;
      char buf[200];
      std::snprintf(buf, sizeof buf, "x=%a y=%a got=%a+%a want=%a", xd, yd, out[0], out[1], rd);
      fam.lowest = buf;
    }
    if (ratio > fam.worst_ratio || (bad && fam.worst.empty())) {
      fam.worst_ratio = ratio;
      char buf[200];
      std::snprintf(buf, sizeof buf, "x=%a y=%a got=%a+%a want=%a", xd, yd, out[0], out[1], rd);
      fam.worst = buf;
    }
    if (!fn.normal || fn.normal(xd, yd, rd)) m.normal_min_bits = std::min(m.normal_min_bits, std::isnan(bits) ? -1 : bits);
  }
  for (mpfr_ptr p : {x, y, ref, got, err}) mpfr_clear(p);
  return m;
}

std::string report(const Function& fn, const Measurement& m) {
  std::string s;
  for (size_t k = 0; k < m.families.size(); ++k) {
    const FamilyResult& f = m.families[k];
    char line[1024];
    std::snprintf(line, sizeof line,
                  "  %-6s %-16s n=%6d min bits %6.2f (vs host double %6.2f)  worst err/bound %8.3g  failures %d  %s"
                  "  (fewest bits: %s)\n",
                  fn.name, fn.families[k].first, f.samples, f.min_bits, f.min_bits_host, f.worst_ratio, f.failures,
                  f.worst.c_str(), f.lowest.c_str());
    s += line;
  }
  char line[128];
  std::snprintf(line, sizeof line, "  %-6s normal range: min bits %.2f\n", fn.name, m.normal_min_bits);
  return s + line;
}

struct Case {
  Backend backend;
  doublet::Target target;
};

class Transcendentals : public ::testing::TestWithParam<Case> {};

TEST_P(Transcendentals, WithinDocumentedBoundsAndAtLeast44BitsInTheNormalRange) {
  auto [backend, target] = GetParam();
  ASSERT_EQ(doublet::runner::backend_unavailable_reason(backend), "");
  for (const Function& fn : functions()) {
    Measurement m = measure(fn, backend, target, doublet::GuardKind::Auto);
    ASSERT_TRUE(m.error.empty()) << fn.name << ": " << m.error;
    std::printf("%s", report(fn, m).c_str());
    EXPECT_EQ(m.failures, 0) << fn.name << "\n" << report(fn, m);
    EXPECT_GE(m.normal_min_bits, 44.0) << fn.name << "\n" << report(fn, m);
  }
}

TEST_P(Transcendentals, WithoutTheGuardTheBoundsBreak) {
  auto [backend, target] = GetParam();
  int broken = 0;
  std::string all;
  for (const Function& fn : functions()) {
    Measurement m = measure(fn, backend, target, doublet::GuardKind::None);
    ASSERT_TRUE(m.error.empty()) << fn.name << ": " << m.error;
    broken += m.failures > 0;
    all += report(fn, m);
  }
  std::printf("guard removed:\n%s", all.c_str());
  EXPECT_GE(broken, 10) << all;
}

TEST_P(Transcendentals, DroppingLoBreaksEveryFunction) {
  auto [backend, target] = GetParam();
  for (const Function& fn : functions()) {
    Measurement m = measure(fn, backend, target, doublet::GuardKind::Auto, true);
    ASSERT_TRUE(m.error.empty()) << fn.name << ": " << m.error;
    EXPECT_GT(m.failures, 0) << fn.name << " kept its bound with doubles demoted to float\n" << report(fn, m);
    EXPECT_LT(m.normal_min_bits, 30.0) << fn.name;
  }
}

// Each argument reduction skipped by editing one step of the lowered text; the edit must apply.
// Every occurrence is replaced (the pi/2 reduction has two rounds).
Edit replace(const std::string& from, const std::string& to) {
  return [from, to](const std::string& text) {
    std::string out = text;
    size_t count = 0;
    for (size_t at = out.find(from); at != std::string::npos; at = out.find(from, at + to.size()), ++count)
      out.replace(at, from.size(), to);
    return count ? out : std::string();
  };
}

// Both edits, in order; empty (the sabotage did not apply) when either finds nothing.
Edit both(const Edit& first, const Edit& second) {
  return [first, second](const std::string& text) {
    const std::string once = first(text);
    return once.empty() ? once : second(once);
  };
}

TEST_P(Transcendentals, SkippingAnArgumentReductionBreaksTheBound) {
  auto [backend, target] = GetParam();
  struct Sabotage {
    const char* function;
    Edit edit;
  };
  const std::vector<Sabotage> sabotages{
      {"exp", replace("floor(x.hi * 1.44269504 + 0.5)", "floor(0.5)")},          // no ln 2 reduction
      {"exp2", replace("floor(x.hi + 0.5)", "floor(0.5)")},                      // no integer split
      {"log", replace("m0.hi < 0.707106781", "m0.hi < 0.0")},                    // m left in [0.5, 1)
      {"sin", both(replace("roundEven(t.hi)", "roundEven(0.0)"), replace("roundEven(f + t.lo)", "roundEven(0.0)"))},  // k = 0
      {"cos", both(replace("roundEven(t.hi)", "roundEven(0.0)"), replace("roundEven(f + t.lo)", "roundEven(0.0)"))},
      {"atan", replace("df_double h = df_atan_halve(h1);", "df_double h = h1;")},  // one half-angle step
  };
  for (const Sabotage& s : sabotages) {
    for (const Function& fn : functions()) {
      if (fn.name != std::string(s.function)) continue;
      Measurement m = measure(fn, backend, target, doublet::GuardKind::Auto, false, s.edit);
      ASSERT_TRUE(m.error.empty()) << fn.name << ": " << m.error;
      std::printf("reduction skipped:\n%s", report(fn, m).c_str());
      EXPECT_GT(m.failures, 0) << fn.name << " kept its bound without its argument reduction\n" << report(fn, m);
    }
  }
}

// The cause of the Uniform guard's old trigonometry gap (31-35 bits for |x| > 2^23): the reduction's
// k = k1 + k2 computed as k1 = floor(t.hi + 0.5), k2 = floor((t.hi - k1) + t.lo + 0.5). Without
// `precise` Mesa reassociates the second + 0.5 into the first (t.hi - k1 + 0.5 becomes
// (t.hi + 0.5) - k1, and t.hi + 0.5 rounds to t.hi above 2^23), so k2 comes out one short and the
// kernels run outside |r| <= pi/4. Put back into the lowered text, that form must break the bound
// with the Uniform guard (the check above would catch the regression) and keep it with `precise`.
TEST_P(Transcendentals, FloorPlusHalfReductionNeedsPrecise) {
  auto [backend, target] = GetParam();
  const bool precise = target == doublet::Target::Es320 || target == doublet::Target::Glsl450;
  const Edit old_reduction = both(replace("roundEven(t.hi)", "floor(t.hi + 0.5)"),
                                  replace("roundEven(f + t.lo)", "floor(f + t.lo + 0.5)"));
  for (const Function& fn : functions()) {
    if (fn.name != std::string("sin") && fn.name != std::string("cos")) continue;
    Measurement m = measure(fn, backend, target, doublet::GuardKind::Auto, false, old_reduction);
    ASSERT_TRUE(m.error.empty()) << fn.name << ": " << m.error;
    std::printf("floor(x + 0.5) reduction:\n%s", report(fn, m).c_str());
    if (precise) {
      EXPECT_EQ(m.failures, 0) << fn.name << "\n" << report(fn, m);
    } else {
      EXPECT_GT(m.failures, 0) << fn.name << " kept its bound with the old reduction\n" << report(fn, m);
      EXPECT_LT(m.normal_min_bits, 40.0) << fn.name;
    }
  }
}

// Special values follow the C library (C99 Annex F.9), the host's libm giving the expected value,
// except where docs/transcendentals.md documents a difference (listed with that value).
TEST_P(Transcendentals, SpecialValuesFollowC) {
  auto [backend, target] = GetParam();
  const double inf = INFINITY, nan = NAN;
  struct Special {
    const char* function;
    double x, y;
    double documented;  // NaN: the host's libm is the reference
    bool use_documented = false;
  };
  const std::vector<Special> cases{
      {"exp", -inf, 0, 0}, {"exp", inf, 0, 0}, {"exp", nan, 0, 0}, {"exp", -200, 0, 0}, {"exp", 200, 0, 0},
      {"exp", 0, 0, 0}, {"exp", -0.0, 0, 0}, {"exp2", -inf, 0, 0}, {"exp2", inf, 0, 0}, {"exp2", 10, 0, 0},
      {"exp2", -149, 0, 0}, {"log", 0, 0, 0}, {"log", -0.0, 0, 0}, {"log", -1, 0, 0}, {"log", inf, 0, 0},
      {"log", -inf, 0, 0}, {"log", nan, 0, 0}, {"log", 1, 0, 0}, {"log2", 0, 0, 0}, {"log2", -1, 0, 0},
      {"log2", inf, 0, 0}, {"log2", 1024, 0, 0}, {"log2", 1, 0, 0}, {"pow", 2, 0, 0}, {"pow", 0, 2, 0},
      {"pow", 0, -2, 0}, {"pow", 1, nan, 0}, {"pow", 1, 1e30, 0}, {"pow", 2, 10, 0}, {"pow", nan, 0, 0},
      {"pow", -8, 1.0 / 3, 0}, {"pow", -2, 3, nan, true},  // C gives -8; doublet NaN for x < 0 (documented)
      {"sin", 0, 0, 0}, {"sin", -0.0, 0, 0}, {"sin", inf, 0, 0}, {"sin", nan, 0, 0}, {"sin", 0x1p41, 0, nan, true},
      {"cos", 0, 0, 0}, {"cos", inf, 0, 0}, {"cos", nan, 0, 0}, {"tan", 0, 0, 0}, {"tan", -0.0, 0, 0},
      {"tan", inf, 0, 0}, {"asin", 0, 0, 0}, {"asin", -0.0, 0, 0}, {"asin", 1, 0, 0}, {"asin", -1, 0, 0},
      {"asin", 2, 0, 0}, {"acos", 1, 0, 0}, {"acos", -1, 0, 0}, {"acos", 0, 0, 0}, {"acos", -2, 0, 0},
      {"atan", 0, 0, 0}, {"atan", -0.0, 0, 0}, {"atan", inf, 0, 0}, {"atan", -inf, 0, 0}, {"atan", nan, 0, 0},
      {"atan2", 1, 0, 0}, {"atan2", -1, 0, 0}, {"atan2", 0, 1, 0}, {"atan2", 0, -1, 0}, {"atan2", -0.0, -1, 0},
      {"atan2", 1, inf, 0}, {"atan2", 0, 0, 0}, {"atan2", nan, 1, 0},
      {"sinh", 0, 0, 0}, {"sinh", -0.0, 0, 0}, {"sinh", inf, 0, 0}, {"sinh", -inf, 0, 0}, {"sinh", nan, 0, 0},
      {"sinh", 89.0, 0, inf, true},  // true value 2.2e38 < FLT_MAX: float-float's exp range ends at 88.72 (documented)
      {"cosh", 0, 0, 0}, {"cosh", inf, 0, 0}, {"cosh", -inf, 0, 0}, {"cosh", nan, 0, 0},
      {"tanh", 0, 0, 0}, {"tanh", -0.0, 0, 0}, {"tanh", 30, 0, 0}, {"tanh", -30, 0, 0}, {"tanh", inf, 0, 0},
      {"tanh", -inf, 0, 0}, {"tanh", nan, 0, 0}};
  std::string failures;
  for (const Function& fn : functions()) {
    std::vector<Special> mine;
    for (const Special& c : cases)
      if (c.function == std::string(fn.name)) mine.push_back(c);
    if (mine.empty()) continue;
    doublet::Options options;
    options.stage = doublet::Stage::Compute;
    options.target = target;
    options.file_name = std::string(fn.name) + ".comp";
    doublet::Result lowered = doublet::lower(shader_for(fn), options);
    ASSERT_TRUE(lowered.ok) << fn.name;
    doublet::runner::ComputeJob job;
    job.glsl = lowered.output;
    job.buffers.resize(2);
    job.buffers[0].assign(64 * 16, 0);
    job.buffers[1].assign(64 * 8, 0);
    for (size_t i = 0; i < mine.size(); ++i) {
      // atan2's shader is atan(y, x): the first value of a case is y.
      const double x = fn.name == std::string("atan2") ? mine[i].y : mine[i].x;
      const double y = fn.name == std::string("atan2") ? mine[i].x : mine[i].y;
      // lo = a zero of x's sign: -0 + -0 keeps the input's -0 (-0 + +0 would be +0).
      const float w[4] = {static_cast<float>(x), std::copysign(0.0f, static_cast<float>(x)), static_cast<float>(y),
                          std::copysign(0.0f, static_cast<float>(y))};
      std::memcpy(job.buffers[0].data() + i * 16, w, 16);
    }
    auto result = doublet::runner::run_compute(backend, job);
    ASSERT_TRUE(result.ok) << result.error;
    for (size_t i = 0; i < mine.size(); ++i) {
      const Special& c = mine[i];
      float out[2];
      std::memcpy(out, result.buffers[1].data() + i * 8, 8);
      // The shader's low word is z - hi, NaN when hi is infinite: then hi alone is the value.
      // A zero low word adds nothing (and -0 + 0 would lose hi's sign).
      const double got = std::isinf(out[0]) || out[1] == 0 ? out[0] : static_cast<double>(out[0]) + static_cast<double>(out[1]);
      double want = c.use_documented ? c.documented : fn.host1 ? fn.host1(c.x) : fn.host2(c.x, c.y);
      if (std::isfinite(want) && std::fabs(want) > 3.4028234663852886e38) want = std::copysign(inf, want);
      if (std::isfinite(want) && want != 0 && std::fabs(want) < 0x1p-149) want = std::copysign(0.0, want);
      bool ok = std::isnan(want) ? std::isnan(got)
                : (want == 0 || std::isinf(want)) ? (got == want && std::signbit(got) == std::signbit(want))
                                                  : std::fabs(got - want) <= 0x1p-40 * std::fabs(want);
      if (!ok) {
        char line[200];
        std::snprintf(line, sizeof line, "%s(%g, %g): got %a, want %a\n", fn.name, c.x, c.y, got, want);
        failures += line;
      }
    }
  }
  EXPECT_TRUE(failures.empty()) << failures;
}

// The vertex and fragment stages (geodesy runs in vertex shaders; Mesa flushes subnormals there
// and optimizes each stage on its own): eight functions on inputs over wide ranges, each result
// within its documented bound of MPFR; without the optimizer guard some must break it.
struct StageCase {
  Backend backend;
  doublet::runner::GraphicsStage stage;
  doublet::Target target;
};

constexpr uint32_t kStageSamples = 512;

// Per sample: 8 inputs (a.xyzw, b.xyzw), each exact float-float.
std::vector<double> stage_inputs() {
  std::mt19937_64 rng(11);
  const double lo[8] = {-100, -30, 0.01, -100, -2, -5, -1, -1000}, hi[8] = {100, 30, 100, 100, 2, 5, 1, 1000};
  std::vector<double> v;
  for (uint32_t i = 0; i < kStageSamples; ++i)
    for (int k = 0; k < 8; ++k) {
      const double x = uniform(rng, lo[k], hi[k]);
      const float h = static_cast<float>(x);
      v.push_back(static_cast<double>(h) + static_cast<double>(static_cast<float>(x - h)));
    }
  return v;
}

std::string stage_shader(doublet::runner::GraphicsStage stage) {
  const bool fragment = stage == doublet::runner::GraphicsStage::Fragment;
  std::string s = "#version 450\n";
  s += fragment ? "flat in dvec4 a;\nflat in dvec4 b;\nlayout(location = 0) out vec4 r_hi;\nlayout(location = 1) out vec4 r_lo;\n"
                  "layout(location = 2) out vec4 s_hi;\nlayout(location = 3) out vec4 s_lo;\n"
                : "in dvec4 a;\nin dvec4 b;\nlayout(location = 0) out dvec4 r;\nlayout(location = 2) out dvec4 s;\n";
  s += "void main() {\n"
       "  dvec4 rr = dvec4(sin(a.x), exp(a.y), log(a.z), atan(a.w, a.x));\n"
       "  dvec4 ss = dvec4(pow(a.z, b.x), tanh(b.y), acos(b.z), cos(b.w));\n";
  s += fragment ? "  r_hi = vec4(rr);\n  r_lo = vec4(rr - dvec4(r_hi));\n  s_hi = vec4(ss);\n  s_lo = vec4(ss - dvec4(s_hi));\n"
                : "  r = rr;\n  s = ss;\n  gl_Position = vec4(0.0);\n";
  return s + "}\n";
}

// Results over their bounds (and a description of the worst); -1 with *error when nothing ran.
int stage_failures(const StageCase& c, doublet::GuardKind guard, std::string* worst, std::string* error) {
  doublet::Options o;
  o.stage = c.stage == doublet::runner::GraphicsStage::Vertex ? doublet::Stage::Vertex : doublet::Stage::Fragment;
  o.target = c.target;
  o.guard = guard;
  o.file_name = "stage.glsl";
  auto lowered = doublet::lower(stage_shader(c.stage), o);
  if (!lowered.ok) {
    for (const auto& d : lowered.diagnostics) *error += doublet::format_diagnostic(d) + "\n";
    return -1;
  }
  const std::vector<double> in = stage_inputs();
  doublet::runner::GraphicsJob job;
  job.stage = c.stage;
  job.glsl = lowered.output;
  job.count = kStageSamples;
  for (const char* v : {"a", "b"}) {
    std::vector<double> h, l;
    for (uint32_t i = 0; i < kStageSamples; ++i)
      for (int k = 0; k < 4; ++k) {
        const double x = in[i * 8 + (v[0] == 'a' ? 0 : 4) + k];
        h.push_back(static_cast<float>(x));
        l.push_back(x - static_cast<float>(x));
      }
    job.inputs[std::string(v) + "_hi"] = h;
    job.inputs[std::string(v) + "_lo"] = l;
  }
  auto result = doublet::runner::run_graphics(c.backend, job);
  if (!result.ok) {
    *error = result.error;
    return -1;
  }
  int failures = 0;
  double worst_ratio = 0;
  mpfr_t x, y, ref;
  for (mpfr_ptr p : {x, y, ref}) mpfr_init2(p, 200);
  const char* names[8] = {"sin", "exp", "log", "atan2", "pow", "tanh", "acos", "cos"};
  for (uint32_t i = 0; i < kStageSamples; ++i) {
    const double* v = &in[i * 8];
    for (int k = 0; k < 8; ++k) {
      const char* word = k < 4 ? "r" : "s";
      const double got = result.outputs[std::string(word) + "_hi"][i * 4 + k % 4] +
                         result.outputs[std::string(word) + "_lo"][i * 4 + k % 4];
      double allowed = 0;
      switch (k) {  // the inputs are exact in binary64, so MPFR sees the shader's values
        case 0: mpfr_set_d(x, v[0], MPFR_RNDN); mpfr_sin(ref, x, MPFR_RNDN); break;
        case 1: mpfr_set_d(x, v[1], MPFR_RNDN); mpfr_exp(ref, x, MPFR_RNDN); break;
        case 2: mpfr_set_d(x, v[2], MPFR_RNDN); mpfr_log(ref, x, MPFR_RNDN); break;
        case 3: mpfr_set_d(y, v[3], MPFR_RNDN); mpfr_set_d(x, v[0], MPFR_RNDN); mpfr_atan2(ref, y, x, MPFR_RNDN); break;
        case 4: mpfr_set_d(x, v[2], MPFR_RNDN); mpfr_set_d(y, v[4], MPFR_RNDN); mpfr_pow(ref, x, y, MPFR_RNDN); break;
        case 5: mpfr_set_d(x, v[5], MPFR_RNDN); mpfr_tanh(ref, x, MPFR_RNDN); break;
        case 6: mpfr_set_d(x, v[6], MPFR_RNDN); mpfr_acos(ref, x, MPFR_RNDN); break;
        default: mpfr_set_d(x, v[7], MPFR_RNDN); mpfr_cos(ref, x, MPFR_RNDN); break;
      }
      const double want = mpfr_get_d(ref, MPFR_RNDN);
      const double c_u2[8] = {20, 10, 28, 70, 40 + 31 * std::fabs(v[4] * std::log(v[2])), 50, 75, 20};
      allowed = c_u2[k] * kU2 * std::fabs(want) + ((k == 0 || k == 7) ? std::fabs(v[k == 0 ? 0 : 7]) * 0x1p-96 : 0);
      mpfr_set_d(x, got, MPFR_RNDN);
      mpfr_sub(x, x, ref, MPFR_RNDN);
      const double err = std::fabs(mpfr_get_d(x, MPFR_RNDN));
      const double ratio = std::isnan(got) ? INFINITY : err / allowed;
      if (!(ratio <= 1)) ++failures;
      if (!(ratio <= worst_ratio)) {
        worst_ratio = ratio;
        char buf[160];
        std::snprintf(buf, sizeof buf, "%s: got %a want %a (error / bound %.3g)", names[k], got, want, ratio);
        *worst = buf;
      }
    }
  }
  for (mpfr_ptr p : {x, y, ref}) mpfr_clear(p);
  return failures;
}

class TranscendentalStages : public ::testing::TestWithParam<StageCase> {};

TEST_P(TranscendentalStages, WithinBoundsAndBrokenWithoutTheGuard) {
  std::string worst, error;
  const int failures = stage_failures(GetParam(), doublet::GuardKind::Auto, &worst, &error);
  ASSERT_GE(failures, 0) << error;
  std::printf("worst: %s\n", worst.c_str());
  EXPECT_EQ(failures, 0) << worst;
  std::string sabotaged_worst;
  const int sabotaged = stage_failures(GetParam(), doublet::GuardKind::None, &sabotaged_worst, &error);
  ASSERT_GE(sabotaged, 0) << error;
  std::printf("guard removed: %d results over their bounds, worst %s\n", sabotaged, sabotaged_worst.c_str());
  EXPECT_GT(sabotaged, 0) << "the stage check kept its bounds without the optimizer guard";
}

INSTANTIATE_TEST_SUITE_P(
    Drivers, TranscendentalStages,
    ::testing::Values(StageCase{Backend::Vulkan, doublet::runner::GraphicsStage::Vertex, doublet::Target::Glsl450},
                      StageCase{Backend::Vulkan, doublet::runner::GraphicsStage::Fragment, doublet::Target::Glsl450},
                      StageCase{Backend::Gles, doublet::runner::GraphicsStage::Vertex, doublet::Target::Es300},
                      StageCase{Backend::Gles, doublet::runner::GraphicsStage::Fragment, doublet::Target::Es320}),
    [](const auto& info) {
      return std::string(doublet::runner::backend_name(info.param.backend)) + "_" +
             (info.param.stage == doublet::runner::GraphicsStage::Vertex ? "vert" : "frag") + "_" +
             std::string(doublet::to_string(info.param.target));
    });

INSTANTIATE_TEST_SUITE_P(Drivers, Transcendentals,
                         ::testing::Values(Case{Backend::Vulkan, doublet::Target::Es310},
                                           Case{Backend::Vulkan, doublet::Target::Glsl450},
                                           Case{Backend::Gles, doublet::Target::Es310},
                                           Case{Backend::Gles, doublet::Target::Es320}),
                         [](const auto& info) {
                           return std::string(doublet::runner::backend_name(info.param.backend)) + "_" +
                                  std::string(doublet::to_string(info.param.target));
                         });

}  // namespace

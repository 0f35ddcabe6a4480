// Mode rte-exact: float(a - b) of two stored doubles is the float nearest (ties to even) to the EXACT
// real difference, rounded once. A compute shader lowered with --mode rte-exact to ES 3.10, run on
// lavapipe and Mesa GLES over 2^20 pairs (random patterns, near-equal operands, huge magnitudes,
// float-subnormal and zero differences, pairs whose binary64 difference lands on a float tie,
// float's overflow threshold, every special class), must store MPFR's correctly rounded float
// (the exact difference at 2200 bits, then mpfr_get_flt) in every result; NaN results count by
// class. Sabotages: rounding twice (the same shader in --mode exact: binary64, then float) and
// ignoring the sticky bit must both differ.
#include <gtest/gtest.h>
#include <mpfr.h>

#include <cmath>
#include <cstdint>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include "doublet/doublet.hpp"
#include "test_util.hpp"

namespace doublet::runner::test {
namespace {

constexpr uint32_t kPairs = 1u << 20;

const char* kSource = R"(#version 450
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer In { dvec2 ab[]; };
layout(std430, binding = 1) writeonly buffer Out { float r[]; };
void main() {
  uint i = gl_GlobalInvocationID.x;
  r[i] = float(ab[i].x - ab[i].y);
}
)";

double d_of(uint64_t x) { return bits<double>(x); }
uint64_t bits_of(double x) { return bits<uint64_t>(x); }

std::vector<double> make_pairs() {
  std::mt19937_64 rng(20261125);
  const uint64_t specials[] = {0, 1, 0x000FFFFFFFFFFFFFull, 0x0010000000000000ull, 0x7FEFFFFFFFFFFFFFull,
                               0x7FF0000000000000ull, 0x7FF8000000000000ull, 0x7FF0000000000001ull,
                               0x3FF0000000000000ull, 0x47EFFFFFE0000000ull /* FLT_MAX */,
                               0x47EFFFFFF0000000ull /* float overflow threshold */, 0x3810000000000000ull /* FLT_MIN */,
                               0x36A0000000000000ull /* 2^-149 */, 0x3690000000000000ull /* 2^-150 */};
  auto sign = [&](double x) { return (rng() & 1) ? -x : x; };
  auto exponent_range = [&](int lo, int hi) {  // a random double with unbiased exponent in [lo, hi]
    const uint64_t e = uint64_t(1023 + lo + int(rng() % uint64_t(hi - lo + 1)));
    return d_of((e << 52) | (rng() >> 12));
  };
  std::vector<double> ab(2 * size_t(kPairs));
  for (uint32_t i = 0; i < kPairs; ++i) {
    double a = 0, b = 0;
    switch (i % 8) {
      case 0:  // random patterns: every exponent, NaN and Inf included
        a = d_of(rng());
        b = d_of(rng());
        break;
      case 1: {  // near-equal: b a few to 2^40 ulps from a (catastrophic cancellation)
        a = sign(exponent_range(-40, 40));
        const int64_t ulps = int64_t(rng() % (uint64_t(1) << (rng() % 41))) * ((rng() & 1) ? 1 : -1);
        b = d_of(uint64_t(int64_t(bits_of(a)) + ulps));
        break;
      }
      case 2:  // huge magnitudes, around 1e300, near-equal or not
        a = sign(exponent_range(990, 1023));
        b = (rng() & 1) ? d_of(bits_of(a) + (rng() % 1024)) : sign(exponent_range(990, 1023));
        break;
      case 3: {  // differences in float's subnormal range (|a - b| below 2^-126) and double subnormals
        a = sign(exponent_range(-140, -110));
        b = (rng() % 4 == 0) ? d_of(rng() & 0x800FFFFFFFFFFFFFull) : a - sign(exponent_range(-160, -126));
        break;
      }
      case 4: {  // the binary64 difference lands on a float tie: t = float f + half its ulp, minus a tiny b
        const float f = static_cast<float>(exponent_range(-100, 100));
        const double t = double(f) + std::ldexp(double(std::nextafter(f, INFINITY) - f), -1);
        a = sign(1) * t;
        b = std::ldexp(a, -int(54 + rng() % 60)) * ((rng() & 1) ? 1 : -1);
        break;
      }
      case 5:  // mixed magnitudes
        a = sign(exponent_range(-1000, 1000));
        b = sign(exponent_range(-1000, 1000));
        break;
      case 6:  // specials against anything
        a = sign(d_of(specials[rng() % std::size(specials)]));
        b = (rng() & 1) ? sign(d_of(specials[rng() % std::size(specials)])) : sign(exponent_range(-200, 200));
        break;
      default:  // around float's overflow threshold and FLT_MAX
        a = sign(d_of(specials[9 + rng() % 2]));
        b = d_of(uint64_t(rng() % 4096) << (rng() % 40)) * ((rng() & 1) ? 1 : -1);
        break;
    }
    if (rng() & 1) std::swap(a, b);
    ab[2 * size_t(i)] = a;
    ab[2 * size_t(i) + 1] = b;
  }
  return ab;
}

// MPFR: the exact difference (2200 bits hold any two doubles' difference), rounded once to float.
std::vector<float> reference(const std::vector<double>& ab, uint32_t* exact_double_checks) {
  mpfr_t x, y, d;
  mpfr_inits2(2200, x, y, d, static_cast<mpfr_ptr>(nullptr));
  std::vector<float> out(kPairs);
  *exact_double_checks = 0;
  for (uint32_t i = 0; i < kPairs; ++i) {
    const double a = ab[2 * size_t(i)], b = ab[2 * size_t(i) + 1];
    mpfr_set_d(x, a, MPFR_RNDN);
    mpfr_set_d(y, b, MPFR_RNDN);
    mpfr_sub(d, x, y, MPFR_RNDN);  // exact
    out[i] = mpfr_get_flt(d, MPFR_RNDN);
    // Where a - b is a double, the host's float(a - b) rounds once too: it must agree with MPFR.
    volatile double host = a - b;
    if (std::isfinite(host) && mpfr_cmp_d(d, host) == 0) {
      EXPECT_EQ(bits<uint32_t>(static_cast<float>(host)), bits<uint32_t>(out[i])) << a << " - " << b;
      ++*exact_double_checks;
    }
  }
  mpfr_clears(x, y, d, static_cast<mpfr_ptr>(nullptr));
  return out;
}

std::vector<float> run(Backend backend, const std::string& glsl, const std::vector<double>& ab) {
  ComputeJob job;
  job.glsl = glsl;
  job.buffers = {to_bytes(ab), std::vector<uint8_t>(size_t(kPairs) * 4)};
  job.groups_x = kPairs / 64;
  ComputeResult r = run_compute(backend, job);
  EXPECT_TRUE(r.ok) << backend_name(backend) << ": " << r.error;
  return r.ok ? from_bytes<float>(r.buffers[1]) : std::vector<float>{};
}

// Results that differ from the reference (NaN against NaN is equal, whatever the payload).
uint32_t differing(const std::vector<float>& got, const std::vector<float>& want, const std::vector<double>& ab,
                   const char* what) {
  if (got.size() != want.size()) return kPairs;
  uint32_t n = 0;
  for (uint32_t i = 0; i < kPairs; ++i) {
    const bool same = std::isnan(got[i]) ? std::isnan(want[i]) : bits<uint32_t>(got[i]) == bits<uint32_t>(want[i]);
    if (same) continue;
    if (n++ == 0)
      std::printf("[ rte-exact ] %s first: a=%a b=%a got %a want %a\n", what, ab[2 * size_t(i)],
                  ab[2 * size_t(i) + 1], double(got[i]), double(want[i]));
  }
  return n;
}

Result lower_with(Mode mode) {
  Options o;
  o.stage = Stage::Compute;
  o.target = Target::Es310;
  o.mode = mode;
  return lower(kSource, o);
}

TEST(RteExact, DifferenceRoundedOnceMatchesMpfrOnBothDrivers) {
  REQUIRE_BACKEND(Backend::Vulkan);
  REQUIRE_BACKEND(Backend::Gles);
  const Result lowered = lower_with(Mode::RteExact);
  std::string diagnostics;
  for (const Diagnostic& d : lowered.diagnostics) diagnostics += format_diagnostic(d) + "\n";
  ASSERT_TRUE(lowered.ok) << diagnostics;
  EXPECT_NE(lowered.output.find("ex_sub_to_float("), std::string::npos);
  EXPECT_EQ(lowered.output.find("ex_sub("), std::string::npos) << "no binary64 subtraction on the way";
  const std::vector<double> ab = make_pairs();
  uint32_t checks = 0;
  const std::vector<float> want = reference(ab, &checks);
  EXPECT_GT(checks, kPairs / 8) << "the host cross-check of MPFR ran";
  uint32_t double_rounded = 0;  // pairs where float(binary64 a - b) is not the reference
  for (uint32_t i = 0; i < kPairs; ++i) {
    volatile double d = ab[2 * size_t(i)] - ab[2 * size_t(i) + 1];
    const float twice = static_cast<float>(d);
    double_rounded += !(std::isnan(twice) ? std::isnan(want[i]) : bits<uint32_t>(twice) == bits<uint32_t>(want[i]));
  }
  std::cout << "[ rte-exact ] host float(a - b) in binary64 (two roundings) differs on " << double_rounded << " of "
            << kPairs << "\n";
  EXPECT_GT(double_rounded, 1000u) << "the inputs exercise double rounding";
  for (Backend backend : {Backend::Vulkan, Backend::Gles}) {
    const uint32_t n = differing(run(backend, lowered.output, ab), want, ab, backend_name(backend));
    std::cout << "[ rte-exact ] " << backend_name(backend) << ": " << n << " of " << kPairs
              << " results differ from MPFR's correctly rounded float\n";
    EXPECT_EQ(n, 0u) << backend_name(backend);
  }
}

// Double matrices in rte-exact are stored as mode exact's (binary64 words): the differences of
// their elements round once like any other (the helpers were float-float's before: the lowered
// shader did not compile, an internal error).
TEST(RteExact, MatrixElementsKeepTheirWordsAndTheirDifferenceRoundsOnce) {
  REQUIRE_BACKEND(Backend::Vulkan);
  REQUIRE_BACKEND(Backend::Gles);
  Options o;
  o.stage = Stage::Compute;
  o.target = Target::Es310;
  o.mode = Mode::RteExact;
  const Result lowered = lower(R"(#version 450
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer In { dvec2 ab[]; };
layout(std430, binding = 1) writeonly buffer Out { float r[]; };
void main() {
  uint i = gl_GlobalInvocationID.x;
  dmat2 m = dmat2(ab[i].x, 0.0lf, 0.0lf, 1.0lf);
  m[1][1] = ab[i].y;
  r[i] = float(m[0][0] - m[1][1]);
}
)", o);
  std::string diagnostics;
  for (const Diagnostic& d : lowered.diagnostics) diagnostics += format_diagnostic(d) + "\n";
  ASSERT_TRUE(lowered.ok) << diagnostics;
  const std::vector<double> ab = make_pairs();
  uint32_t checks = 0;
  const std::vector<float> want = reference(ab, &checks);
  for (Backend backend : {Backend::Vulkan, Backend::Gles}) {
    const uint32_t n = differing(run(backend, lowered.output, ab), want, ab, backend_name(backend));
    EXPECT_EQ(n, 0u) << backend_name(backend);
  }
}

TEST(RteExact, RoundingTwiceOrWithoutStickyDiffers) {
  REQUIRE_BACKEND(Backend::Vulkan);
  const std::vector<double> ab = make_pairs();
  uint32_t checks = 0;
  const std::vector<float> want = reference(ab, &checks);
  // Mode exact lowers the same float(a - b) as ex_to_float(ex_sub(a, b)): binary64, then float.
  const Result twice = lower_with(Mode::Exact);
  ASSERT_TRUE(twice.ok);
  const uint32_t twice_differ = differing(run(Backend::Vulkan, twice.output, ab), want, ab, "rounded twice");
  // No sticky bit: a round bit with anything below it is taken for a tie.
  Result no_sticky = lower_with(Mode::RteExact);
  ASSERT_TRUE(no_sticky.ok);
  const std::string sticky = "rest == 3u || ";
  ASSERT_NE(no_sticky.output.find(sticky), std::string::npos);
  no_sticky.output.erase(no_sticky.output.find(sticky), sticky.size());
  const uint32_t sticky_differ = differing(run(Backend::Vulkan, no_sticky.output, ab), want, ab, "no sticky");
  std::cout << "[ rte-exact ] sabotaged: rounded twice " << twice_differ << ", without the sticky bit "
            << sticky_differ << " of " << kPairs << " differ\n";
  EXPECT_GT(twice_differ, 0u);
  EXPECT_GT(sticky_differ, 0u);
}

TEST(RteExact, WholeShaderOnlyAndNeedsEs300) {
  auto first_error = [](const Result& r) {
    for (const Diagnostic& d : r.diagnostics)
      if (d.severity == Severity::Error) return format_diagnostic(d);
    return std::string("(no error)");
  };
  Options o;
  o.stage = Stage::Vertex;
  o.target = Target::Es100;
  o.mode = Mode::RteExact;
  const Result es100 = lower("#version 450\nin double a;\nvoid main() { gl_Position = vec4(float(a)); }\n", o);
  EXPECT_NE(first_error(es100).find("--mode rte-exact needs 32-bit integers"), std::string::npos) << first_error(es100);
  o.target = Target::Es300;
  o.mode = Mode::Df64;
  o.mode_for = {{"main", Mode::RteExact}};
  const Result named = lower("#version 450\nin double a;\nvoid main() { gl_Position = vec4(float(a)); }\n", o);
  EXPECT_NE(first_error(named).find("applies to the whole shader only"), std::string::npos) << first_error(named);
  o.mode = Mode::RteExact;
  o.mode_for.clear();
  const Result pragma =
      lower("#version 450\nin double a;\n#pragma doublet mode(fp32)\nvoid main() { gl_Position = vec4(float(a)); }\n", o);
  EXPECT_NE(first_error(pragma).find("<stdin>:3:"), std::string::npos) << first_error(pragma);
  EXPECT_EQ(parse_mode("rte-exact"), Mode::RteExact);
  EXPECT_EQ(to_string(Mode::RteExact), "rte-exact");
}

}  // namespace
}  // namespace doublet::runner::test

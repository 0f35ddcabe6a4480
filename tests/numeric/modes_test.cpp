// Precision modes on real drivers (Mesa GLES/llvmpipe and lavapipe), against the host's double:
//   df64       >= 44 bits on add sub mul div sqrt;
//   df64-fast  the bounds of rules/fast.glsl where they hold (add of same-sign, sub of
//              opposite-sign operands: 3u^2; mul 7u^2; div about 17u^2, estimated; sqrt is df64's);
//   fp32       <= 24 bits, and at least 16 bits below df64 on every op;
//   rte        the difference of two hi/lo values is the correctly rounded float of the exact
//              difference.
// Each accuracy check is also run under both sabotages of src/verify/sabotage.hpp (drop-lo: the
// doubles demoted in the source; drop-guard: no optimizer guard) and must then fail.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <string>

#include "doublet/doublet.hpp"
#include "runner/runner.hpp"
#include "verify/sabotage.hpp"

namespace {

using doublet::Mode;
using doublet::runner::Backend;
using doublet::verify::Sabotage;

constexpr int kOps = 5;
const char* kOpNames[kOps] = {"add", "sub", "mul", "div", "sqrt"};
constexpr int kSamples = 4096;
constexpr double kU2Bits = 48.0;  // -log2(u^2)

// ES 3.10 compute; doubles inside only, so every mode can lower it.
const char* kArithmetic = R"(#version 310 es
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Inputs { vec4 operands[]; };   // x_hi, x_lo, y_hi, y_lo
layout(std430, binding = 1) writeonly buffer Outputs { vec2 results[]; };  // hi, lo per op

void store(uint slot, double r) {
  float hi = float(r);
  results[slot] = vec2(hi, float(r - double(hi)));
}

void main() {
  uint i = gl_GlobalInvocationID.x;
  vec4 v = operands[i];
  double x = double(v.x) + double(v.y);
  double y = double(v.z) + double(v.w);
  store(i * 5u + 0u, x + y);
  store(i * 5u + 1u, x - y);
  store(i * 5u + 2u, x * y);
  store(i * 5u + 3u, x / y);
  store(i * 5u + 4u, sqrt(abs(x)));
}
)";

// The rte case: the operands arrive as hi/lo (a block of doubles), the difference leaves as float.
const char* kDifference = R"(#version 310 es
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Inputs { double xy[]; };
layout(std430, binding = 1) writeonly buffer Outputs { float d[]; };
void main() {
  uint i = gl_GlobalInvocationID.x;
  d[i] = float(xy[2u * i] - xy[2u * i + 1u]);
}
)";

struct Pair {
  float hi, lo;
  double value() const { return static_cast<double>(hi) + static_cast<double>(lo); }
};

Pair split(double x) {
  float hi = static_cast<float>(x);
  return {hi, static_cast<float>(x - static_cast<double>(hi))};
}

// Log-uniform magnitudes in [2^-20, 2^20] with random signs; a quarter of the pairs within a
// factor 2 of each other, a quarter cancelling (y ~ -x(1 +- 2^-k)).
std::vector<std::pair<Pair, Pair>> arithmetic_inputs() {
  std::mt19937_64 rng(51122);
  std::uniform_real_distribution<double> exponent(-20.0, 20.0), unit(0.0, 1.0);
  auto sign = [&] { return unit(rng) < 0.5 ? -1.0 : 1.0; };
  std::vector<std::pair<Pair, Pair>> inputs;
  for (int i = 0; i < kSamples; ++i) {
    Pair x = split(std::exp2(exponent(rng)) * sign());
    Pair y;
    if (i % 4 == 3) y = split(-x.value() * (1.0 + sign() * std::exp2(-(1 + (i / 4) % 40))));
    else if (i % 4 == 2) y = split(x.value() * std::exp2(2.0 * unit(rng) - 1.0) * sign());
    else y = split(std::exp2(exponent(rng)) * sign());
    inputs.push_back({x, y});
  }
  return inputs;
}

double bits(double got, double want) {
  if (got == want) return 60.0;
  return std::min(60.0, -std::log2(std::fabs(got - want) / std::max(std::fabs(want), 1e-300)));
}

doublet::Result lower_with(const char* shader, Mode mode, Sabotage sabotage, std::string* error) {
  std::string source = shader;
  doublet::Options options;
  options.stage = doublet::Stage::Compute;
  options.target = doublet::Target::Es310;
  options.file_name = "modes.comp";
  options.mode = mode;
  doublet::verify::apply_sabotage(sabotage, &source, &options);
  doublet::Result r = doublet::lower(source, options);
  for (const auto& d : r.diagnostics) *error += doublet::format_diagnostic(d) + "\n";
  return r;
}

struct Accuracy {
  std::string error;
  double min_bits[kOps];
  // Restricted to where df64-fast's sloppy addition has its 3u^2 bound.
  double same_sign_add_bits = 60, opposite_sign_sub_bits = 60;
  std::string report() const {
    std::string s;
    for (int op = 0; op < kOps; ++op) s += std::string("  ") + kOpNames[op] + ": " + std::to_string(min_bits[op]) + " bits\n";
    s += "  add (same signs): " + std::to_string(same_sign_add_bits) + " bits, sub (opposite signs): " +
         std::to_string(opposite_sign_sub_bits) + " bits\n";
    return s;
  }
};

Accuracy measure(Backend backend, Mode mode, Sabotage sabotage = Sabotage::None) {
  Accuracy m;
  std::fill(std::begin(m.min_bits), std::end(m.min_bits), 60.0);
  doublet::Result lowered = lower_with(kArithmetic, mode, sabotage, &m.error);
  if (!lowered.ok) return m;
  m.error.clear();
  auto inputs = arithmetic_inputs();
  std::vector<float> packed;
  for (const auto& [x, y] : inputs) packed.insert(packed.end(), {x.hi, x.lo, y.hi, y.lo});
  doublet::runner::ComputeJob job;
  job.glsl = lowered.output;
  job.buffers.resize(2);
  job.buffers[0].resize(packed.size() * sizeof(float));
  std::memcpy(job.buffers[0].data(), packed.data(), job.buffers[0].size());
  job.buffers[1].assign(static_cast<size_t>(kSamples) * kOps * 2 * sizeof(float), 0);
  job.groups_x = kSamples / 64;
  auto run = doublet::runner::run_compute(backend, job);
  if (!run.ok) {
    m.error = run.error;
    return m;
  }
  std::vector<float> out(static_cast<size_t>(kSamples) * kOps * 2);
  std::memcpy(out.data(), run.buffers[1].data(), out.size() * sizeof(float));
  for (int i = 0; i < kSamples; ++i) {
    double x = inputs[i].first.value(), y = inputs[i].second.value();
    const double want[kOps] = {x + y, x - y, x * y, x / y, std::sqrt(std::fabs(x))};
    for (int op = 0; op < kOps; ++op) {
      size_t slot = (static_cast<size_t>(i) * kOps + op) * 2;
      double b = bits(static_cast<double>(out[slot]) + static_cast<double>(out[slot + 1]), want[op]);
      m.min_bits[op] = std::min(m.min_bits[op], b);
      if (op == 0 && (x > 0) == (y > 0)) m.same_sign_add_bits = std::min(m.same_sign_add_bits, b);
      if (op == 1 && (x > 0) != (y > 0)) m.opposite_sign_sub_bits = std::min(m.opposite_sign_sub_bits, b);
    }
  }
  return m;
}

// Pairs x, y given as hi + lo: Cesium-like (|x| <= 6.4e6, |x - y| <= 1e5), log-uniform, and
// near-tie pairs. A near-tie pair (scaled by 2^k, either sign) is x = (2^20 + 2^-3) + (2^-5 +
// 2^-27), y = 2^20 - 2^-j: x - y = T + 2^-j with T = 2^-3 + 2^-5 + 2^-27 halfway between two
// floats, so the float must round up. The exact float-float subtraction keeps the 2^-j; a
// subtraction that rounds the low words separately (what Mesa leaves of an unguarded TwoSum)
// loses it and lands on the tie, which rounds to even: down.
struct DifferenceInput {
  Pair x, y;
};

std::vector<DifferenceInput> difference_inputs() {
  std::mt19937_64 rng(8128);
  std::uniform_real_distribution<double> unit(-1.0, 1.0), exponent(-20.0, 20.0);
  std::uniform_int_distribution<int> scale(-20, 20), tail(30, 44);
  std::vector<DifferenceInput> inputs;
  for (int i = 0; i < kSamples; ++i) {
    Pair x, y;
    if (i % 4 == 0 || i % 4 == 1) {
      x = split(6.4e6 * unit(rng));
      y = split(x.value() + 1e5 * unit(rng) * std::exp2(-20.0 * std::fabs(unit(rng))));
    } else if (i % 4 == 2) {
      x = split(std::exp2(exponent(rng)) * (unit(rng) < 0 ? -1 : 1));
      y = split(std::exp2(exponent(rng)) * (unit(rng) < 0 ? -1 : 1));
    } else {
      float k = std::ldexp(1.0f, scale(rng)) * (unit(rng) < 0 ? -1.0f : 1.0f);
      x = {k * (std::ldexp(1.0f, 20) + std::ldexp(1.0f, -3)), k * (std::ldexp(1.0f, -5) + std::ldexp(1.0f, -27))};
      y = {k * std::ldexp(1.0f, 20), -k * std::ldexp(1.0f, -tail(rng))};
    }
    inputs.push_back({x, y});
  }
  return inputs;
}

struct Exactness {
  std::string error;
  int checked = 0;     // samples whose difference is exact in long double
  int mismatches = 0;
  std::string first_mismatch;
};

Exactness measure_difference(Backend backend, Mode mode, Sabotage sabotage = Sabotage::None) {
  Exactness m;
  doublet::Result lowered = lower_with(kDifference, mode, sabotage, &m.error);
  if (!lowered.ok) return m;
  m.error.clear();
  auto inputs = difference_inputs();
  std::vector<float> packed;  // df_double {hi, lo} per element, std430: 8 bytes each
  for (const auto& in : inputs) packed.insert(packed.end(), {in.x.hi, in.x.lo, in.y.hi, in.y.lo});
  doublet::runner::ComputeJob job;
  job.glsl = lowered.output;
  job.buffers.resize(2);
  job.buffers[0].resize(packed.size() * sizeof(float));
  std::memcpy(job.buffers[0].data(), packed.data(), job.buffers[0].size());
  job.buffers[1].assign(static_cast<size_t>(kSamples) * sizeof(float), 0);
  job.groups_x = kSamples / 64;
  auto run = doublet::runner::run_compute(backend, job);
  if (!run.ok) {
    m.error = run.error + "\n" + lowered.output;
    return m;
  }
  std::vector<float> out(kSamples);
  std::memcpy(out.data(), run.buffers[1].data(), out.size() * sizeof(float));
  for (int i = 0; i < kSamples; ++i) {
    // The reference in long double (64-bit significand on x86): x, y and x - y are checked to be
    // exact there, so float(x - y) is the correctly rounded float of the exact difference.
    using Wide = long double;
    const Pair& px = inputs[i].x;
    const Pair& py = inputs[i].y;
    Wide x = Wide(px.hi) + Wide(px.lo), y = Wide(py.hi) + Wide(py.lo);
    if (x - Wide(px.hi) != Wide(px.lo) || y - Wide(py.hi) != Wide(py.lo)) continue;
    Wide s = x - y, yy = s - x, xx = s - yy, e = (x - xx) + (-y - yy);
    if (e != 0) continue;
    ++m.checked;
    float want = static_cast<float>(s);
    if (std::memcmp(&out[i], &want, sizeof want) != 0) {
      if (m.mismatches++ == 0) {
        char buf[200];
        std::snprintf(buf, sizeof buf, "x=%a+%a y=%a+%a got=%a want=%a", double(px.hi), double(px.lo), double(py.hi),
                      double(py.lo), static_cast<double>(out[i]), static_cast<double>(want));
        m.first_mismatch = buf;
      }
    }
  }
  return m;
}

class ModeAccuracy : public ::testing::TestWithParam<Backend> {
 protected:
  void SetUp() override { ASSERT_EQ(doublet::runner::backend_unavailable_reason(GetParam()), ""); }
};

TEST_P(ModeAccuracy, Df64KeepsAtLeast44BitsAndFailsUnderSabotage) {
  Accuracy m = measure(GetParam(), Mode::Df64);
  ASSERT_EQ(m.error, "");
  std::printf("%s df64:\n%s", doublet::runner::backend_name(GetParam()), m.report().c_str());
  for (int op = 0; op < kOps; ++op) EXPECT_GE(m.min_bits[op], 44.0) << kOpNames[op] << "\n" << m.report();
  for (Sabotage s : {Sabotage::DropLo, Sabotage::DropGuard}) {
    Accuracy broken = measure(GetParam(), Mode::Df64, s);
    ASSERT_EQ(broken.error, "");
    double worst = *std::min_element(std::begin(broken.min_bits), std::end(broken.min_bits));
    std::printf("  sabotage %s: worst op %.1f bits\n", std::string(doublet::verify::to_string(s)).c_str(), worst);
    EXPECT_LT(worst, 44.0) << "the 44-bit check cannot fail under " << doublet::verify::to_string(s);
  }
}

TEST_P(ModeAccuracy, Df64FastMeetsItsDocumentedBoundsAndFailsUnderSabotage) {
  // -log2 of the bounds in rules/fast.glsl, less half a bit for float division and sqrt,
  // which GLSL does not require to be correctly rounded.
  const double add_sub = kU2Bits - std::log2(3.0) - 0.5;  // 3u^2 where it holds
  const double mul = kU2Bits - std::log2(7.0) - 0.5;      // 7u^2
  const double div = kU2Bits - std::log2(17.0) - 0.5;     // about 17u^2 (estimate)
  const double sqrt_bits = 44.0;                          // df_sqrt, as df64
  auto check = [&](const Accuracy& m) {
    return m.same_sign_add_bits >= add_sub && m.opposite_sign_sub_bits >= add_sub && m.min_bits[2] >= mul &&
           m.min_bits[3] >= div && m.min_bits[4] >= sqrt_bits;
  };
  Accuracy m = measure(GetParam(), Mode::Df64Fast);
  ASSERT_EQ(m.error, "");
  std::printf("%s df64-fast:\n%s", doublet::runner::backend_name(GetParam()), m.report().c_str());
  EXPECT_GE(m.same_sign_add_bits, add_sub) << m.report();
  EXPECT_GE(m.opposite_sign_sub_bits, add_sub) << m.report();
  EXPECT_GE(m.min_bits[2], mul) << m.report();
  EXPECT_GE(m.min_bits[3], div) << m.report();
  EXPECT_GE(m.min_bits[4], sqrt_bits) << m.report();
  for (Sabotage s : {Sabotage::DropLo, Sabotage::DropGuard}) {
    Accuracy broken = measure(GetParam(), Mode::Df64Fast, s);
    ASSERT_EQ(broken.error, "");
    std::printf("  sabotage %s:\n%s", std::string(doublet::verify::to_string(s)).c_str(), broken.report().c_str());
    EXPECT_FALSE(check(broken)) << "the df64-fast bounds cannot fail under " << doublet::verify::to_string(s);
  }
}

TEST_P(ModeAccuracy, Fp32IsFloatAndClearlyWorseThanDf64) {
  Accuracy fp32 = measure(GetParam(), Mode::Fp32);
  Accuracy df64 = measure(GetParam(), Mode::Df64);
  ASSERT_EQ(fp32.error, "");
  ASSERT_EQ(df64.error, "");
  std::printf("%s fp32:\n%s", doublet::runner::backend_name(GetParam()), fp32.report().c_str());
  for (int op = 0; op < kOps; ++op) {
    EXPECT_LE(fp32.min_bits[op], 24.0) << kOpNames[op] << ": fp32 cannot be more accurate than float";
    EXPECT_GE(df64.min_bits[op] - fp32.min_bits[op], 16.0) << kOpNames[op] << ": fp32 is not visibly worse";
  }
}

TEST_P(ModeAccuracy, RteDifferenceOfSplitValuesIsTheCorrectlyRoundedFloat) {
  Exactness m = measure_difference(GetParam(), Mode::Rte);
  ASSERT_EQ(m.error, "");
  std::printf("%s rte: %d of %d exact differences rounded correctly\n", doublet::runner::backend_name(GetParam()),
              m.checked - m.mismatches, m.checked);
  EXPECT_GE(m.checked, kSamples / 2) << "too few samples with a difference exact in double";
  EXPECT_EQ(m.mismatches, 0) << m.first_mismatch;
  for (Sabotage s : {Sabotage::DropLo, Sabotage::DropGuard}) {
    Exactness broken = measure_difference(GetParam(), Mode::Rte, s);
    ASSERT_EQ(broken.error, "");
    std::printf("  sabotage %s: %d of %d wrong\n", std::string(doublet::verify::to_string(s)).c_str(),
                broken.mismatches, broken.checked);
    EXPECT_GT(broken.mismatches, 0) << "the exactness check cannot fail under " << doublet::verify::to_string(s);
  }
}

INSTANTIATE_TEST_SUITE_P(Drivers, ModeAccuracy, ::testing::Values(Backend::Gles, Backend::Vulkan),
                         [](const ::testing::TestParamInfo<Backend>& info) {
                           return std::string(info.param == Backend::Gles ? "gles" : "vulkan");
                         });

}  // namespace

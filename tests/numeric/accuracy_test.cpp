// Numeric proof on real drivers: a compute shader that computes in double
// internally (float-only interface) is lowered by doublet and run on Mesa GLES
// (llvmpipe) and lavapipe. Every result is compared with the host's double.
//
// The inputs are exact float-float values (hi + lo chosen on the host), so the
// measured error is the arithmetic's, not the 53 → 48-bit input rounding.
// Two sabotages must turn the test red: removing the optimizer guard, and
// dropping `lo` (the same shader with every double demoted to float).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <regex>
#include <string>

#include "doublet/doublet.hpp"
#include "runner/runner.hpp"

namespace {

using doublet::runner::Backend;

constexpr int kOps = 6;
const char* kOpNames[kOps] = {"add", "sub", "mul", "div", "sqrt", "(x+y)-x"};
constexpr int kSamples = 4096;
constexpr double kRequiredBits = 44.0;

// ES 3.10 with doubles inside; the interface is float only.
const char* kShader = R"(#version 310 es
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
  store(i * 6u + 0u, x + y);
  store(i * 6u + 1u, x - y);
  store(i * 6u + 2u, x * y);
  store(i * 6u + 3u, x / y);
  store(i * 6u + 4u, sqrt(abs(x)));
  store(i * 6u + 5u, (x + y) - x);
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

// Log-uniform magnitudes in [2^-20, 2^20] with random signs (half the
// samples); y = ±x·r with r log-uniform in [1/2, 2] (a quarter); and
// cancellation pairs y ≈ -x(1 ± 2^-k), k = 1..40 (a quarter).
std::vector<std::pair<Pair, Pair>> make_inputs(unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> exponent(-20.0, 20.0), unit(0.0, 1.0);
  auto random_double = [&] { return std::exp2(exponent(rng)) * (unit(rng) < 0.5 ? -1.0 : 1.0); };
  std::vector<std::pair<Pair, Pair>> inputs;
  for (int i = 0; i < kSamples; ++i) {
    Pair x = split(random_double());
    Pair y;
    if (i % 4 == 3) {
      int k = 1 + (i / 4) % 40;
      y = split(-x.value() * (1.0 + (unit(rng) < 0.5 ? -1 : 1) * std::exp2(-k)));
    } else if (i % 4 == 2) {
      y = split(x.value() * std::exp2(2.0 * unit(rng) - 1.0) * (unit(rng) < 0.5 ? -1.0 : 1.0));
    } else {
      y = split(random_double());
    }
    inputs.push_back({x, y});
  }
  return inputs;
}

double reference(int op, double x, double y) {
  switch (op) {
    case 0: return x + y;
    case 1: return x - y;
    case 2: return x * y;
    case 3: return x / y;
    case 4: return std::sqrt(std::fabs(x));
    default: {
      // Exact (x + y) - x in long double: both are 48-bit values close in size.
      long double s = static_cast<long double>(x) + static_cast<long double>(y);
      return static_cast<double>(s - static_cast<long double>(x));
    }
  }
}

// Correct bits: -log2 of the relative error (capped at 60 for exact results).
double correct_bits(double got, double want) {
  if (got == want) return 60.0;
  double rel = std::fabs(got - want) / std::max(std::fabs(want), 1e-300);
  return std::min(60.0, -std::log2(rel));
}

struct Measured {
  std::string error;                // non-empty when the shader did not run
  double min_bits[kOps] = {};
  std::string worst[kOps];
};

std::string hexfloat(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%a", v);
  return buf;
}

Measured measure(Backend backend, const std::string& source, doublet::Target target, doublet::GuardKind guard) {
  Measured m;
  doublet::Options options;
  options.stage = doublet::Stage::Compute;
  options.target = target;
  options.guard = guard;
  options.file_name = "accuracy.comp";
  doublet::Result lowered = doublet::lower(source, options);
  if (!lowered.ok) {
    for (const auto& d : lowered.diagnostics) m.error += doublet::format_diagnostic(d) + "\n";
    return m;
  }
  auto inputs = make_inputs(20261122);
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
    m.error = run.error + "\n--- lowered shader ---\n" + lowered.output;
    return m;
  }
  std::vector<float> out(static_cast<size_t>(kSamples) * kOps * 2);
  std::memcpy(out.data(), run.buffers[1].data(), out.size() * sizeof(float));
  for (int op = 0; op < kOps; ++op) m.min_bits[op] = 60.0;
  for (int i = 0; i < kSamples; ++i) {
    double x = inputs[i].first.value(), y = inputs[i].second.value();
    for (int op = 0; op < kOps; ++op) {
      // (x+y)-x is measured where |y| is within a factor 2 of |x|: there any
      // fixed precision keeps its bits, and float keeps none of the cancelled ones.
      // (With |x| = 2^k |y|, double itself would lose k bits.)
      if (op == 5 && i % 4 < 2) continue;
      size_t slot = (static_cast<size_t>(i) * kOps + op) * 2;
      double got = static_cast<double>(out[slot]) + static_cast<double>(out[slot + 1]);
      double bits = correct_bits(got, reference(op, x, y));
      if (bits < m.min_bits[op]) {
        m.min_bits[op] = bits;
        m.worst[op] = "x=" + hexfloat(x) + " y=" + hexfloat(y) + " got=" + hexfloat(got);
      }
    }
  }
  return m;
}

std::string report(const Measured& m) {
  std::string s;
  for (int op = 0; op < kOps; ++op)
    s += std::string("  ") + kOpNames[op] + ": " + std::to_string(m.min_bits[op]) + " bits (worst " + m.worst[op] + ")\n";
  return s;
}

struct Case {
  Backend backend;
  doublet::Target target;
};

class Accuracy : public ::testing::TestWithParam<Case> {};

TEST_P(Accuracy, EveryOperationKeepsAtLeast44Bits) {
  auto [backend, target] = GetParam();
  ASSERT_EQ(doublet::runner::backend_unavailable_reason(backend), "");
  Measured m = measure(backend, kShader, target, doublet::GuardKind::Auto);
  ASSERT_TRUE(m.error.empty()) << m.error;
  std::printf("%s %s, guarded (min correct bits over %d samples):\n%s", doublet::runner::backend_name(backend),
              std::string(doublet::to_string(target)).c_str(), kSamples, report(m).c_str());
  for (int op = 0; op < kOps; ++op) EXPECT_GE(m.min_bits[op], kRequiredBits) << kOpNames[op] << "\n" << report(m);
}

TEST_P(Accuracy, WithoutTheGuardTheDriverDeletesTheErrorTerms) {
  auto [backend, target] = GetParam();
  Measured m = measure(backend, kShader, target, doublet::GuardKind::None);
  ASSERT_TRUE(m.error.empty()) << m.error;
  std::printf("%s %s, guard removed:\n%s", doublet::runner::backend_name(backend),
              std::string(doublet::to_string(target)).c_str(), report(m).c_str());
  double worst = 60.0;
  for (int op = 0; op < kOps; ++op) worst = std::min(worst, m.min_bits[op]);
  EXPECT_LT(worst, kRequiredBits) << "sabotage (no guard) did not turn the test red:\n" << report(m);
}

TEST_P(Accuracy, DroppingLoTurnsTheTestRed) {
  auto [backend, target] = GetParam();
  // The same shader with every double demoted to float: what users have without doublet.
  std::string demoted = std::regex_replace(kShader, std::regex(R"(\bdouble\b)"), "float");
  Measured m = measure(backend, demoted, target, doublet::GuardKind::Auto);
  ASSERT_TRUE(m.error.empty()) << m.error;
  for (int op = 0; op < kOps; ++op) EXPECT_LT(m.min_bits[op], 30.0) << kOpNames[op] << "\n" << report(m);
}

INSTANTIATE_TEST_SUITE_P(Drivers, Accuracy,
                         ::testing::Values(Case{Backend::Gles, doublet::Target::Es310},
                                           Case{Backend::Gles, doublet::Target::Es320},
                                           Case{Backend::Vulkan, doublet::Target::Es310},
                                           Case{Backend::Vulkan, doublet::Target::Es320}),
                         [](const auto& info) {
                           return std::string(doublet::runner::backend_name(info.param.backend)) + "_" +
                                  std::string(doublet::to_string(info.param.target));
                         });

}  // namespace

// Float-float operations whose operands are all compile-time constants once the driver has inlined
// the calls (`product(2.53lf, 0.13lf)`), under the uniform guard (es310 without gpu_shader5): the
// driver folds and reassociates the rule's steps and the low word is lost, unless every constant
// reads the guard (pass guard-constants; docs/accuracy.md, "Constants the driver folds"). These
// tests run doublet's es310 output on lavapipe and Mesa GLES, and the same lowering with the pass
// skipped: the control, which must lose bits on both drivers.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "doublet/doublet.hpp"
#include "runner/runner.hpp"

namespace {

using doublet::runner::Backend;

const char* kShader = R"(#version 450
layout(local_size_x = 1) in;
layout(std430, binding = 0) writeonly buffer Out { double r[]; };
double g = -2.5315213579651239lf;
double product(double a, double b) { return a * b; }
double sum(double a, double b) { return a + b; }
dvec2 transform(dmat2 m, dvec2 v) { return m * v; }
void main() {
  r[0] = product(-2.5315213579651239lf, -0.13377862020845477lf);
  r[1] = product(g, 0.7123456789012345lf);
  r[2] = sum(1.0000000123456789lf, 3.4567890123456789e-9lf);
  dvec2 t = transform(dmat2(1.1lf, 2.2lf, 3.3lf, 4.4lf), dvec2(0.1lf, 0.3lf));
  r[3] = t.x;
  r[4] = t.y;
}
)";

// What the shader computes, in host doubles (each operation correctly rounded: the reference).
std::vector<double> expected() {
  const double g = -2.5315213579651239;
  return {-2.5315213579651239 * -0.13377862020845477, g * 0.7123456789012345, 1.0000000123456789 + 3.4567890123456789e-9,
          1.1 * 0.1 + 3.3 * 0.3, 2.2 * 0.1 + 4.4 * 0.3};
}

std::string lowered_es310(bool guard_constants) {
  doublet::Options options;
  options.stage = doublet::Stage::Compute;
  options.target = doublet::Target::Es310;
  if (!guard_constants) options.skip_passes = {"guard-constants"};
  auto result = doublet::lower(kShader, options);
  EXPECT_TRUE(result.ok);
  return result.output;
}

// The fewest bits of relative accuracy over the five results.
double worst_bits(Backend backend, const std::string& glsl) {
  const std::vector<double> want = expected();
  doublet::runner::ComputeJob job;
  job.glsl = glsl;
  job.buffers.emplace_back(8 * want.size(), 0);
  auto result = doublet::runner::run_compute(backend, job);
  EXPECT_TRUE(result.ok) << result.error;
  if (!result.ok) return 0;
  double bits = 60;
  for (size_t i = 0; i < want.size(); ++i) {
    float words[2];
    std::memcpy(words, result.buffers[0].data() + 8 * i, 8);
    const double got = static_cast<double>(words[0]) + words[1];
    const double error = std::fabs(got - want[i]) / std::fabs(want[i]);
    if (error > 0) bits = std::min(bits, -std::log2(error));
  }
  return bits;
}

TEST(GuardConstants, ConstantsReadTheGuardInTheText) {
  const std::string text = lowered_es310(true);
  EXPECT_NE(text.find("df_double(-2.5315213 - df_guard[int(df_guard[1])]"), std::string::npos) << text;
  // The global's constant initialiser moved into main, where it can read the guard.
  EXPECT_EQ(text.find("df_double g = "), std::string::npos) << text;
  EXPECT_NE(text.find("  g = df_double("), std::string::npos) << text;
}

// The worst bits on lavapipe and on Mesa GLES, printed (the figures of docs/accuracy.md).
std::vector<double> bits_on_both_drivers(const std::string& text) {
  std::vector<double> bits;
  for (Backend backend : {Backend::Vulkan, Backend::Gles}) {
    bits.push_back(worst_bits(backend, text));
    std::printf("  %s: %.2f bits\n", doublet::runner::backend_name(backend), bits.back());
  }
  return bits;
}

TEST(GuardConstants, FoldableOperationsKeepFloatFloatOnBothDrivers) {
  for (double bits : bits_on_both_drivers(lowered_es310(true))) EXPECT_GE(bits, 46.0);
}

// The control: without the pass both drivers fold the constants' low words away (if this ever
// passes, Mesa stopped folding through the guard's neighbours and the pass may be reconsidered).
TEST(GuardConstants, WithoutThePassBothDriversLoseTheLowWord) {
  for (double bits : bits_on_both_drivers(lowered_es310(false))) EXPECT_LT(bits, 44.0);
}

}  // namespace

// Where the uniform guard is declared matters on lavapipe: when a shader branches on a uniform,
// lavapipe specialises it on that uniform's value, and a scalar guard declared before every other
// uniform (offset 0 of the uniform block the loose uniforms are gathered into) then reads as a
// constant, so every guarded step folds and the results are float(x). doublet therefore prints the
// shader's loose uniforms before the runtime's guard (emit::PrintOptions::guard_uniform), and, from
// ES 3.00 on, reads the guard at a non-constant index (`df_guard[int(df_guard[1])]`), which no
// uniform inliner replaces (docs/accuracy.md, "The guard's place" and "A uniform inliner cannot
// reach an indexed guard"). These tests run doublet's output, the same text with the guard moved
// first, and that text with the guard turned back into a scalar: only the last loses the low words.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "doublet/doublet.hpp"
#include "runner/runner.hpp"

namespace {

using doublet::runner::Backend;

const char* kShader = R"(#version 450
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer In { double x[]; };
layout(std430, binding = 1) writeonly buffer Out { double y[]; };
uniform uint n;
uniform double dt;
void main() {
  uint i = gl_GlobalInvocationID.x;
  double a = 0.0lf;
  if (n == 7u) return;  // a branch on a uniform: lavapipe specialises the shader on n
  for (uint j = 0u; j < 3u; ++j) a += x[j] * 1e-12lf;
  y[i] = x[i] + a * dt;
}
)";

constexpr int kCount = 64;

std::string lowered_es310() {
  doublet::Options options;
  options.stage = doublet::Stage::Compute;
  options.target = doublet::Target::Es310;
  auto result = doublet::lower(kShader, options);
  EXPECT_TRUE(result.ok);
  return result.output;
}

const std::string kIndexedGuardLine = "uniform highp float df_guard[2];";

// The same text with the guard's declaration moved in front of the shader's own uniforms.
std::string with_guard_first(const std::string& text, const std::string& guard_line = kIndexedGuardLine) {
  size_t guard = text.find(guard_line);
  size_t first_uniform = text.find("\nuniform ");
  if (guard == std::string::npos || first_uniform == std::string::npos || first_uniform + 1 >= guard) return "";
  size_t guard_end = text.find('\n', guard) + 1;
  std::string line = text.substr(guard, guard_end - guard);
  std::string moved = text;
  moved.erase(guard, guard_end - guard);
  moved.insert(first_uniform + 1, line);
  return moved;
}

// The text with the guard read as the scalar of ES 1.00 and WGSL: `float df_guard;`, `- df_guard)`.
std::string with_scalar_guard(std::string text) {
  const std::pair<std::string, std::string> edits[] = {{"df_guard[int(df_guard[1])]", "df_guard"}, {"df_guard[2]", "df_guard"}};
  for (const auto& [from, to] : edits)
    for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) text.replace(at, from.size(), to);
  return text;
}

// Bits of the worst relative error of y = x + (sum of x[0..2] * 1e-12) * dt against host doubles.
double run_bits(Backend backend, const std::string& glsl) {
  std::vector<float> in(2 * kCount);
  std::vector<double> x(kCount);
  for (int i = 0; i < kCount; ++i) {
    double v = 1.0 + i * 0.1373737373737;  // low words that float cannot hold
    float hi = static_cast<float>(v);
    in[2 * i] = hi;
    in[2 * i + 1] = static_cast<float>(v - hi);
    x[i] = static_cast<double>(in[2 * i]) + in[2 * i + 1];
  }
  doublet::runner::ComputeJob job;
  job.glsl = glsl;
  job.buffers.emplace_back(reinterpret_cast<const uint8_t*>(in.data()), reinterpret_cast<const uint8_t*>(in.data() + in.size()));
  job.buffers.emplace_back(8 * kCount, 0);
  const double dt = 0.75;
  job.uniforms["n"] = {3};
  job.uniforms["dt_hi"] = {dt};
  job.uniforms["dt_lo"] = {0};
  auto result = doublet::runner::run_compute(backend, job);
  EXPECT_TRUE(result.ok) << result.error;
  if (!result.ok) return 0;
  double a = 0;
  for (int j = 0; j < 3; ++j) a += x[j] * 1e-12;
  double worst = 0;
  for (int i = 0; i < kCount; ++i) {
    float out[2];
    std::memcpy(out, result.buffers[1].data() + 8 * i, 8);
    double want = x[i] + a * dt, got = static_cast<double>(out[0]) + out[1];
    worst = std::fmax(worst, std::fabs(got - want) / std::fabs(want));
  }
  return worst == 0 ? 60 : -std::log2(worst);
}

TEST(GuardPlace, LooseUniformsPrecedeTheGuard) {
  std::string text = lowered_es310();
  size_t guard = text.find(kIndexedGuardLine);
  ASSERT_NE(guard, std::string::npos) << text;
  EXPECT_LT(text.find("uniform uint n;"), guard);
  EXPECT_LT(text.find("uniform float dt_hi;"), guard);
}

TEST(GuardPlace, DoubletsOrderKeepsFloatFloatOnBothDrivers) {
  std::string text = lowered_es310();
  for (Backend backend : {Backend::Vulkan, Backend::Gles})
    EXPECT_GE(run_bits(backend, text), 44.0) << doublet::runner::backend_name(backend);
}

// The indexed guard holds even in the place that breaks a scalar one: lavapipe inlines only loads at
// a constant offset.
TEST(GuardPlace, IndexedGuardDeclaredFirstKeepsFloatFloatOnBothDrivers) {
  std::string moved = with_guard_first(lowered_es310());
  ASSERT_FALSE(moved.empty());
  for (Backend backend : {Backend::Vulkan, Backend::Gles})
    EXPECT_GE(run_bits(backend, moved), 44.0) << doublet::runner::backend_name(backend);
}

// The sabotage: a scalar guard declared first. On lavapipe the specialised shader loses the low
// words; if this ever passes, Mesa changed and the hoisting may no longer be needed where the guard
// is a scalar (ES 1.00, WGSL; docs/accuracy.md).
TEST(GuardPlace, ScalarGuardDeclaredFirstLosesTheLowWordsOnLavapipe) {
  const std::string scalar = with_scalar_guard(lowered_es310());
  ASSERT_NE(scalar.find("uniform highp float df_guard;"), std::string::npos);
  ASSERT_EQ(scalar.find("df_guard["), std::string::npos);
  std::string moved = with_guard_first(scalar, "uniform highp float df_guard;");
  ASSERT_FALSE(moved.empty());
  EXPECT_LT(run_bits(Backend::Vulkan, moved), 30.0);
  EXPECT_GE(run_bits(Backend::Gles, moved), 44.0);  // Mesa's GL driver does not specialise this way
}

}  // namespace

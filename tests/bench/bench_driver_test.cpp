// A tiny bench on both backends: it completes, reports positive finite numbers, and its ratios are
// quotients of medians of the same run. No timing thresholds (shared, noisy machines).
#include <gtest/gtest.h>

#include <cmath>

#include "bench/bench.hpp"
#include "bench/kernels.hpp"

namespace {
using namespace doublet::bench;
using doublet::runner::Backend;

BenchReport tiny_run(std::vector<std::string> ops) {
  BenchOptions o;
  o.ops = std::move(ops);
  o.elements = 256;
  o.steps = 16;
  o.warmup = 1;
  o.repetitions = 3;
  BenchReport report;
  std::string error;
  EXPECT_TRUE(run_bench(o, &report, &error)) << error;
  return report;
}

const Measurement* row(const BenchReport& r, const std::string& op, Backend b, Mode m) {
  for (const Measurement& x : r.rows)
    if (x.op == op && x.backend == b && x.mode == m) return &x;
  return nullptr;
}

TEST(BenchDriver, TinyRunOnBothBackendsReportsPositiveFiniteNumbers) {
  const BenchReport r = tiny_run({"add", "mat4"});
  ASSERT_EQ(r.rows.size(), 2u * 2u * 3u);
  for (const Measurement& m : r.rows) {
    SCOPED_TRACE(m.op + " " + mode_name(m.mode) + " " + backend_key(m.backend) + ": " + m.note);
    if (m.backend == Backend::Gles && m.mode == Mode::Native) {
      EXPECT_FALSE(m.ok);  // GLES has no fp64: reported, not run
      EXPECT_TRUE(m.not_applicable);
      continue;
    }
    ASSERT_TRUE(m.ok);
    ASSERT_EQ(m.seconds.size(), 3u);
    for (double s : m.seconds) EXPECT_TRUE(std::isfinite(s) && s >= 0);
    EXPECT_TRUE(std::isfinite(m.median_seconds) && m.median_seconds > 0);
    EXPECT_TRUE(std::isfinite(m.ops_per_second) && m.ops_per_second > 0);
    EXPECT_TRUE(m.finite_output);
    EXPECT_GT(m.size.spirv_instructions, 0u);
    EXPECT_GT(m.size.glsl_lines, 0u);
    ASSERT_TRUE(m.time_vs_fp32 && m.time_vs_native);
    EXPECT_TRUE(std::isfinite(*m.time_vs_fp32) && *m.time_vs_fp32 > 0);
    EXPECT_TRUE(std::isfinite(*m.time_vs_native) && *m.time_vs_native > 0);
  }
  EXPECT_EQ(r.clocks.at("vulkan"), "vkCmdWriteTimestamp");
  EXPECT_FALSE(r.clocks.at("gles").empty());
  EXPECT_EQ(r.devices.count("vulkan") + r.devices.count("gles"), 2u);
}

TEST(BenchDriver, RatiosAreQuotientsOfTheSameRun) {
  const BenchReport r = tiny_run({"mul"});
  const Measurement* native = row(r, "mul", Backend::Vulkan, Mode::Native);
  ASSERT_TRUE(native && native->ok) << (native ? native->note : "missing");
  for (Backend b : {Backend::Vulkan, Backend::Gles}) {
    const Measurement* fp32 = row(r, "mul", b, Mode::Fp32);
    const Measurement* df64 = row(r, "mul", b, Mode::Df64);
    ASSERT_TRUE(fp32 && fp32->ok && df64 && df64->ok);
    EXPECT_DOUBLE_EQ(*df64->time_vs_fp32, df64->median_seconds / fp32->median_seconds);
    EXPECT_DOUBLE_EQ(*df64->time_vs_native, df64->median_seconds / native->median_seconds);
    EXPECT_DOUBLE_EQ(*fp32->time_vs_fp32, 1.0);
    EXPECT_DOUBLE_EQ(df64->ops_per_second, 256.0 * 16.0 / df64->median_seconds);
  }
}

TEST(BenchDriver, UserShaderAsAWhole) {
  BenchOptions o;
  o.shader_path = "globe.comp";
  o.shader_source =
      "#version 450\n"
      "layout(local_size_x = 32) in;\n"
      "layout(std430, binding = 0) buffer B { vec4 pos[]; };\n"
      "void main() {\n"
      "  uint i = gl_GlobalInvocationID.x;\n"
      "  dvec3 p = dvec3(pos[i].xyz) * 6.4e6;\n"
      "  dvec3 eye = dvec3(6.4e6, 1.0, 2.0);\n"
      "  pos[i] = vec4(vec3(p - eye), float(length(p)));\n"
      "}\n";
  o.elements = 128;
  o.repetitions = 3;
  o.backends = {Backend::Vulkan};
  BenchReport r;
  std::string error;
  ASSERT_TRUE(run_bench(o, &r, &error)) << error;
  ASSERT_EQ(r.rows.size(), 3u);
  for (const Measurement& m : r.rows) {
    EXPECT_TRUE(m.ok) << mode_name(m.mode) << ": " << m.note;
    EXPECT_GT(m.ops_per_second, 0);
  }
}

}  // namespace

// Shader variants per mode, without a driver.
#include <gtest/gtest.h>

#include <regex>

#include "bench/kernels.hpp"
#include "bench/variants.hpp"

namespace {
using namespace doublet::bench;

// A double type named in code (comments removed): what a float-only shader must not contain.
bool names_double_type(const std::string& glsl) {
  const std::string code = std::regex_replace(glsl, std::regex("//[^\n]*"), "");
  return std::regex_search(code, std::regex("(^|[^_A-Za-z0-9])(double|dvec[234]|dmat[234](x[234])?)\\b"));
}

TEST(BenchVariants, EveryKernelLowersAndDemotesWithoutDoubles) {
  for (const Kernel& k : kernels()) {
    const std::string src = kernel_source(k, 16);
    const Variant df = make_variant(Mode::Df64, doublet::runner::Backend::Gles, src, doublet::Target::Es320, k.op);
    ASSERT_FALSE(df.glsl.empty()) << k.op << ": " << df.note;
    EXPECT_FALSE(names_double_type(df.glsl)) << k.op;
    const Variant f = make_variant(Mode::Fp32, doublet::runner::Backend::Gles, src, doublet::Target::Es320, k.op);
    EXPECT_FALSE(names_double_type(f.glsl)) << k.op;
    EXPECT_TRUE(names_double_type(src)) << k.op;
    EXPECT_EQ(f.glsl.rfind("#version 320 es", 0), 0u) << k.op;
    EXPECT_GT(shader_size(df.glsl).spirv_instructions, shader_size(f.glsl).spirv_instructions) << k.op;
  }
}

TEST(BenchVariants, NativeIsVulkanOnly) {
  const std::string src = kernel_source(*find_kernel("add"), 8);
  EXPECT_TRUE(make_variant(Mode::Native, doublet::runner::Backend::Gles, src, doublet::Target::Es320, "add").glsl.empty());
  EXPECT_EQ(make_variant(Mode::Native, doublet::runner::Backend::Vulkan, src, doublet::Target::Es320, "add").glsl, src);
}

// --modes exact: every kernel lowers: the scalar, geometric and matrix kernels to the integer
// runtime, the transcendentals to its float-float bridges.
TEST(BenchVariants, ExactLowersEveryKernel) {
  EXPECT_EQ(parse_mode("exact"), Mode::Exact);
  EXPECT_STREQ(mode_name(Mode::Exact), "exact");
  for (const Kernel& k : kernels()) {
    const Variant v = make_variant(Mode::Exact, doublet::runner::Backend::Gles, kernel_source(k, 16),
                                   doublet::Target::Es320, k.op);
    ASSERT_FALSE(v.glsl.empty()) << k.op << ": " << v.note;
    EXPECT_FALSE(names_double_type(v.glsl)) << k.op;
    const bool scalar = k.op == "add" || k.op == "sub" || k.op == "mul" || k.op == "div" || k.op == "sqrt";
    const std::string rule = k.op == "mat4" ? "mul_dmat4_dvec4" : k.op.back() == '3' ? k.op.substr(0, k.op.size() - 1) : k.op;
    EXPECT_NE(v.glsl.find("ex_" + rule + (scalar ? "_bits(" : "(")), std::string::npos) << k.op;
  }
}

}  // namespace

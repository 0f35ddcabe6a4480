// Batches (one compile, many dispatches) and vector/double loose uniforms: what `doublet verify`
// relies on to feed many input sets to one shader.
#include "test_util.hpp"

namespace doublet::runner::test {
namespace {

class BatchTest : public ::testing::TestWithParam<Backend> {};

TEST_P(BatchTest, EachJobSeesItsOwnVectorUniformAndBuffers) {
  REQUIRE_BACKEND(GetParam());
  std::vector<ComputeJob> jobs(3);
  for (int i = 0; i < 3; ++i) {
    jobs[i].glsl = R"(#version 310 es
layout(local_size_x = 1) in;
uniform vec3 v;
uniform float s;
layout(std430, binding = 0) buffer Io { vec4 x; };
void main() { x = vec4(v * s, x.w + 1.0); }
)";
    jobs[i].uniforms["v"] = {1.0 + i, 2.0 + i, 3.0 + i};
    jobs[i].uniforms["s"] = {0.5};
    jobs[i].buffers = {to_bytes(std::vector<float>{0, 0, 0, float(10 * i)})};
  }
  const std::vector<ComputeResult> results = run_compute_batch(GetParam(), jobs);
  ASSERT_EQ(results.size(), 3u);
  for (int i = 0; i < 3; ++i) {
    ASSERT_TRUE(results[i].ok) << results[i].error;
    const std::vector<float> x = from_bytes<float>(results[i].buffers[0]);
    EXPECT_EQ(x, (std::vector<float>{0.5f * (1 + i), 0.5f * (2 + i), 0.5f * (3 + i), 10.0f * i + 1}));
  }
}

TEST_P(BatchTest, WrongComponentCountIsAnError) {
  REQUIRE_BACKEND(GetParam());
  ComputeJob job;
  job.glsl = "#version 310 es\nlayout(local_size_x = 1) in;\nuniform vec2 v;\n"
             "layout(std430, binding = 0) buffer Io { vec2 x; };\nvoid main() { x = v; }\n";
  job.uniforms["v"] = {1.0};
  job.buffers = {std::vector<uint8_t>(8)};
  const ComputeResult r = run_compute(GetParam(), job);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.error.find("component"), std::string::npos) << r.error;
}

// A struct uniform whose members follow a nested struct: std140 rounds the nested struct to 16
// bytes, so `n` lies at 16, not 8 (glslang's reflection says 8; the runner takes the SPIR-V's
// offsets). Every value must arrive where the shader reads it.
TEST_P(BatchTest, MembersAfterANestedStructArriveWhereTheShaderReadsThem) {
  REQUIRE_BACKEND(GetParam());
  ComputeJob job;
  job.glsl = R"(#version 310 es
layout(local_size_x = 1) in;
struct Pair { float hi; float lo; };
struct Params { Pair scale; int n; Pair bias; float last; };
uniform Params p;
uniform float after;
layout(std430, binding = 0) buffer Io { vec4 x; vec4 y; };
void main() {
  x = vec4(p.scale.hi, p.scale.lo, float(p.n), p.last);
  y = vec4(p.bias.hi, p.bias.lo, after, 0.0);
}
)";
  job.uniforms = {{"p.scale.hi", {1.5}}, {"p.scale.lo", {2.5}}, {"p.n", {7}},      {"p.bias.hi", {3.5}},
                  {"p.bias.lo", {4.5}},  {"p.last", {5.5}},     {"after", {6.5}}};
  job.buffers = {std::vector<uint8_t>(32)};
  RUN_OK(r, GetParam(), job);
  EXPECT_EQ(from_bytes<float>(r.buffers[0]), (std::vector<float>{1.5f, 2.5f, 7.0f, 5.5f, 3.5f, 4.5f, 6.5f, 0.0f}));
}

INSTANTIATE_TEST_SUITE_P(Backends, BatchTest, ::testing::Values(Backend::Vulkan, Backend::Gles), backend_param_name);

TEST(VulkanDoubleUniform, DvecUniformKeepsAllBits) {
  REQUIRE_BACKEND(Backend::Vulkan);
  ComputeJob job;
  job.glsl = "#version 450\nlayout(local_size_x = 1) in;\nuniform dvec2 d;\nuniform double e;\n"
             "layout(std430, binding = 0) buffer Io { dvec3 x; };\nvoid main() { x = dvec3(d, e); }\n";
  const double third = 1.0 / 3.0;
  job.uniforms["d"] = {third, -third * 1e-20};
  job.uniforms["e"] = {0.1};
  job.buffers = {std::vector<uint8_t>(32)};
  RUN_OK(r, Backend::Vulkan, job);
  const std::vector<double> x = from_bytes<double>(r.buffers[0]);
  EXPECT_EQ(x[0], third);
  EXPECT_EQ(x[1], -third * 1e-20);
  EXPECT_EQ(x[2], 0.1);
}

}  // namespace
}  // namespace doublet::runner::test

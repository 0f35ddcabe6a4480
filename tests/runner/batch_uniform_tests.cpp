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

// Plumbing: buffers, uniforms, errors, devices, threads — on both backends.
#include <cmath>
#include <random>
#include <thread>

#include "test_util.hpp"

namespace doublet::runner::test {
namespace {

class RunnerTest : public ::testing::TestWithParam<Backend> {};

TEST_P(RunnerTest, DeviceIsMesaSoftware) {
  REQUIRE_BACKEND(GetParam());
  ComputeJob job;
  job.glsl = "#version 310 es\nlayout(local_size_x = 1) in;\nvoid main() {}\n";
  RUN_OK(r, GetParam(), job);
  std::cout << "[ device ] " << backend_name(GetParam()) << ": " << r.device << "\n";
  RecordProperty("device", r.device);
  EXPECT_NE(r.device.find("llvmpipe"), std::string::npos) << r.device;
}

TEST_P(RunnerTest, SquaresFloatsBitExact) {
  REQUIRE_BACKEND(GetParam());
  std::mt19937 rng(1);
  std::uniform_real_distribution<float> exponent(-30.0f, 30.0f);
  std::vector<float> x(4096);
  for (size_t i = 0; i < x.size(); ++i) x[i] = std::ldexp(1.0f + (rng() % 1000000) / 1e6f, int(exponent(rng))) * (i % 2 ? -1 : 1);
  ComputeJob job;
  job.glsl = R"(#version 310 es
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer In { float x[]; };
layout(std430, binding = 1) writeonly buffer Out { float y[]; };
void main() { uint i = gl_GlobalInvocationID.x; y[i] = x[i] * x[i]; }
)";
  job.buffers = {to_bytes(x), std::vector<uint8_t>(x.size() * 4)};
  job.groups_x = static_cast<uint32_t>(x.size() / 64);
  RUN_OK(r, GetParam(), job);
  EXPECT_EQ(r.buffers[0], job.buffers[0]) << "read-only input changed";
  std::vector<float> y = from_bytes<float>(r.buffers[1]);
  int mismatches = 0;
  for (size_t i = 0; i < x.size(); ++i) {
    const float want = x[i] * x[i];
    if (bits<uint32_t>(y[i]) != bits<uint32_t>(want) && ++mismatches <= 5)
      ADD_FAILURE() << "x=" << std::hexfloat << x[i] << " got " << y[i] << " want " << want;
  }
  EXPECT_EQ(mismatches, 0);
}

TEST_P(RunnerTest, UniformValuesReachTheShader) {
  REQUIRE_BACKEND(GetParam());
  ComputeJob job;
  // Three uniforms so that a wrong offset in the Vulkan global block cannot pass by luck;
  // `unset` stays 0 because nobody sets it.
  job.glsl = R"(#version 310 es
layout(local_size_x = 4) in;
layout(std430, binding = 0) buffer Io { float v[]; };
uniform float bias;
uniform float k;
uniform float unset;
void main() { uint i = gl_GlobalInvocationID.x; v[i] = v[i] * k + bias + unset * 1000.0; }
)";
  job.buffers = {to_bytes(std::vector<float>{1, 2, 3, 4})};
  job.float_uniforms = {{"k", 3.0f}, {"bias", 0.5f}, {"not_in_shader", 7.0f}};
  RUN_OK(r, GetParam(), job);
  EXPECT_EQ(from_bytes<float>(r.buffers[0]), (std::vector<float>{3.5f, 6.5f, 9.5f, 12.5f}));
}

TEST_P(RunnerTest, NonFloatUniformIsAnError) {
  REQUIRE_BACKEND(GetParam());
  ComputeJob job;
  job.glsl = R"(#version 310 es
layout(local_size_x = 1) in;
layout(std430, binding = 0) buffer Io { int v[]; };
uniform int n;
void main() { v[0] = n; }
)";
  job.buffers = {std::vector<uint8_t>(4)};
  job.float_uniforms = {{"n", 1.0f}};
  ComputeResult r = run_compute(GetParam(), job);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.error.find("'n' is not a float"), std::string::npos) << r.error;
}

TEST_P(RunnerTest, InvalidShaderReportsCompilerLog) {
  REQUIRE_BACKEND(GetParam());
  ComputeJob job;
  job.glsl = R"(#version 310 es
layout(local_size_x = 1) in;
layout(std430, binding = 0) buffer Io { float v[]; };
void main() { v[0] = no_such_variable * 2.0; }
)";
  job.buffers = {std::vector<uint8_t>(4)};
  ComputeResult r = run_compute(GetParam(), job);
  EXPECT_FALSE(r.ok);
  EXPECT_TRUE(r.buffers.empty());
  EXPECT_NE(r.error.find("compile failed"), std::string::npos) << r.error;
  EXPECT_NE(r.error.find("no_such_variable"), std::string::npos) << r.error;
  std::cout << "[ log ] " << r.error << "\n";
}

TEST_P(RunnerTest, MissingBufferIsAnError) {
  REQUIRE_BACKEND(GetParam());
  ComputeJob job;
  job.glsl = R"(#version 310 es
layout(local_size_x = 1) in;
layout(std430, binding = 0) buffer A { float a[]; };
layout(std430, binding = 1) buffer B { float b[]; };
void main() { b[0] = a[0]; }
)";
  job.buffers = {std::vector<uint8_t>(4)};
  ComputeResult r = run_compute(GetParam(), job);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.error.find("binding 1"), std::string::npos) << r.error;
}

TEST_P(RunnerTest, ConcurrentJobsFromManyThreads) {
  REQUIRE_BACKEND(GetParam());
  std::vector<std::string> errors(4);
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([&, t] {
      ComputeJob job;
      job.glsl = "#version 310 es\nlayout(local_size_x = 8) in;\n"
                 "layout(std430, binding = 0) buffer Io { float v[]; };\nuniform float k;\n"
                 "void main() { v[gl_GlobalInvocationID.x] += k; }\n";
      job.buffers = {to_bytes(std::vector<float>(8, float(t)))};
      job.float_uniforms = {{"k", 10.0f}};
      for (int rep = 0; rep < 5 && errors[t].empty(); ++rep) {
        ComputeResult r = run_compute(GetParam(), job);
        if (!r.ok) errors[t] = r.error;
        else if (from_bytes<float>(r.buffers[0]) != std::vector<float>(8, t + 10.0f)) errors[t] = "wrong values";
      }
    });
  for (auto& th : threads) th.join();
  for (int t = 0; t < 4; ++t) EXPECT_EQ(errors[t], "") << "thread " << t;
}

INSTANTIATE_TEST_SUITE_P(Backends, RunnerTest, ::testing::Values(Backend::Vulkan, Backend::Gles), backend_param_name);

// Vulkan only: a module that fails SPIRV-Tools validation never reaches the driver.
TEST(VulkanSpirv, InvalidModuleIsReportedAsInvalidSpirv) {
  REQUIRE_BACKEND(Backend::Vulkan);
  std::vector<uint32_t> words;
  std::string error;
  ASSERT_TRUE(compile_compute_to_spirv("#version 310 es\nlayout(local_size_x = 1) in;\nvoid main() {}\n", &words, &error))
      << error;
  ComputeJob job;
  ComputeResult good = run_spirv_compute(words, job);
  EXPECT_TRUE(good.ok) << good.error;
  words[3] = 1;  // ID bound 1: every id in the module is now out of bounds
  ComputeResult bad = run_spirv_compute(words, job);
  EXPECT_FALSE(bad.ok);
  EXPECT_EQ(bad.error.rfind("invalid SPIR-V: ", 0), 0u) << bad.error;
  std::cout << "[ log ] " << bad.error << "\n";
}

}  // namespace
}  // namespace doublet::runner::test

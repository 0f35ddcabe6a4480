// The emitted-flop counter of `doublet bench` (src/bench/opcount.hpp): callees count along their
// cheapest path, and a callee with a loop makes the count unknown (-1, printed "—") instead of
// counting its body zero times (df64-int's matrix products as loops printed 0 flops per step).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "bench/opcount.hpp"
#include "runner/runner.hpp"

namespace {

std::vector<uint32_t> spirv(const std::string& glsl) {
  std::vector<uint32_t> words;
  std::string error;
  EXPECT_TRUE(doublet::runner::compile_compute_to_spirv(glsl, &words, &error)) << error;
  return words;
}

const char* kHead = R"(#version 450
layout(local_size_x = 1) in;
layout(std430, binding = 0) buffer B { float x[]; };
)";

TEST(OpCount, CalleesCountAlongTheirPath) {
  const std::string glsl = std::string(kHead) + R"(
float twice_plus(float a, float b) { return a * b + a * b; }
void main() { x[0] = twice_plus(x[1], x[2]) - x[3]; }
)";
  // Two products and a sum in the callee, one subtraction in main.
  EXPECT_EQ(doublet::bench::count_main_float_ops(spirv(glsl)), 4.0);
}

TEST(OpCount, ACalleeWithALoopIsUnknownNotZero) {
  const std::string glsl = std::string(kHead) + R"(
float dot4(float a) { float s = 0.0; for (int k = 0; k < 4; ++k) s = s + a * x[k]; return s; }
void main() { x[0] = dot4(x[1]) - x[3]; }
)";
  EXPECT_EQ(doublet::bench::count_main_float_ops(spirv(glsl)), -1.0);
}

TEST(OpCount, LoopsInMainCountTheirBodyOnce) {
  // The kernels' own loop: its body (the steps written out) is what float_ops_per_step differences.
  const std::string glsl = std::string(kHead) + R"(
void main() { float s = x[1]; for (int k = 0; k < 64; ++k) s = s * x[2] + x[3]; x[0] = s; }
)";
  EXPECT_EQ(doublet::bench::count_main_float_ops(spirv(glsl)), 2.0);
}

}  // namespace

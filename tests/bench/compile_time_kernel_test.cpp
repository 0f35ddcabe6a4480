// The loop series of `doublet bench --compile-time` (src/bench/compile_time.cpp): its loop bound must
// not be a uniform. Lavapipe (Mesa 22.3) inlines the uniforms an `if` or a loop bound reads,
// unrolls, and can recompile at every submit, so a uniform bound times a different, unrolled shader
// (docs/performance.md, "The first dispatch holds the compile").
#include <gtest/gtest.h>

#include <string>

#include "bench/compile_time.hpp"

namespace {

TEST(CompileTimeKernel, TheLoopBoundComesFromABufferNotAUniform) {
  for (int ops : {1, 8, 64}) {
    const std::string kernel = doublet::bench::compile_time_kernel(ops);
    EXPECT_EQ(kernel.find("\nuniform "), std::string::npos) << kernel;  // no uniform declared
    EXPECT_NE(kernel.find("readonly buffer Bound { float steps; }"), std::string::npos) << kernel;
    EXPECT_NE(kernel.find("k < int(steps)"), std::string::npos) << kernel;
  }
}

}  // namespace

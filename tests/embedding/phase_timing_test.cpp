// Result::phase_seconds: every phase of a lowering that ran, in pipeline order, each timed.
#include <gtest/gtest.h>

#include <chrono>
#include <string>
#include <vector>

#include "doublet/doublet.hpp"

namespace {

const char* const kShader = R"(#version 450
layout(local_size_x = 1) in;
layout(std430, binding = 0) buffer B { double x; double y; };
void main() { y = sqrt(x * x + 1.0lf); }
)";

doublet::Options compute_options() {
  doublet::Options o;
  o.stage = doublet::Stage::Compute;
  o.target = doublet::Target::Es310;
  return o;
}

TEST(PhaseTiming, EveryPhaseInPipelineOrderWithinTheWholeTime) {
  const auto t0 = std::chrono::steady_clock::now();
  const doublet::Result r = doublet::lower(kShader, compute_options());
  const double whole = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ASSERT_TRUE(r.ok);
  std::vector<std::string> names;
  double sum = 0;
  for (const auto& [name, seconds] : r.phase_seconds) {
    names.push_back(name);
    EXPECT_GE(seconds, 0) << name;
    sum += seconds;
  }
  EXPECT_EQ(names, (std::vector<std::string>{"parse", "import", "lints", "modes", "lower", "optimize", "interfaces",
                                             "print", "validate"}));
  EXPECT_GT(sum, 0);
  EXPECT_LE(sum, whole);  // the phases are disjoint parts of the call
}

TEST(PhaseTiming, AFailedLoweringReportsOnlyThePhasesThatFinished) {
  const doublet::Result r = doublet::lower("#version 450\nvoid main() { undeclared = 1.0; }\n", compute_options());
  ASSERT_FALSE(r.ok);
  EXPECT_TRUE(r.phase_seconds.empty());  // the parse failed: no phase finished
}

}  // namespace

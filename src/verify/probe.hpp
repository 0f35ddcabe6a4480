// The driver probe printed at the top of every report (NUMERICS.md): does an unprotected TwoSum
// keep its error term, is fma fused, are fp32 denormals flushed — measured in the stage verified.
#pragma once

#include <string>

#include "runner/runner.hpp"

namespace doublet::verify {

struct Probe {
  std::string stage = "comp";     // comp, vert or frag
  bool two_sum_survives = false;   // unprotected TwoSum error term kept for every test pair
  bool fma_fused = false;          // fma(a, b, -RN(a*b)) returns the exact product error
  bool denormals_flushed = false;  // FLT_MIN * 0.5 reads back as 0
  std::string error;               // non-empty: the probe did not run
};

Probe probe_compute(runner::Backend);
Probe probe_stage(runner::Backend, runner::GraphicsStage);  // the same probe in a vertex/fragment stage
std::string describe(const Probe&);  // one line for the report

}  // namespace doublet::verify

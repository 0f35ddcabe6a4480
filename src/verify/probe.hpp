// The driver probe printed at the top of every report (docs/numerics.md#measured-driver-facts):
// does an unprotected TwoSum keep its error term, is fma fused, are fp32 denormals flushed —
// measured in the stage verified.
#pragma once

#include <string>

#include "runner/runner.hpp"

namespace doublet::verify {

struct Probe {
  std::string stage = "comp";     // comp, vert or frag
  bool two_sum_survives = false;   // unprotected TwoSum error term kept for every test pair
  bool fma_fused = false;          // fma(a, b, -RN(a*b)) returns the exact product error
  bool has_fma = true;             // false on WebGL2: GLSL ES 3.00 has no fma (fma_fused is then false)
  bool denormals_flushed = false;  // FLT_MIN * 0.5 reads back as 0
  std::string error;               // non-empty: the probe did not run
};

Probe probe_compute(runner::Backend);
Probe probe_stage(runner::Backend, runner::GraphicsStage);  // the same probe in a vertex/fragment stage
// probe_stage in two halves, for a backend that runs it together with other batches (WebGL2: in
// the page that runs the lowered shader): the job, and the verdict on its result.
runner::GraphicsJob stage_probe_job(runner::Backend, runner::GraphicsStage);
Probe judge_stage_probe(runner::Backend, runner::GraphicsStage, const runner::GraphicsResult&);
std::string describe(const Probe&);  // one line for the report

}  // namespace doublet::verify

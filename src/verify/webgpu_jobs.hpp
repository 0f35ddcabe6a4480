// `doublet verify --backend webgpu`: the compute harness's lowered jobs (planned on the GLSL
// lowering the WGSL is printed from: same names, same buffers) run as the WGSL lowering in headless
// Chromium's WebGPU (runner::run_webgpu_compute, one page per dispatch).
#pragma once

#include <string>
#include <vector>

#include "doublet/doublet.hpp"
#include "runner/runner.hpp"

namespace doublet::verify {

// One result per job, as run_compute_batch gives them (buffers in job order, device = the adapter);
// on the first failure it stops and the last result carries the error.
std::vector<runner::ComputeResult> run_jobs_on_webgpu(const std::string& wgsl, const Manifest& wgsl_manifest,
                                                      const std::vector<runner::ComputeJob>& jobs);

}  // namespace doublet::verify

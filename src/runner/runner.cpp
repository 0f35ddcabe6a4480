#include "runner/runner.hpp"

#include "runner/browser.hpp"
#include "runner/internal.hpp"

namespace doublet::runner {

const char* backend_name(Backend b) {
  switch (b) {
    case Backend::Vulkan: return "Vulkan";
    case Backend::Gles: return "GLES";
    case Backend::WebGl2: return "WebGL2";
    case Backend::WebGpu: return "WebGPU";
  }
  return "?";
}

ComputeResult run_compute(Backend backend, const ComputeJob& job) {
  return run_compute_batch(backend, {job}).back();
}

std::vector<ComputeResult> run_compute_batch(Backend backend, const std::vector<ComputeJob>& jobs) {
  if (jobs.empty()) {
    ComputeResult result;
    result.error = "run_compute_batch: no jobs";
    return {result};
  }
  if (backend == Backend::Gles) return detail::gles_run(jobs);
  if (backend == Backend::WebGl2 || backend == Backend::WebGpu) {
    ComputeResult result;
    result.error = backend == Backend::WebGl2 ? "WebGL2 has no compute shaders"
                                              : "WebGPU runs WGSL: use run_webgpu_compute (runner/webgpu.hpp)";
    return {result};
  }
  detail::SpirvProgram program;
  std::string error;
  if (!detail::compile_glsl(jobs[0].glsl, &program, &error, nullptr, jobs[0].strict_fp64)) {
    ComputeResult result;
    result.error = std::move(error);
    return {result};
  }
  return detail::vulkan_run(program, jobs);
}

ComputeResult run_spirv_compute(const std::vector<uint32_t>& spirv, const ComputeJob& job) {
  ComputeResult result;
  if (!job.float_uniforms.empty()) {
    result.error = "run_spirv_compute cannot set float_uniforms (no reflection for raw SPIR-V)";
    return result;
  }
  if (std::string v = validate_spirv(spirv); !v.empty()) {
    result.error = "invalid SPIR-V: " + v;
    return result;
  }
  detail::SpirvProgram program;
  program.words = spirv;
  // Without reflection the SSBO bindings are unknown; the layout still offers bindings 0..n-1.
  return detail::vulkan_run(program, {job}).back();
}

std::string backend_unavailable_reason(Backend backend) {
  if (backend == Backend::WebGl2 || backend == Backend::WebGpu) return browser_unavailable_reason();
  return backend == Backend::Gles ? detail::gles_unavailable_reason() : detail::vulkan_unavailable_reason();
}

}  // namespace doublet::runner

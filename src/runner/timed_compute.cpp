#include "runner/timed_compute.hpp"

#include <chrono>

#include "runner/internal.hpp"

namespace doublet::runner {
namespace detail {
TimedResult vulkan_run_timed(const SpirvProgram& program, const ComputeJob& job, int warmup, int repetitions,
                             std::chrono::steady_clock::time_point start);
TimedResult gles_run_timed(const ComputeJob& job, int warmup, int repetitions);
}  // namespace detail

TimedResult run_compute_timed(Backend backend, const ComputeJob& job, int warmup, int repetitions) {
  if (repetitions < 1 || warmup < 0) {
    TimedResult r;
    r.error = "run_compute_timed: need repetitions >= 1 and warmup >= 0";
    return r;
  }
  if (backend == Backend::Gles) return detail::gles_run_timed(job, warmup, repetitions);
  const auto start = std::chrono::steady_clock::now();  // first_result_seconds counts the SPIR-V compile
  detail::SpirvProgram program;
  TimedResult r;
  if (!detail::compile_glsl(job.glsl, &program, &r.error)) return r;
  return detail::vulkan_run_timed(program, job, warmup, repetitions, start);
}

}  // namespace doublet::runner

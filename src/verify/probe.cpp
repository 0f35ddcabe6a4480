#include "verify/probe.hpp"

#include <cmath>
#include <cstring>
#include <vector>

namespace doublet::verify {
namespace {

// Inputs come from a buffer so the compiler cannot fold them. Every invocation writes
// (two_sum e, fma error, denormal) for its pair; the host checks against IEEE float arithmetic.
constexpr const char* kProbeShader = R"(#version 320 es
layout(local_size_x = 16) in;
layout(std430, binding = 0) readonly buffer In { vec4 abd[]; };
layout(std430, binding = 1) writeonly buffer Out { vec4 r[]; };
void main() {
  uint i = gl_GlobalInvocationID.x;
  float a = abd[i].x, b = abd[i].y, d = abd[i].z;
  float s = a + b;
  float bb = s - a;
  float e = (a - (s - bb)) + (b - bb);
  precise float p = a * b;
  precise float f = fma(a, b, -p);
  r[i] = vec4(s, e, f, d * 0.5);
}
)";
constexpr int kPairs = 64;

// The same arithmetic as a vertex/fragment stage (the runner feeds `abd` per sample, reads `r`).
constexpr const char* kStageProbeShader = R"(#version 320 es
precision highp float;
in vec4 abd;
out vec4 r;
void main() {
  float a = abd.x, b = abd.y, d = abd.z;
  float s = a + b;
  float bb = s - a;
  float e = (a - (s - bb)) + (b - bb);
  precise float p = a * b;
  precise float f = fma(a, b, -p);
  r = vec4(s, e, f, d * 0.5);
}
)";

// WebGL2 (GLSL ES 3.00): no fma and no precise, so the fma column is left at 0 (has_fma false).
constexpr const char* kEs300StageProbeShader = R"(#version 300 es
precision highp float;
in vec4 abd;
out vec4 r;
void main() {
  float a = abd.x, b = abd.y, d = abd.z;
  float s = a + b;
  float bb = s - a;
  float e = (a - (s - bb)) + (b - bb);
  r = vec4(s, e, 0.0, d * 0.5);
}
)";

// Per pair: a = 1 + k·2^-12, b = a shifted (TwoSum and TwoProd errors all non-zero), FLT_MIN.
std::vector<float> probe_inputs() {
  std::vector<float> in(4 * kPairs);
  for (int i = 0; i < kPairs; ++i) {
    const float a = 1.0f + static_cast<float>(i + 1) * 0x1p-12f;
    in[4 * i] = a;
    in[4 * i + 1] = a * 0x1p-20f;
    in[4 * i + 2] = 0x1p-126f;  // FLT_MIN: half of it is a denormal
  }
  return in;
}

// Compares the stage's (s, e, f, d/2) per pair with IEEE float arithmetic on the host.
void judge(const std::vector<float>& in, const std::vector<float>& out, Probe* probe) {
  bool two_sum = true, fused = true, flushed = true;
  for (int i = 0; i < kPairs; ++i) {
    const float a = in[4 * i], b = in[4 * i + 1];
    const float s = a + b, bb = s - a, e = (a - (s - bb)) + (b - bb);
    const double exact_prod_err = static_cast<double>(a) * b - static_cast<double>(a * b);
    two_sum &= out[4 * i + 1] == e;
    fused &= static_cast<double>(out[4 * i + 2]) == exact_prod_err;
    flushed &= out[4 * i + 3] == 0.0f;
  }
  probe->two_sum_survives = two_sum;
  probe->fma_fused = fused;
  probe->denormals_flushed = flushed;
}

}  // namespace

runner::GraphicsJob stage_probe_job(runner::Backend backend, runner::GraphicsStage stage) {
  const std::vector<float> in = probe_inputs();
  runner::GraphicsJob job;
  job.stage = stage;
  job.glsl = backend == runner::Backend::WebGl2 ? kEs300StageProbeShader : kStageProbeShader;
  job.count = kPairs;
  job.inputs["abd"].assign(in.begin(), in.end());
  return job;
}

Probe probe_stage(runner::Backend backend, runner::GraphicsStage stage) {
  return judge_stage_probe(backend, stage, runner::run_graphics(backend, stage_probe_job(backend, stage)));
}

Probe judge_stage_probe(runner::Backend backend, runner::GraphicsStage stage, const runner::GraphicsResult& r) {
  Probe probe;
  probe.stage = stage == runner::GraphicsStage::Vertex ? "vert" : "frag";
  probe.has_fma = backend != runner::Backend::WebGl2;
  const std::vector<float> in = probe_inputs();
  if (!r.ok) {
    probe.error = r.error;
    return probe;
  }
  const std::vector<double>& got = r.outputs.at("r");
  judge(in, std::vector<float>(got.begin(), got.end()), &probe);
  probe.fma_fused &= probe.has_fma;
  return probe;
}

Probe probe_compute(runner::Backend backend) {
  Probe probe;
  const std::vector<float> in = probe_inputs();
  runner::ComputeJob job;
  job.glsl = kProbeShader;
  job.buffers = {std::vector<uint8_t>(in.size() * 4), std::vector<uint8_t>(in.size() * 4)};
  std::memcpy(job.buffers[0].data(), in.data(), job.buffers[0].size());
  job.groups_x = kPairs / 16;
  const runner::ComputeResult r = runner::run_compute(backend, job);
  if (!r.ok) {
    probe.error = r.error;
    return probe;
  }
  std::vector<float> out(4 * kPairs);
  std::memcpy(out.data(), r.buffers[1].data(), r.buffers[1].size());
  judge(in, out, &probe);
  return probe;
}

std::string describe(const Probe& p) {
  if (p.error.rfind("not run", 0) == 0) return p.error;  // a backend without the probe (WebGPU)
  if (!p.error.empty()) return "probe failed: " + p.error;
  return std::string("stage ") + p.stage + ": unprotected TwoSum " +
         (p.two_sum_survives ? "survives" : "DELETED (error term folded to 0)") + "; fma " +
         (!p.has_fma ? "absent (GLSL ES 3.00)" : p.fma_fused ? "fused" : "NOT fused") + "; fp32 denormals " + (p.denormals_flushed ? "FLUSHED" : "kept");
}

}  // namespace doublet::verify

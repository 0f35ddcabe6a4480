// run_graphics / reflect_graphics: wrap the stage (graphics_wrapper.hpp), then hand the program to
// a backend. Also the host side of the wrapper's storage buffers (std430 records per sample).
#include <algorithm>
#include <cmath>
#include <cstring>

#include "runner/graphics_wrapper.hpp"
#include "runner/webgl2.hpp"

namespace doublet::runner {
namespace detail {
namespace {

uint32_t scalar_bytes(const StageVariable& v) { return v.scalar == 'd' ? 8 : 4; }

double load(const uint8_t* at, char scalar) {
  switch (scalar) {
    case 'd': { double d; std::memcpy(&d, at, 8); return d; }
    case 'f': { float f; std::memcpy(&f, at, 4); return f; }
    case 'i': { int32_t i; std::memcpy(&i, at, 4); return i; }
    default: { uint32_t u; std::memcpy(&u, at, 4); return u; }
  }
}

}  // namespace

std::string pack_inputs(const GraphicsInterface& iface, const GraphicsJob& job, std::vector<uint8_t>* bytes) {
  bytes->assign(std::max<size_t>(size_t{job.count} * iface.input_stride, 16), 0);
  for (const auto& [name, values] : job.inputs) {
    const StageVariable* v = nullptr;
    for (const StageVariable& in : iface.inputs)
      if (in.name == name) v = &in;
    if (!v) continue;  // as for uniforms: a name the shader lacks is ignored
    const size_t n = size_t{job.count} * static_cast<size_t>(v->components);
    if (values.size() != n)
      return "input '" + name + "' needs " + std::to_string(n) + " values (count × components), job gives " +
             std::to_string(values.size());
    for (size_t k = 0; k < n; ++k) {
      const size_t sample = k / static_cast<size_t>(v->components), c = k % static_cast<size_t>(v->components);
      store_scalar(bytes->data() + sample * iface.input_stride + v->offset + c * scalar_bytes(*v), v->scalar, values[k]);
    }
  }
  return {};
}

std::vector<uint8_t> blank_outputs(const GraphicsInterface& iface, uint32_t count) {
  return std::vector<uint8_t>(std::max<size_t>(size_t{count} * iface.records_per_sample * iface.output_stride, 16), 0xff);
}

void unpack_outputs(const GraphicsInterface& iface, uint32_t count, const uint8_t* bytes, GraphicsResult* out) {
  for (const StageVariable& v : iface.outputs) {
    std::vector<double>& values = out->outputs[v.name];
    values.resize(size_t{count} * iface.records_per_sample * static_cast<size_t>(v.components));
    for (size_t k = 0; k < values.size(); ++k) {
      const size_t sample = k / static_cast<size_t>(v.components), c = k % static_cast<size_t>(v.components);
      values[k] = load(bytes + sample * iface.output_stride + v.offset + c * scalar_bytes(v), v.scalar);
    }
  }
}

std::vector<std::pair<Stage, std::string>> stages_of(const WrappedProgram& w) {
  std::vector<std::pair<Stage, std::string>> stages = {{Stage::Vertex, w.vertex}, {Stage::Fragment, w.fragment}};
  if (!w.geometry.empty()) stages.emplace_back(Stage::Geometry, w.geometry);
  if (!w.tess_control.empty()) stages.emplace_back(Stage::TessControl, w.tess_control);
  if (!w.tess_evaluation.empty()) stages.emplace_back(Stage::TessEvaluation, w.tess_evaluation);
  return stages;
}

}  // namespace detail

bool reflect_graphics(GraphicsStage stage, const std::string& glsl, GraphicsInterface* out, std::string* error) {
  detail::WrappedProgram wrapped;
  if (std::string e = detail::wrap_graphics(stage, glsl, &wrapped); !e.empty()) {
    *error = e;
    return false;
  }
  detail::SpirvProgram program;
  ShaderInterface iface;
  if (!detail::compile_glsl_stages(detail::stages_of(wrapped), &program, error, &iface))
    return false;
  if (iface.blocks.size() > (wrapped.iface.inputs.empty() ? 1u : 2u)) {
    *error = "the shader declares storage buffers of its own (not fed by vertex/fragment runs yet)";
    return false;
  }
  *out = wrapped.iface;
  out->uniforms = iface.uniforms;
  out->uniform_blocks = iface.uniform_blocks;
  out->samplers = iface.samplers;
  return true;
}

GraphicsResult run_graphics(Backend backend, const GraphicsJob& job) { return run_graphics_batch(backend, {job}).back(); }

std::vector<std::vector<GraphicsResult>> run_graphics_batches(Backend backend,
                                                             const std::vector<std::vector<GraphicsJob>>& batches) {
  if (backend == Backend::WebGl2) return detail::webgl2_run_graphics(batches);
  std::vector<std::vector<GraphicsResult>> results;
  for (const auto& jobs : batches) results.push_back(run_graphics_batch(backend, jobs));
  return results;
}

std::vector<GraphicsResult> run_graphics_batch(Backend backend, const std::vector<GraphicsJob>& jobs) {
  if (backend == Backend::WebGl2) return detail::webgl2_run_graphics({jobs}).front();
  GraphicsResult failed;
  if (backend == Backend::WebGpu) {
    failed.error = "the WebGPU backend runs compute shaders only (WGSL)";
    return {failed};
  }
  if (jobs.empty()) {
    failed.error = "run_graphics_batch: no jobs";
    return {failed};
  }
  if (jobs[0].count == 0 || jobs[0].count > detail::kGridWidth * detail::kGridHeight) {
    failed.error = "a graphics job runs 1 to " + std::to_string(detail::kGridWidth * detail::kGridHeight) + " samples";
    return {failed};
  }
  for (const GraphicsJob& job : jobs)
    if (job.count != jobs[0].count) {
      failed.error = "every job of a graphics batch must have the same count";
      return {failed};
    }
  detail::WrappedProgram wrapped;
  if (std::string e = detail::wrap_graphics(jobs[0].stage, jobs[0].glsl, &wrapped); !e.empty()) {
    failed.error = e;
    return {failed};
  }
  if (backend != Backend::Vulkan && backend != Backend::Gles && (!wrapped.geometry.empty() || !wrapped.tess_control.empty())) {
    failed.error = "geometry and tessellation jobs run on Vulkan and GLES only";
    return {failed};
  }
  if (backend == Backend::Gles) {
    if (!wrapped.es) {
      failed.error = "GLES runs GLSL ES text only (the shader is desktop #version 450)";
      return {failed};
    }
    return detail::gles_run_graphics(wrapped, jobs);
  }
  detail::SpirvProgram program;
  if (!detail::compile_glsl_stages(detail::stages_of(wrapped), &program, &failed.error, nullptr, jobs[0].strict_fp64))
    return {failed};
  return detail::vulkan_run_graphics(wrapped, program, jobs);
}

}  // namespace doublet::runner

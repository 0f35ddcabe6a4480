#include "verify/webgpu_jobs.hpp"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <map>

#include "runner/webgpu.hpp"

namespace doublet::verify {
namespace {

// The storage buffers the WGSL declares, by binding: read-only ones are `var<storage, read>`.
std::map<int, runner::WebGpuBuffer::Kind> storage_bindings(const std::string& wgsl) {
  std::map<int, runner::WebGpuBuffer::Kind> kinds;
  for (size_t at = wgsl.find("@binding("); at != std::string::npos; at = wgsl.find("@binding(", at + 1)) {
    const int binding = std::atoi(wgsl.c_str() + at + 9);
    const size_t eol = wgsl.find('\n', at);
    const std::string line = wgsl.substr(at, eol == std::string::npos ? std::string::npos : eol - at);
    if (line.find("var<storage, read>") != std::string::npos) kinds[binding] = runner::WebGpuBuffer::Kind::ReadOnlyStorage;
    else if (line.find("var<storage") != std::string::npos) kinds[binding] = runner::WebGpuBuffer::Kind::Storage;
  }
  return kinds;
}

// Components of a WGSL scalar/vector/matrix type and its scalar ('f', 'i', 'u'); matrices: column stride.
struct WgslShape {
  char scalar = 'f';
  int columns = 1, rows = 1;
  int column_stride = 0;
};
WgslShape shape_of(const std::string& t) {
  WgslShape s;
  s.scalar = t.find("i32") != std::string::npos ? 'i' : t.find("u32") != std::string::npos ? 'u' : 'f';
  if (t.rfind("vec", 0) == 0) s.rows = t[3] - '0';
  if (t.rfind("mat", 0) == 0) {
    s.columns = t[3] - '0';
    s.rows = t[5] - '0';
    s.column_stride = s.rows == 2 ? 8 : 16;
  }
  return s;
}

void put(std::vector<std::uint8_t>& bytes, size_t offset, char scalar, double value) {
  std::uint32_t word = 0;
  if (scalar == 'f') {
    const float f = static_cast<float>(value);
    std::memcpy(&word, &f, 4);
  } else if (scalar == 'i') {
    word = static_cast<std::uint32_t>(static_cast<std::int32_t>(value));
  } else {
    word = static_cast<std::uint32_t>(value);
  }
  if (offset + 4 <= bytes.size()) std::memcpy(bytes.data() + offset, &word, 4);
}

// The df_uniforms buffer for one job: every loose uniform at its manifest offset, the guard 0.
std::vector<std::uint8_t> uniform_bytes(const InterfaceVariable& block, const runner::ComputeJob& job) {
  size_t size = 16;
  for (const BlockMember& m : block.members) size = std::max(size, static_cast<size_t>(m.offset + m.size));
  std::vector<std::uint8_t> bytes((size + 15) / 16 * 16, 0);
  for (const BlockMember& m : block.members) {
    std::vector<double> values;
    if (auto it = job.uniforms.find(m.name); it != job.uniforms.end()) values = it->second;
    else if (auto f = job.float_uniforms.find(m.name); f != job.float_uniforms.end()) values = {f->second};
    const WgslShape s = shape_of(m.lowered_type);
    for (size_t i = 0; i < values.size() && i < static_cast<size_t>(s.columns * s.rows); ++i) {
      const size_t column = i / static_cast<size_t>(s.rows), row = i % static_cast<size_t>(s.rows);
      put(bytes, static_cast<size_t>(m.offset) + column * static_cast<size_t>(s.column_stride) + row * 4, s.scalar, values[i]);
    }
  }
  return bytes;
}

}  // namespace

std::vector<runner::ComputeResult> run_jobs_on_webgpu(const std::string& wgsl, const Manifest& wgsl_manifest,
                                                      const std::vector<runner::ComputeJob>& jobs) {
  const std::map<int, runner::WebGpuBuffer::Kind> storage = storage_bindings(wgsl);
  const InterfaceVariable* uniforms = nullptr;
  for (const InterfaceVariable& v : wgsl_manifest.variables)
    if (v.layout == "wgsl-uniform") uniforms = &v;
  std::vector<runner::ComputeResult> results;
  for (const runner::ComputeJob& job : jobs) {
    runner::ComputeResult result;
    std::vector<runner::WebGpuBuffer> buffers;
    std::vector<size_t> from_job;  // which job buffer each WebGPU storage buffer is
    for (size_t i = 0; i < job.buffers.size(); ++i) {
      auto kind = storage.find(static_cast<int>(i));
      if (kind == storage.end()) continue;  // a block the lowering removed: nothing to bind
      buffers.push_back({static_cast<int>(i), kind->second, job.buffers[i]});
      from_job.push_back(i);
    }
    if (uniforms) buffers.push_back({uniforms->binding, runner::WebGpuBuffer::Kind::Uniform, uniform_bytes(*uniforms, job)});
    const runner::WebGpuRun run = runner::run_webgpu_compute(
        wgsl, buffers, {static_cast<int>(job.groups_x), static_cast<int>(job.groups_y), static_cast<int>(job.groups_z)});
    result.device = run.adapter.empty() ? "WebGPU" : "WebGPU: " + run.adapter;
    if (!run.ok) {
      result.error = run.unavailable ? "no browser here: " + run.error : run.error;
      results.push_back(std::move(result));
      return results;
    }
    result.ok = true;
    result.buffers = job.buffers;  // a buffer WebGPU did not bind keeps its input bytes
    for (size_t k = 0; k < from_job.size() && k < run.buffers.size(); ++k) result.buffers[from_job[k]] = run.buffers[k];
    results.push_back(std::move(result));
  }
  return results;
}

}  // namespace doublet::verify

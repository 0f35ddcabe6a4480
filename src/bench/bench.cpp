#include "bench/bench.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "bench/kernels.hpp"
#include "bench/opcount.hpp"
#include "runner/timed_compute.hpp"

namespace doublet::bench {

const char* backend_key(runner::Backend b) { return b == runner::Backend::Vulkan ? "vulkan" : "gles"; }

namespace {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

bool all_finite(const std::vector<uint8_t>& bytes) {
  for (size_t i = 0; i + 4 <= bytes.size(); i += 4) {
    float f;
    std::memcpy(&f, bytes.data() + i, 4);
    if (!std::isfinite(f)) return false;
  }
  return true;
}

// What one op (kernel or user shader) needs to run in any mode.
struct Workload {
  std::string name;
  std::string source;  // "#version 450" with doubles
  std::vector<std::vector<uint8_t>> buffers;
  std::map<std::string, std::vector<double>> uniforms;
  std::map<std::string, int> double_uniforms;  // name -> components: exact mode takes them as words
  uint32_t groups = 1;
  double ops_per_dispatch = 0;
  int steps = 1;            // kernels: chain length; shaders: 1 (one invocation is one "op")
  int checked_buffer = -1;  // kernels: the output buffer whose values must stay finite
  std::string source16;     // kernels: the source with 16 steps written out per loop trip (op counts)
  std::string accuracy_source;           // kernels: kUnroll steps storing hi and lo (kernel_accuracy_source)
  std::vector<long double> native_values;  // kernels: that source's results in native fp64 on lavapipe
};

// hi + lo of each element's outp[i].xy.
std::vector<long double> hi_lo_values(const std::vector<uint8_t>& out) {
  std::vector<long double> v(out.size() / 16);
  for (size_t i = 0; i < v.size(); ++i) v[i] = stored_hi_lo(out, i);
  return v;
}

// Mode exact takes a double uniform X as binary64 words, low word first (docs/modes.md, exact's
// interface): double -> uvec2 X, dvec2 -> uvec4 X, dvec3/dvec4 -> X_xy plus X_z/X_zw. The value
// the other modes get (1 per component) is given here as 1.0's words.
void set_exact_uniform_words(const std::string& name, int components,
                             std::map<std::string, std::vector<double>>* uniforms) {
  constexpr double kOneLow = 0, kOneHigh = 0x3FF00000;  // the bit pattern of 1.0
  auto words = [](int n) {
    std::vector<double> v;
    for (int i = 0; i < n; ++i) v.insert(v.end(), {kOneLow, kOneHigh});
    return v;
  };
  uniforms->erase(name + "_hi");
  if (components <= 2) {
    (*uniforms)[name] = words(components);
    return;
  }
  uniforms->erase(name);
  (*uniforms)[name + "_xy"] = words(2);
  (*uniforms)[name + (components == 3 ? "_z" : "_zw")] = words(components - 2);
}

runner::ComputeJob compute_job(const Workload& w, const std::string& glsl, Mode mode = Mode::Df64) {
  runner::ComputeJob job;
  job.glsl = glsl;
  job.buffers = w.buffers;
  job.uniforms = w.uniforms;
  if (mode == Mode::Exact)
    for (const auto& [name, components] : w.double_uniforms) set_exact_uniform_words(name, components, &job.uniforms);
  job.groups_x = w.groups;
  return job;
}

// The accuracy run of one variant against native fp64 (Measurement::bits); -1 when it cannot run.
double measured_bits(const BenchOptions& o, const Workload& w, runner::Backend backend, Mode mode, std::string* error) {
  if (w.native_values.empty()) return -1;
  const Variant v = make_variant(mode, backend, w.accuracy_source, o.target, w.name);
  if (v.glsl.empty()) return -1;
  const runner::ComputeResult r = runner::run_compute(backend, compute_job(w, v.glsl, mode));
  if (!r.ok) {
    *error = "accuracy run: " + r.error;
    return -1;
  }
  const std::vector<long double> got = hi_lo_values(r.buffers[1]);
  WorstRelativeError error_of;
  for (size_t i = 0; i < got.size() && i < w.native_values.size(); ++i) {
    const long double want = w.native_values[i];
    error_of.add(want == 0 ? std::fabs(got[i]) : std::fabs(got[i] - want) / std::fabs(want));
  }
  return std::min(53.0, error_of.bits(53.0));
}

// Native fp64 of the accuracy source on lavapipe: the reference every mode's bits compare with.
void run_native_reference(const BenchOptions& o, Workload* w, std::vector<std::string>* notes) {
  const Variant v = make_variant(Mode::Native, runner::Backend::Vulkan, w->accuracy_source, o.target, w->name);
  if (v.glsl.empty()) return;
  const runner::ComputeResult r = runner::run_compute(runner::Backend::Vulkan, compute_job(*w, v.glsl));
  if (r.ok) w->native_values = hi_lo_values(r.buffers[1]);
  else notes->push_back(w->name + ": no native fp64 reference, bits not measured: " + r.error);
}

// A user shader's buffers (its uniforms below): every reflected block gets its fixed part plus `elements` records of
// its largest runtime array (twice over, as lowered layouts may be larger), filled with floats in
// [1, 2): finite as floats and, read as doubles, finite numbers in [2^-7, 2).
bool shader_workload(const BenchOptions& o, Workload* w, std::string* error) {
  runner::ShaderInterface iface;
  if (!runner::reflect_compute(o.shader_source, &iface, error)) return false;
  size_t count = 0;
  for (const auto& b : iface.blocks) count = std::max<size_t>(count, static_cast<size_t>(std::max(b.binding, 0)) + 1);
  w->buffers.assign(count, {});
  for (size_t bi = 0; bi < iface.blocks.size(); ++bi) {
    const auto& b = iface.blocks[bi];
    uint32_t stride = 0;
    for (const auto& m : iface.members)
      if (m.block == static_cast<int>(bi) && m.array_size == 0) stride = std::max(stride, m.array_stride);
    size_t size = b.fixed_size + 2ull * stride * static_cast<size_t>(o.elements);
    size = (std::max<size_t>(size, 16) + 3) / 4 * 4;
    std::vector<uint8_t>& buf = w->buffers[static_cast<size_t>(std::max(b.binding, 0))];
    buf.resize(size);
    for (size_t i = 0; i < size; i += 4) {
      const float f = 1.0f + static_cast<float>((i / 4 * 2654435761u) % 1000u) / 1000.0f;
      std::memcpy(buf.data() + i, &f, 4);
    }
  }
  // Loose numeric uniforms read 1 in every mode (0 would make divisions NaN): the name itself, and
  // the hi word of the split pair the lowering makes of a double uniform (lo stays 0).
  for (const auto& u : iface.uniforms) {
    if (u.components <= 0) continue;
    const std::vector<double> ones(static_cast<size_t>(u.components), 1.0);
    w->uniforms[u.name] = ones;
    if (u.is_double) {
      w->uniforms[u.name + "_hi"] = ones;
      w->double_uniforms[u.name] = u.components;
    }
  }
  const uint32_t local = std::max<uint32_t>(1, iface.local_size[0] * iface.local_size[1] * iface.local_size[2]);
  w->groups = std::max<uint32_t>(1, (static_cast<uint32_t>(o.elements) + local - 1) / local);
  w->ops_per_dispatch = static_cast<double>(w->groups) * local;
  return true;
}

Measurement measure(const BenchOptions& o, const Workload& w, runner::Backend backend, Mode mode,
                    BenchReport* report) {
  Measurement m;
  m.op = w.name;
  m.steps = w.steps;
  m.backend = backend;
  m.mode = mode;
  const Variant v = make_variant(mode, backend, w.source, o.target, w.name);
  if (v.glsl.empty()) {
    m.note = v.note;
    m.not_applicable = v.not_applicable;
    return m;
  }
  m.size = shader_size(v.glsl);
  if (!w.source16.empty()) {
    const Variant v16 = make_variant(mode, backend, w.source16, o.target, w.name);
    if (!v16.glsl.empty()) m.emitted_flops_per_step = float_ops_per_step(v.glsl, v16.glsl);
  }
  const runner::TimedResult r = runner::run_compute_timed(backend, compute_job(w, v.glsl, mode), o.warmup, o.repetitions);
  if (!r.device.empty()) report->devices[backend_key(backend)] = r.device;
  if (!r.ok) {
    m.note = r.error;
    return m;
  }
  report->clocks[backend_key(backend)] = r.clock;
  m.seconds = r.seconds;
  m.median_seconds = median(r.seconds);
  m.min_seconds = *std::min_element(r.seconds.begin(), r.seconds.end());
  // A timer can read 0 for a dispatch shorter than its resolution; that is not a throughput.
  if (!(m.median_seconds > 0)) {
    m.note = "median time is 0 (dispatch below the timer's resolution): raise --elements or --steps";
    return m;
  }
  m.ops_per_second = w.ops_per_dispatch / m.median_seconds;
  if (w.checked_buffer >= 0) m.finite_output = all_finite(r.buffers[static_cast<size_t>(w.checked_buffer)]);
  std::string accuracy_error;
  m.bits = measured_bits(o, w, backend, mode, &accuracy_error);
  if (!accuracy_error.empty()) m.note = accuracy_error;
  m.ok = true;
  return m;
}

// Ratios between rows of the same run: fp32 and native of the same op (native only exists on
// lavapipe, so GLES rows compare with lavapipe's native; both run on the same CPU via llvmpipe).
void fill_ratios(std::vector<Measurement>& rows) {
  auto find = [&](const std::string& op, runner::Backend b, Mode mode) -> const Measurement* {
    for (const Measurement& r : rows)
      if (r.ok && r.op == op && r.backend == b && r.mode == mode) return &r;
    return nullptr;
  };
  for (Measurement& r : rows) {
    if (!r.ok) continue;
    if (const Measurement* f = find(r.op, r.backend, Mode::Fp32)) r.time_vs_fp32 = r.median_seconds / f->median_seconds;
    if (const Measurement* n = find(r.op, runner::Backend::Vulkan, Mode::Native))
      r.time_vs_native = r.median_seconds / n->median_seconds;
  }
}

}  // namespace

bool run_bench(const BenchOptions& o, BenchReport* report, std::string* error) {
  report->options = o;
  if (o.elements < 1 || o.steps < 0 || o.repetitions < 1 || o.warmup < 0) {
    *error = "--elements and --reps must be at least 1, --steps and --warmup at least 0";
    return false;
  }
  std::vector<Workload> work;
  if (!o.shader_path.empty()) {
    Workload w;
    w.name = o.shader_path.substr(o.shader_path.find_last_of('/') + 1);
    w.source = o.shader_source;
    if (!shader_workload(o, &w, error)) {
      *error = o.shader_path + ": " + *error;
      return false;
    }
    work.push_back(std::move(w));
  } else {
    for (const std::string& op : o.ops) {
      const Kernel* k = find_kernel(op);
      if (!k) {
        *error = "unknown op '" + op + "'";
        return false;
      }
      Workload w;
      w.name = op;
      w.steps = rounded_steps(o.steps > 0 ? o.steps : k->default_steps);
      w.source = kernel_source(*k, w.steps);
      w.buffers = kernel_buffers(*k, o.elements);
      w.groups = static_cast<uint32_t>((o.elements + kLocalSize - 1) / kLocalSize);
      w.ops_per_dispatch = static_cast<double>(w.groups) * kLocalSize * w.steps;
      w.checked_buffer = 1;
      w.source16 = with_doubled_unroll(w.source, kernel_step(*k));
      w.accuracy_source = kernel_accuracy_source(*k);
      run_native_reference(o, &w, &report->notes);
      work.push_back(std::move(w));
    }
  }
  for (const Workload& w : work)
    for (runner::Backend b : o.backends)
      for (Mode mode : o.modes) report->rows.push_back(measure(o, w, b, mode, report));
  fill_ratios(report->rows);
  for (const Measurement& r : report->rows)
    if (!r.ok && !r.note.empty())
      report->notes.push_back(r.op + " " + mode_name(r.mode) + " on " + backend_key(r.backend) + ": " + r.note);
  return true;
}

}  // namespace doublet::bench

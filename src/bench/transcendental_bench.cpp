#include "bench/transcendental_bench.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "bench/bench.hpp"
#include "bench/kernels.hpp"
#include "bench/luma_peer.hpp"
#include "runner/timed_compute.hpp"

namespace doublet::bench {
namespace {

using V = TranscendentalVariant;

struct Program {
  std::string glsl;  // empty: cannot run (note)
  std::string note;
  bool not_applicable = false;
  std::map<std::string, float> uniforms;
};

// What `variant` runs on `backend`, built from the variant's source (transcendental_kernels.hpp).
Program program(const std::string& source, V variant, runner::Backend backend, Target target, GuardKind guard) {
  Program p;
  if (variant == V::Native) {
    if (backend == runner::Backend::Gles) p.note = "GLES has no fp64", p.not_applicable = true;
    else p.glsl = source;
    return p;
  }
  if (variant == V::Luma) {
    const LumaLibrary& lib = luma_fp64_library();
    if (!lib.ok) p.note = "luma.gl: " + lib.error;
    else p.glsl = source, p.uniforms = lib.uniforms;
    return p;
  }
  if (backend == runner::Backend::Gles && !target_is_es(target)) {
    p.note = "desktop target " + std::string(to_string(target)) + " does not run on GLES";
    p.not_applicable = true;
    return p;
  }
  Options o;
  o.stage = Stage::Compute;
  o.target = target;
  o.guard = guard;
  o.mode = variant == V::Fp32 ? doublet::Mode::Fp32 : doublet::Mode::Df64;
  o.file_name = "transcendental.comp";
  Result r = lower(source, o);
  if (r.ok) {
    p.glsl = std::move(r.output);
  } else {
    p.note = "doublet::lower failed:";
    for (const Diagnostic& d : r.diagnostics) p.note += " " + format_diagnostic(d) + ";";
  }
  return p;
}

const std::string& luma_glsl(V variant) {
  static const std::string none;
  return variant == V::Luma && luma_fp64_library().ok ? luma_fp64_library().glsl : none;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

std::vector<uint8_t> chain_inputs(int elements) {
  std::vector<float> in(static_cast<size_t>(elements) * 4);
  uint32_t state = 12345;
  for (float& v : in) {  // xorshift, values in [0.5, 1)
    state ^= state << 13, state ^= state >> 17, state ^= state << 5;
    v = 0.5f + static_cast<float>(state >> 8) * (0.5f / 16777216.0f);
  }
  std::vector<uint8_t> bytes(in.size() * sizeof(float));
  std::memcpy(bytes.data(), in.data(), bytes.size());
  return bytes;
}

void time_row(const TranscendentalOptions& o, TranscendentalRow* row, TranscendentalReport* report) {
  const int steps = rounded_steps(o.steps);
  const Program p = program(chain_source(row->function, row->variant, steps, luma_glsl(row->variant)), row->variant,
                            row->backend, o.target, GuardKind::Auto);
  if (p.glsl.empty()) {
    row->note = p.note;
    row->not_applicable = p.not_applicable;
    return;
  }
  runner::ComputeJob job;
  job.glsl = p.glsl;
  job.float_uniforms = p.uniforms;
  job.buffers = {chain_inputs(o.elements), std::vector<uint8_t>(static_cast<size_t>(o.elements) * 16)};
  job.groups_x = static_cast<uint32_t>((o.elements + kLocalSize - 1) / kLocalSize);
  const runner::TimedResult r = runner::run_compute_timed(row->backend, job, o.warmup, o.repetitions);
  if (!r.device.empty()) report->devices[backend_key(row->backend)] = r.device;
  if (!r.ok) {
    row->note = r.error;
    return;
  }
  report->clocks[backend_key(row->backend)] = r.clock;
  row->seconds = r.seconds;
  row->median_seconds = median(r.seconds);
  if (!(row->median_seconds > 0)) {
    row->note = "median time is 0 (below the timer's resolution): raise --elements or --steps";
    return;
  }
  const double calls = static_cast<double>(job.groups_x) * kLocalSize * steps;
  row->ns_per_call = row->median_seconds * 1e9 / calls;
  row->ns_per_call_min = *std::min_element(r.seconds.begin(), r.seconds.end()) * 1e9 / calls;
  for (size_t i = 0; i + 4 <= r.buffers[1].size(); i += 4) {
    float f;
    std::memcpy(&f, r.buffers[1].data() + i, 4);
    if (!std::isfinite(f)) row->finite_output = false;
  }
  row->ok = true;
}

}  // namespace

AccuracyRun transcendental_accuracy(const std::string& function, V variant, runner::Backend backend, Target target,
                                    Domain domain, int samples, GuardKind guard) {
  AccuracyRun run;
  const Program p = program(accuracy_source(function, variant, luma_glsl(variant)), variant, backend, target, guard);
  if (p.glsl.empty()) {
    run.error = p.note;
    run.not_applicable = p.not_applicable;
    return run;
  }
  samples = std::max(kLocalSize, (samples + kLocalSize - 1) / kLocalSize * kLocalSize);
  const std::vector<float> in = accuracy_inputs(function, domain, samples);
  runner::ComputeJob job;
  job.glsl = p.glsl;
  job.float_uniforms = p.uniforms;
  job.buffers.assign(2, std::vector<uint8_t>(static_cast<size_t>(samples) * 16, 0));
  for (int i = 0; i < samples; ++i) std::memcpy(job.buffers[0].data() + 16 * i, &in[2 * static_cast<size_t>(i)], 8);
  job.groups_x = static_cast<uint32_t>(samples / kLocalSize);
  const runner::ComputeResult r = runner::run_compute(backend, job);
  if (!r.ok) {
    run.error = r.error;
    return run;
  }
  double worst_bits = 99;
  for (int i = 0; i < samples; ++i) {
    const float hi = in[2 * static_cast<size_t>(i)], lo = in[2 * static_cast<size_t>(i) + 1];
    // fp32 sees the float nearest the input; the others the exact float-float (or binary64) value.
    const long double x = variant == V::Fp32 ? static_cast<long double>(hi + lo)
                                             : static_cast<long double>(hi) + static_cast<long double>(lo);
    const uint8_t* out = r.buffers[1].data() + 16 * static_cast<size_t>(i);
    long double got;
    if (variant == V::Native) {
      double d;
      std::memcpy(&d, out, 8);
      got = d;
    } else {
      float w[2];
      std::memcpy(w, out, 8);
      got = static_cast<long double>(w[0]) + static_cast<long double>(w[1]);
    }
    const long double want = reference(function, x);
    const long double error = std::fabs(got - want) / std::fabs(want);
    const double bits = error == 0 ? 64 : std::isnan(static_cast<double>(error)) ? -1 : -std::log2(static_cast<double>(error));
    if (bits < worst_bits) {
      worst_bits = bits;
      char buf[200];
      std::snprintf(buf, sizeof buf, "x = %.17Lg: got %.17Lg, want %.17Lg", x, got, want);
      run.worst = buf;
    }
  }
  run.min_bits = std::min(worst_bits, 64.0);
  run.ok = true;
  return run;
}

bool run_transcendental_bench(const TranscendentalOptions& o, TranscendentalReport* report, std::string* error) {
  report->options = o;
  if (o.elements < 1 || o.steps < 1 || o.repetitions < 1 || o.warmup < 0 || o.accuracy_samples < 1) {
    *error = "--elements, --steps and --reps must be at least 1, --warmup at least 0";
    return false;
  }
  for (const std::string& f : o.functions)
    if (std::find(transcendental_functions().begin(), transcendental_functions().end(), f) ==
        transcendental_functions().end()) {
      *error = "unknown function '" + f + "' for --transcendentals (exp,log,sin,cos,tan)";
      return false;
    }
  std::vector<V> variants{V::Fp32, V::Df64, V::Native};
  if (o.peer_luma) {
    variants.push_back(V::Luma);
    const LumaLibrary& lib = luma_fp64_library();
    if (lib.ok) report->luma_version = lib.version;
    else report->notes.push_back("luma.gl not run: " + lib.error);
  }
  for (const std::string& f : o.functions)
    for (runner::Backend b : o.backends)
      for (V v : variants) {
        TranscendentalRow row;
        row.function = f, row.backend = b, row.variant = v;
        time_row(o, &row, report);
        if (row.ok) {
          const AccuracyRun main = transcendental_accuracy(f, v, b, o.target, Domain::Main, o.accuracy_samples);
          if (main.ok) row.bits = main.min_bits, row.worst = main.worst;
          else row.note = "accuracy run: " + main.error;
          if (is_trig(f)) {
            const AccuracyRun wide = transcendental_accuracy(f, v, b, o.target, Domain::Wide, o.accuracy_samples);
            if (wide.ok) row.bits_wide = wide.min_bits;
          }
        }
        report->rows.push_back(std::move(row));
      }
  auto find = [&](const std::string& f, runner::Backend b, V v) -> const TranscendentalRow* {
    for (const TranscendentalRow& r : report->rows)
      if (r.ok && r.function == f && r.backend == b && r.variant == v) return &r;
    return nullptr;
  };
  for (TranscendentalRow& r : report->rows) {
    if (!r.ok) continue;
    if (const auto* x = find(r.function, r.backend, V::Fp32)) r.vs_fp32 = r.median_seconds / x->median_seconds;
    if (const auto* x = find(r.function, runner::Backend::Vulkan, V::Native)) r.vs_native = r.median_seconds / x->median_seconds;
    if (const auto* x = find(r.function, r.backend, V::Luma)) r.vs_luma = r.median_seconds / x->median_seconds;
  }
  for (const TranscendentalRow& r : report->rows)
    if (!r.not_applicable && !r.note.empty() && !(r.variant == V::Luma && !report->luma_version.size()))
      report->notes.push_back(r.function + " " + variant_name(r.variant) + " on " + backend_key(r.backend) + ": " + r.note);
  return true;
}

namespace {
std::string fixed(double v, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}
std::string ratio(const std::optional<double>& r) { return r ? fixed(*r, 2) + "×" : "—"; }
std::string bits(double b) { return b < 0 ? "—" : fixed(b, 2); }
}  // namespace

std::string format_transcendental_markdown(const TranscendentalReport& report) {
  const TranscendentalOptions& o = report.options;
  std::string s = "`" + report.command + "`\n\n";
  for (runner::Backend b : o.backends) {
    const std::string key = backend_key(b);
    const auto dev = report.devices.find(key);
    const auto clock = report.clocks.find(key);
    s += "- " + key + ": " + (dev != report.devices.end() ? dev->second : "not run") + ", clock " +
         (clock != report.clocks.end() ? clock->second : "none") + "\n";
  }
  if (!report.luma_version.empty()) s += "- luma.gl: @luma.gl/shadertools " + report.luma_version + " (npm)\n";
  s += "- time: " + std::to_string(rounded_steps(o.steps)) + " dependent calls × " + std::to_string(o.elements) +
       " invocations, median of " + std::to_string(o.repetitions) +
       "; native = the df64 rules' algorithms in fp64 on lavapipe (GLSL has no fp64 transcendentals)\n"
       "- bits: worst of " + std::to_string(o.accuracy_samples) +
       " inputs per domain against long double; fp32 on the float nearest each input\n\n";
  s += "| function | backend | variant | ns/call | min ns/call | time / fp32 | time / native | time / luma.gl | bits | domain | "
       "bits, \\|x\\| in [2^-10, 2^20] |\n|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const TranscendentalRow& r : report.rows) {
    if (!r.ok && r.not_applicable) continue;
    s += "| " + r.function + " | " + backend_key(r.backend) + " | " + variant_name(r.variant) + " | ";
    if (!r.ok) {
      s += "not run | | | | | | | |\n";
      continue;
    }
    s += fixed(r.ns_per_call, 1) + (r.finite_output ? "" : " (non-finite!)") + " | " + fixed(r.ns_per_call_min, 1) + " | " +
         ratio(r.vs_fp32) + " | " +
         ratio(r.vs_native) + " | " + ratio(r.vs_luma) + " | " + bits(r.bits) + " | " +
         domain_name(r.function, Domain::Main) + " | " + bits(r.bits_wide) + " |\n";
  }
  if (!report.notes.empty()) {
    s += "\nNot run:\n";
    for (const std::string& n : report.notes) s += "- " + n.substr(0, n.find('\n')) + "\n";
  }
  return s;
}

}  // namespace doublet::bench

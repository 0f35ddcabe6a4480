#include "verify/verify.hpp"

#include <regex>

#include "verify/compute_harness.hpp"
#include "verify/graphics_harness.hpp"

namespace doublet::verify {
namespace {

// The user's shader as the native reference: same text, desktop GLSL 4.50 (doubles are core there).
std::string as_native_450(std::string_view source) {
  static const std::regex version(R"(^[ \t]*#[ \t]*version[^\n]*)", std::regex::multiline);
  std::string s(source);
  if (std::regex_search(s, version)) return std::regex_replace(s, version, "#version 450",
                                                               std::regex_constants::format_first_only);
  return "#version 450\n" + s;
}

std::string diagnostics_text(const Result& r) {
  std::string s;
  for (const Diagnostic& d : r.diagnostics) s += format_diagnostic(d) + "\n";
  return s;
}

}  // namespace

bool VerifyReport::driver_failed() const {
  for (const BackendRun& r : runs)
    if (!r.error.empty()) return true;
  return false;
}

bool VerifyReport::passed() const {
  if (!input_error.empty() || driver_failed()) return false;
  for (const BackendRun& r : runs)
    for (const OutputStats& o : r.outputs)
      if (!o.passed()) return false;
  return true;
}

namespace {

// Compute: every sample a dispatch or an invocation (compute_harness.hpp).
void run_compute_stage(const std::string& native_glsl, const Result& lowered, const VerifyOptions& options,
                       VerifyReport* report) {
  ComputeHarness harness;
  if (std::string e = harness.plan(native_glsl, lowered.output, lowered.manifest, options.spec, options.samples);
      !e.empty()) {
    report->input_error = e;
    return;
  }
  harness.generate(options.seed);
  report->notes = harness.notes();
  report->inputs = harness.describe_inputs();
  report->dispatches = harness.dispatches();

  const std::vector<runner::ComputeResult> native = runner::run_compute_batch(runner::Backend::Vulkan, harness.native_jobs());
  const bool native_ok = native.size() == harness.dispatches() && native.back().ok;
  const std::vector<runner::ComputeJob> lowered_jobs = harness.lowered_jobs();
  for (runner::Backend backend : options.backends) {
    BackendRun run;
    run.backend = backend;
    run.reference_driver = native.back().device;
    if (backend == runner::Backend::Gles && !target_is_es(options.lower.target)) {
      report->notes.push_back("GLES backend skipped: target " + report->target + " is desktop GLSL");
      continue;
    }
    run.probe = probe_compute(backend);
    if (!native_ok) {
      run.error = "native fp64 run failed: " + native.back().error;
    } else {
      const std::vector<runner::ComputeResult> got = runner::run_compute_batch(backend, lowered_jobs);
      run.driver = got.back().device;
      if (got.size() != lowered_jobs.size() || !got.back().ok) run.error = "lowered run failed: " + got.back().error;
      else run.outputs = harness.compare(native, got, options.min_bits);
    }
    report->runs.push_back(std::move(run));
  }
}

// Vertex/fragment: draws of points whose in/out variables pass through storage buffers
// (graphics_harness.hpp); the native fp64 shader runs in the same stage on lavapipe.
void run_graphics_stage(runner::GraphicsStage stage, const std::string& native_glsl, const Result& lowered,
                        const VerifyOptions& options, VerifyReport* report) {
  const Target t = options.lower.target;
  GraphicsHarness harness;
  if (std::string e = harness.plan(stage, native_glsl, lowered.output, lowered.manifest, options.spec, options.samples);
      !e.empty()) {
    report->input_error = e;
    return;
  }
  harness.generate(options.seed);
  report->notes = harness.notes();
  if (t == Target::Es100 || t == Target::Es300)
    report->notes.push_back(report->target + " text runs as #version 310 es (the capture's storage buffers need 3.10; "
                            "in/out, attribute/varying, gl_FragColor/gl_FragData and texture2D/textureCube are "
                            "rewritten, the rest of the text is unchanged)");
  if (t == Target::Glsl330)
    report->notes.push_back("glsl330 text runs as #version 450 (the capture's storage buffers need 4.30)");
  report->inputs = harness.describe_inputs();
  report->dispatches = harness.draws();

  const std::vector<runner::GraphicsResult> native = runner::run_graphics_batch(runner::Backend::Vulkan, harness.native_jobs());
  const bool native_ok = native.size() == harness.draws() && native.back().ok;
  const std::vector<runner::GraphicsJob> lowered_jobs = harness.lowered_jobs();
  for (runner::Backend backend : options.backends) {
    BackendRun run;
    run.backend = backend;
    run.reference_driver = native.back().device;
    if (backend == runner::Backend::Gles && !target_is_es(t)) {
      report->notes.push_back("GLES backend skipped: target " + report->target + " is desktop GLSL");
      continue;
    }
    run.probe = probe_stage(backend, stage);
    if (!native_ok) {
      run.error = "native fp64 run failed: " + native.back().error;
    } else {
      const std::vector<runner::GraphicsResult> got = runner::run_graphics_batch(backend, lowered_jobs);
      run.driver = got.back().device;
      if (got.size() != lowered_jobs.size() || !got.back().ok) run.error = "lowered run failed: " + got.back().error;
      else run.outputs = harness.compare(native, got, options.min_bits);
    }
    report->runs.push_back(std::move(run));
  }
}

}  // namespace

VerifyReport verify(std::string_view source, const VerifyOptions& options) {
  VerifyReport report;
  report.shader = options.lower.file_name;
  report.target = std::string(to_string(options.lower.target));
  report.stage = options.lower.stage ? std::string(to_string(*options.lower.stage)) : "";
  report.sabotage = std::string(to_string(options.sabotage));
  report.samples = options.samples;
  report.seed = options.seed;
  if (!options.lower.stage) {
    report.input_error = "the stage is unknown (vert, frag or comp)";
    return report;
  }
  if (options.samples == 0) {
    report.input_error = "--samples must be at least 1";
    return report;
  }

  std::string lowered_source(source);
  Options lower_options = options.lower;
  apply_sabotage(options.sabotage, &lowered_source, &lower_options);
  const Result lowered = lower(lowered_source, lower_options);
  if (!lowered.ok) {
    report.input_error = "lowering failed:\n" + diagnostics_text(lowered);
    return report;
  }
  report.lowered_glsl = lowered.output;

  const std::string native = as_native_450(source);
  switch (*options.lower.stage) {
    case Stage::Compute: run_compute_stage(native, lowered, options, &report); break;
    case Stage::Vertex: run_graphics_stage(runner::GraphicsStage::Vertex, native, lowered, options, &report); break;
    case Stage::Fragment: run_graphics_stage(runner::GraphicsStage::Fragment, native, lowered, options, &report); break;
  }
  return report;
}

}  // namespace doublet::verify

#include "verify/verify.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

#include "frontend/text_scan.hpp"
#include "target/target.hpp"
#include "verify/compute_harness.hpp"
#include "verify/webgpu_jobs.hpp"
#include "verify/graphics_harness.hpp"
#include "verify/words.hpp"

namespace doublet::verify {
namespace {

// The user's shader as the native reference: same text, desktop GLSL 4.50 (doubles are core
// there), with the -D definitions after the #version line (a #line keeps line numbers) and every
// `#include "..."` expanded the way the lowering resolves it (Options::includer, else next to the
// including file, then the -I directories), so that both runs compile the same program.
// The file an `#include "name"` or `#include <name>` line names, else "". (A scanner, not a regex:
// libstdc++'s matcher recurses per character and a long line would overflow the stack.)
std::string include_line_target(const std::string& line) {
  std::string_view rest;
  if (frontend::directive_name(line, rest) != "include") return "";
  rest = frontend::trim_blanks(rest);
  if (rest.empty() || (rest.front() != '"' && rest.front() != '<')) return "";
  const size_t end = rest.find_first_of("\">", 1);
  if (end == std::string_view::npos || end == 1) return "";
  return std::string(rest.substr(1, end - 1));
}

std::optional<IncludeResult> resolve_include(const Options& o, const std::string& requested, const std::string& from) {
  if (o.includer) return o.includer->include(requested, from);
  namespace fs = std::filesystem;
  std::vector<fs::path> dirs{fs::path(from).parent_path()};
  for (const std::string& d : o.include_dirs) dirs.emplace_back(d);
  for (const fs::path& dir : dirs) {
    std::ifstream in(dir / requested, std::ios::binary);
    if (!in) continue;
    std::ostringstream text;
    text << in.rdbuf();
    return IncludeResult{(dir / requested).lexically_normal().string(), text.str()};
  }
  return std::nullopt;
}

constexpr int kMaxIncludeDepth = 32;  // as the front end: deeper means a cycle

bool expand_includes(const Options& o, const std::string& text, const std::string& path, int depth, std::string* out,
                     std::string* error) {
  std::istringstream lines(text);
  int number = 0;
  for (std::string line; std::getline(lines, line);) {
    ++number;
    const std::string requested = include_line_target(line);
    if (requested.empty()) {
      *out += line + "\n";
      continue;
    }
    const std::optional<IncludeResult> found = resolve_include(o, requested, path);
    if (!found) return (*error = path + ":" + std::to_string(number) + ": cannot find include \"" + requested + "\""), false;
    if (depth >= kMaxIncludeDepth) return (*error = path + ": #include nested too deep (a cycle?)"), false;
    if (!expand_includes(o, found->contents, found->resolved_path, depth + 1, out, error)) return false;
    *out += "#line " + std::to_string(number + 1) + "\n";
  }
  return true;
}

std::string as_native_450(std::string_view source, const Options& o, std::string* error) {
  std::string s(source);
  // The first line that is a #version directive: [version_at, body_at) without its newline.
  size_t version_at = 0, body_at = 0;
  bool has_version = false;
  for (size_t start = 0; start < s.size() && !has_version;) {
    const size_t end = std::min(s.find('\n', start), s.size());
    std::string_view rest;
    if (frontend::directive_name(std::string_view(s).substr(start, end - start), rest) == "version") {
      has_version = true;
      version_at = start;
      body_at = end;
    }
    start = end + 1;
  }
  const int body_line = has_version ? 1 + static_cast<int>(std::count(s.begin(), s.begin() + static_cast<long>(body_at), '\n')) : 1;
  std::string header = "#version 450\n";
  for (const auto& [name, value] : o.defines) header += "#define " + name + " " + (value.empty() ? "1" : value) + "\n";
  header += "#line " + std::to_string(has_version ? body_line : 1) + "\n";
  std::string body = s.substr(body_at);
  if (has_version && !body.empty() && body.front() == '\n') body.erase(0, 1);
  std::string expanded;
  if (!expand_includes(o, body, o.file_name, 0, &expanded, error)) return {};
  return (has_version ? s.substr(0, version_at) : std::string()) + header + expanded;
}

// WebGL2 compiles GLSL ES 1.00 and 3.00 (and the webgl2 target's text, ES 3.00 with WebGL's rules).
bool runs_on_webgl2(Target t) { return t == Target::Es100 || t == Target::Es300 || t == Target::Webgl2; }

bool has_backend(const VerifyOptions& o, runner::Backend b) {
  return std::find(o.backends.begin(), o.backends.end(), b) != o.backends.end();
}

// WebGL2 asked for where it cannot run: an input error when it is the only backend, else a note
// and the other backends run. Empty when WebGL2 can run (or was not asked for).
std::string webgl2_skip_reason(const VerifyOptions& o) {
  if (!has_backend(o, runner::Backend::WebGl2)) return {};
  if (*o.lower.stage == Stage::Compute)
    return "WebGL2 has no compute shaders: verify a compute shader with --backend webgpu (a WGSL target), vulkan or gles";
  if (!runs_on_webgl2(o.lower.target))
    return "WebGL2 runs GLSL ES 1.00/3.00: use --target es300 (or es100) with --backend webgl2, not " +
           std::string(to_string(o.lower.target));
  return {};
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

// A uniform declared with an initializer runs at that value in both shaders (the manifest's
// "default", which the lowered shader does not carry on ES targets: the application sets it, and so
// does verify), unless --range or a spec names it.
Spec with_uniform_defaults(const Spec& spec, const Manifest& manifest, std::vector<std::string>* notes) {
  Spec out = spec;
  for (const InterfaceVariable& v : manifest.variables) {
    if (v.storage != "uniform" || v.default_value.empty() || out.inputs.count(v.name)) continue;
    out.inputs[v.name].values = v.default_value;
    out.inputs[v.name].from_initializer = true;
    notes->push_back("uniform '" + v.name + "' runs at its initializer's value (the manifest's default; --range " +
                     v.name + "=LO:HI samples it instead)");
  }
  return out;
}

// Compute: every sample a dispatch or an invocation (compute_harness.hpp).
// `wgsl`: the WGSL lowering for --backend webgpu (null when WebGPU was not asked for or cannot run).
void run_compute_stage(const std::string& native_glsl, const Result& lowered, const Result* wgsl,
                       const VerifyOptions& options, VerifyReport* report) {
  ComputeHarness harness;
  std::vector<std::string> default_notes;
  const Spec spec = with_uniform_defaults(options.spec, lowered.manifest, &default_notes);
  if (std::string e = harness.plan(native_glsl, lowered.output, lowered.manifest, spec, options.samples); !e.empty()) {
    report->input_error = e;
    return;
  }
  harness.generate(options.seed);
  report->notes = harness.notes();
  report->notes.insert(report->notes.end(), default_notes.begin(), default_notes.end());
  report->inputs_beyond_float_range = harness.inputs_beyond_float_range();
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
    if (backend == runner::Backend::WebGl2) {
      report->notes.push_back("WebGL2 backend skipped: " + webgl2_skip_reason(options));
      continue;
    }
    if (backend == runner::Backend::WebGpu) {
      if (!wgsl) continue;  // the reason is already a note
      // One browser page per dispatch (about a second each): a shader fed through uniforms or
      // fixed-size arrays needs a dispatch per sample, which would take minutes.
      constexpr size_t kMaxWebGpuDispatches = 32;
      if (lowered_jobs.size() > kMaxWebGpuDispatches) {
        const std::string why = "the WebGPU backend runs one browser page per dispatch and this shader needs " +
                                std::to_string(lowered_jobs.size()) + " (one per sample: its inputs are uniforms or " +
                                "fixed-size arrays); use --samples " + std::to_string(kMaxWebGpuDispatches) +
                                " or fewer, or feed it through runtime-sized arrays";
        if (options.backends.size() == 1) {
          report->input_error = why;
          return;
        }
        report->notes.push_back("WebGPU backend skipped: " + why);
        continue;
      }
      run.probe.error = "not run on WebGPU (the driver probe is GLSL)";
      if (!native_ok) {
        run.error = "native fp64 run failed: " + native.back().error;
      } else {
        const std::vector<runner::ComputeResult> got = run_jobs_on_webgpu(wgsl->output, wgsl->manifest, lowered_jobs);
        run.driver = got.back().device;
        if (got.size() != lowered_jobs.size() || !got.back().ok) run.error = "lowered run failed: " + got.back().error;
        else run.outputs = harness.compare(native, got, options.min_bits);
      }
      report->runs.push_back(std::move(run));
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
  std::vector<std::string> default_notes;
  const Spec spec = with_uniform_defaults(options.spec, lowered.manifest, &default_notes);
  if (std::string e = harness.plan(stage, native_glsl, lowered.output, lowered.manifest, spec, options.samples);
      !e.empty()) {
    report->input_error = e;
    return;
  }
  harness.generate(options.seed);
  report->notes = harness.notes();
  report->notes.insert(report->notes.end(), default_notes.begin(), default_notes.end());
  report->inputs_beyond_float_range = harness.inputs_beyond_float_range();
  const bool storage_capture = std::any_of(options.backends.begin(), options.backends.end(),
                                           [](runner::Backend b) { return b != runner::Backend::WebGl2; });
  if ((t == Target::Es100 || t == Target::Es300 || t == Target::Webgl2) && storage_capture)
    report->notes.push_back(report->target + " text runs as #version 310 es (the capture's storage buffers need 3.10; "
                            "in/out, attribute/varying, gl_FragColor/gl_FragData and texture2D/textureCube are "
                            "rewritten, the rest of the text is unchanged)");
  if (has_backend(options, runner::Backend::WebGl2) && runs_on_webgl2(t))
    report->notes.push_back("WebGL2: the lowered text runs as #version 300 es in headless Chromium (in/out as plain "
                            "globals, inputs read bit-exactly from an RGBA32UI texture, outputs returned as their bits "
                            "through " + std::string(stage == runner::GraphicsStage::Vertex ? "transform feedback" : "RGBA32UI colour attachments") + ")");
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
    const bool vertex_or_fragment = stage == runner::GraphicsStage::Vertex || stage == runner::GraphicsStage::Fragment;
    if ((backend == runner::Backend::WebGl2 || backend == runner::Backend::WebGpu) && !vertex_or_fragment) {
      report->notes.push_back(std::string(runner::backend_name(backend)) +
                              " backend skipped: WebGL2 and WebGPU have no geometry or tessellation shaders");
      continue;
    }
    if (backend == runner::Backend::Gles && !target_is_es(t)) {
      report->notes.push_back("GLES backend skipped: target " + report->target + " is desktop GLSL");
      continue;
    }
    if (backend == runner::Backend::WebGpu) {
      report->notes.push_back("WebGPU backend skipped: it verifies compute shaders (WGSL); use --backend webgl2 for a "
                              "vertex or fragment shader");
      continue;
    }
    if (backend == runner::Backend::WebGl2 && !runs_on_webgl2(t)) {
      report->notes.push_back("WebGL2 backend skipped: " + webgl2_skip_reason(options));
      continue;
    }
    // The probe and the lowered draws in one call: on WebGL2 that is one browser start.
    // A geometry or tessellation shader's driver is probed in the vertex stage (the probe is a
    // vertex/fragment job).
    const runner::GraphicsStage probed = vertex_or_fragment ? stage : runner::GraphicsStage::Vertex;
    std::vector<std::vector<runner::GraphicsJob>> batches{{stage_probe_job(backend, probed)}};
    if (native_ok) batches.push_back(lowered_jobs);
    const std::vector<std::vector<runner::GraphicsResult>> results = runner::run_graphics_batches(backend, batches);
    run.probe = judge_stage_probe(backend, probed, results[0].back());
    if (!native_ok) {
      run.error = "native fp64 run failed: " + native.back().error;
    } else {
      const std::vector<runner::GraphicsResult>& got = results[1];
      run.driver = got.back().device;
      if (got.size() != lowered_jobs.size() || !got.back().ok) run.error = "lowered run failed: " + got.back().error;
      else run.outputs = harness.compare(native, got, options.min_bits);
    }
    report->runs.push_back(std::move(run));
  }
}

}  // namespace

namespace {

// VerifyOptions::judge_against_float: the same verification of the shader demoted to float (the
// drop-lo sabotage) gives each output's float median; outputs match by name (the demoted shader
// names them without the " (hi+lo)" of a split output) and by backend.
void judge_against_float(std::string_view source, const VerifyOptions& options, VerifyReport* report) {
  const Mode mode = options.lower.mode;
  if (!report->input_error.empty()) return;
  if (mode != Mode::Df64 && mode != Mode::Df64Fast && mode != Mode::Df64Int) return;
  VerifyOptions demoted = options;
  demoted.sabotage = Sabotage::DropLo;
  demoted.judge_against_float = false;
  const VerifyReport floor = verify(source, demoted);
  auto base_name = [](const std::string& n) { return n.substr(0, n.find(" (")); };
  int judged = 0;
  for (BackendRun& run : report->runs)
    for (const BackendRun& float_run : floor.runs)
      if (float_run.backend == run.backend && float_run.error.empty())
        for (OutputStats& o : run.outputs)
          for (const OutputStats& f : float_run.outputs)
            if (base_name(f.name) == base_name(o.name)) {
              o.float_median_bits = f.median_bits();
              ++judged;
            }
  report->notes.push_back("no threshold: judged against the shader demoted to float (" + std::to_string(judged) +
                          " outputs): each must keep " + std::to_string(int(OutputStats::kBeyondFloatBits)) +
                          " more median bits than float alone, where float keeps fewer than " +
                          std::to_string(int(OutputStats::kFloatIsEnoughBits)));
}

// The runner's stage for a vertex, fragment, geometry or tessellation shader.
runner::GraphicsStage graphics_stage(Stage stage) {
  switch (stage) {
    case Stage::Vertex: return runner::GraphicsStage::Vertex;
    case Stage::Fragment: return runner::GraphicsStage::Fragment;
    case Stage::Geometry: return runner::GraphicsStage::Geometry;
    case Stage::TessControl: return runner::GraphicsStage::TessControl;
    default: return runner::GraphicsStage::TessEvaluation;
  }
}

}  // namespace

VerifyReport verify(std::string_view source, const VerifyOptions& options) {
  VerifyReport report;
  report.shader = options.lower.file_name;
  report.target = std::string(to_string(options.lower.target));
  report.stage = options.lower.stage ? std::string(to_string(*options.lower.stage)) : "";
  report.sabotage = std::string(to_string(options.sabotage));
  if (options.lower.mode != Mode::Df64) report.mode = std::string(to_string(options.lower.mode));
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

  if (std::string why = webgl2_skip_reason(options); !why.empty() && options.backends.size() == 1) {
    report.input_error = why;
    return report;
  }

  std::string lowered_source(source);
  Options lower_options = options.lower;
  if (options.sabotage == Sabotage::DropLo) {
    // The demotion edits text: included text too (an engine header's dvec3 helper, a macro's 1.0lf),
    // so the includes are expanded first, as for the native run.
    std::string expanded, include_error;
    if (!expand_includes(options.lower, lowered_source, options.lower.file_name, 0, &expanded, &include_error)) {
      report.input_error = include_error;
      return report;
    }
    lowered_source = expanded;
  }
  apply_sabotage(options.sabotage, &lowered_source, &lower_options);
  Result lowered = lower(lowered_source, lower_options);
  if (!lowered.ok) {
    report.input_error = "lowering failed:\n" + diagnostics_text(lowered);
    return report;
  }
  if (!apply_output_sabotage(options.sabotage, &lowered.output)) {
    report.input_error = "--sabotage " + report.sabotage + " found nothing to break in the lowered shader (it edits "
                         "mode exact's rounding: use --mode exact or rte-exact)";
    return report;
  }
  report.lowered_glsl = lowered.output;

  std::string include_error;
  const std::string native = as_native_450(source, options.lower, &include_error);
  if (!include_error.empty()) {
    report.input_error = include_error;
    return report;
  }
  // WebGPU runs the WGSL lowering of the same (sabotaged) source; the harness plans on `lowered`,
  // the GLSL lowering the WGSL is printed from (same names and buffers).
  std::optional<Result> wgsl;
  if (has_backend(options, runner::Backend::WebGpu)) {
    const bool alone = options.backends.size() == 1;
    if (*options.lower.stage != Stage::Compute) {
      if (alone) {
        report.input_error = "the WebGPU backend verifies compute shaders (WGSL); use --backend webgl2 for a vertex "
                             "or fragment shader";
        return report;
      }
    } else {
      Options wgsl_options = lower_options;
      wgsl_options.target = Target::Wgsl;
      wgsl = lower(lowered_source, wgsl_options);
      if (wgsl->ok && !apply_output_sabotage(options.sabotage, &wgsl->output)) {
        report.input_error = "--sabotage " + report.sabotage + " found nothing to break in the WGSL lowering";
        return report;
      }
      if (!wgsl->ok) {
        const std::string why = "the WGSL lowering failed:\n" + diagnostics_text(*wgsl);
        if (alone) {
          report.input_error = why;
          return report;
        }
        report.notes.push_back("WebGPU backend skipped: " + why);
        wgsl.reset();
      }
    }
  }
  if (*options.lower.stage == Stage::Compute)
    run_compute_stage(native, lowered, wgsl ? &*wgsl : nullptr, options, &report);
  else
    run_graphics_stage(graphics_stage(*options.lower.stage), native, lowered, options, &report);
  if (options.judge_against_float) judge_against_float(source, options, &report);
  // Mode exact promises native fp64's bits: any output differing is a failure (NaN payloads apart).
  if (options.lower.mode == Mode::Exact)
    for (BackendRun& run : report.runs)
      for (OutputStats& o : run.outputs) o.require_identical = true;
  return report;
}

FirstJobs first_jobs(std::string_view source, const VerifyOptions& options) {
  FirstJobs out;
  if (!options.lower.stage) return (out.error = "the stage is unknown"), out;
  const Result lowered = lower(source, options.lower);
  if (!lowered.ok) return (out.error = "lowering failed:\n" + diagnostics_text(lowered)), out;
  std::string include_error;
  const std::string native = as_native_450(source, options.lower, &include_error);
  if (!include_error.empty()) return (out.error = include_error), out;
  std::vector<std::string> notes;
  const Spec spec = with_uniform_defaults(options.spec, lowered.manifest, &notes);
  if (*options.lower.stage == Stage::Compute) {
    ComputeHarness harness;
    if (std::string e = harness.plan(native, lowered.output, lowered.manifest, spec, 1); !e.empty())
      return (out.error = e), out;
    harness.generate(options.seed);
    out.native_compute = harness.native_jobs().at(0);
    out.lowered_compute = harness.lowered_jobs().at(0);
    out.native_compute.strict_fp64 = false;  // native fp64 as users compile it
    return out;
  }
  GraphicsHarness harness;
  if (std::string e = harness.plan(graphics_stage(*options.lower.stage), native, lowered.output, lowered.manifest, spec, 1); !e.empty())
    return (out.error = e), out;
  harness.generate(options.seed);
  out.native_graphics = harness.native_jobs().at(0);
  out.lowered_graphics = harness.lowered_jobs().at(0);
  out.native_graphics.strict_fp64 = false;
  return out;
}

}  // namespace doublet::verify

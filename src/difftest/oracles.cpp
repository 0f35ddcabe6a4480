// Runs the oracles of oracles.hpp through doublet::verify, which feeds native and lowered shaders the
// same inputs and hands back every sample's values (OutputStats::got_values / want_values).
#include "difftest/oracles.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <sstream>

#include <regex>

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include "plan/planner.hpp"
#include "runner/runner.hpp"
#include "verify/verify.hpp"

namespace doublet::difftest {
namespace {

// What the WGSL lowering says of what it refuses by design (src/emit/wgsl_printer.cpp, docs/web.md):
// a construct WGSL cannot express, a std140 member it cannot place at std140's offsets, a padded
// std140 array read as a whole. (verify's one-page-per-dispatch limit is met with fewer samples
// instead: kWebGpuPagedSamples.)
bool is_documented_wgsl_refusal(const std::string& error) {
  return error.find("cannot be expressed in WGSL") != std::string::npos ||
         error.find("is std140, and WGSL cannot read") != std::string::npos ||
         error.find("elements are padded to std140's 16-byte stride") != std::string::npos;
}

// Samples of a WebGPU comparison whose inputs are uniforms: verify runs one browser page per
// sample there (docs/verify.md), so a few.
constexpr int kWebGpuPagedSamples = 4;

// Float-float's range: beyond this a df64 pair overflows where native does not (docs/accuracy.md).
constexpr double kPairRange = 1e30;

uint64_t bits_of(double x) {
  uint64_t b;
  std::memcpy(&b, &x, 8);
  return b;
}

std::string show(double x) {
  std::ostringstream s;
  s.precision(17);
  s << x << " (" << verify::hex(x) << ")";
  return s.str();
}

// One lowering an oracle runs: its mode and target, and what differs from the defaults.
struct Lowering {
  Mode mode;
  Target target;
  bool gpu_shader5 = false;          // es310's `precise` through GL_EXT_gpu_shader5
  GuardKind guard = GuardKind::Auto;
  bool sabotaged = false;            // CheckOptions::sabotage applies to this run
  std::string label() const {
    return std::string(to_string(mode)) + " " + std::string(to_string(target)) + (gpu_shader5 ? " (gpu_shader5)" : "");
  }
};

verify::VerifyReport run_verify(const std::string& glsl, const verify::Spec& spec, Stage stage, const Lowering& lowering,
                                std::vector<runner::Backend> backends, const CheckOptions& options, CheckResult* result) {
  const auto start = std::chrono::steady_clock::now();
  verify::VerifyOptions o;
  o.lower.stage = stage;
  o.lower.target = lowering.target;
  o.lower.mode = lowering.mode;
  o.lower.allow_gpu_shader5 = lowering.gpu_shader5;
  o.lower.guard = lowering.guard;
  o.lower.skip_passes = options.skip_passes;
  if (lowering.sabotaged) o.sabotage = verify::parse_sabotage(options.sabotage).value_or(verify::Sabotage::None);
  o.lower.file_name = "program." + std::string(to_string(stage));
  o.samples = options.samples;
  o.seed = 1;
  o.spec = spec;
  o.backends = std::move(backends);
  verify::VerifyReport report = verify::verify(glsl, o);
  result->seconds.emplace_back(
      lowering.label() + (o.backends.size() == 1 ? std::string(" ") + runner::backend_name(o.backends[0]) : ""),
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  return report;
}

// A lowering or driver failure of a valid program, as a finding; true when there was one (or when
// verify refused the program itself, which makes it invalid).
bool failed(const verify::VerifyReport& r, const std::string& what, CheckResult* result) {
  std::vector<Finding>* findings = &result->findings;
  if (r.input_error.rfind("lowering failed", 0) == 0 || r.input_error.rfind("the lowered shader", 0) == 0 ||
      r.input_error.rfind("the WGSL lowering failed", 0) == 0) {
    findings->push_back({"lowering", what + ": " + r.input_error});
    return true;
  }
  if (!r.input_error.empty()) {
    if (result->invalid.empty()) result->invalid = what + ": " + r.input_error;
    return true;
  }
  for (const verify::BackendRun& run : r.runs)
    if (!run.error.empty()) {
      findings->push_back({"lowering", what + " on " + runner::backend_name(run.backend) + ": " + run.error});
      return true;
    }
  return false;
}

// Samples whose bits differ between `a` and `b` (NaN against NaN is no difference), less those
// `excused(s)` leaves out; the first of them.
struct Differences {
  uint64_t count = 0, first = 0;
};
template <class Excused>
Differences differences(const std::vector<double>& a, const std::vector<double>& b, Excused excused) {
  Differences d;
  for (size_t s = 0; s < a.size() && s < b.size(); ++s) {
    if (bits_of(a[s]) == bits_of(b[s]) || (std::isnan(a[s]) && std::isnan(b[s])) || excused(s)) continue;
    if (d.count++ == 0) d.first = s;
  }
  return d;
}

// Two runs' values of every output, sample by sample; `skip` says which samples do not count.
template <class Skip>
void compare_runs(const verify::BackendRun& a, const verify::BackendRun& b, const std::string& oracle,
                  const std::string& what, Skip skip, std::vector<Finding>* findings) {
  for (size_t o = 0; o < a.outputs.size() && o < b.outputs.size(); ++o) {
    const verify::OutputStats& x = a.outputs[o];
    const verify::OutputStats& y = b.outputs[o];
    const Differences d = differences(x.got_values, y.got_values, [&](size_t s) {
      return skip(x.want_values[s], x.got_values[s], y.got_values[s]);
    });
    if (d.count)
      findings->push_back({oracle, what + ": output " + x.name + ": " + std::to_string(d.count) + " of " +
                                       std::to_string(x.got_values.size()) + " samples differ; sample " +
                                       std::to_string(d.first) + ": " + show(x.got_values[d.first]) + " against " +
                                       show(y.got_values[d.first]) + ", native " + show(x.want_values[d.first])});
  }
}

// Samples where native is not finite or beyond float-float's range make no claim about pairs.
bool outside_pair_range(double want, double, double) { return !std::isfinite(want) || std::fabs(want) > kPairRange; }

// Below 2^-100 a pair's lo word is under float's normal range (2^-126): the error terms of the
// integer and the float error-free transformations underflow, each rounded its own way (rules/int.glsl,
// df_int_prod_error's range; docs/accuracy.md), so df64-int and df64 need not agree there (seed
// 70349: 2 and 7 of 16384 results near 1e-38 differ in the last bits of hi).
bool outside_int_range(double want, double a, double b) {
  return outside_pair_range(want, a, b) || (want != 0 && std::fabs(want) < 0x1p-100);
}

// An output's own name: "r0" for verify's "r0[].x", "r0.y" or "r0 (hi+lo)".
std::string base_name(const std::string& output) { return output.substr(0, output.find_first_of(".[ ")); }

// The bound oracle's scene: the spec's input ranges (a block member by its own name, a geometry
// input by its array's) and every output the df64 run measured, each with a nominal requirement
// (only the planner's estimates are read).
plan::Scene scene_of(const verify::Spec& spec, const verify::BackendRun& run) {
  plan::Scene scene;
  scene.file = "scene.json";
  for (const auto& [name, in] : spec.inputs) {
    if (!in.lo || !in.hi) continue;  // no range: the planner takes the input as unbounded
    std::string own = name.substr(name.rfind('.') == std::string::npos ? 0 : name.rfind('.') + 1);
    own = own.substr(0, own.find('['));
    scene.inputs[own].components = {plan::Interval{*in.lo, *in.hi}};
  }
  for (const verify::OutputStats& o : run.outputs) scene.outputs[base_name(o.name)].abs_error = 1;
  return scene;
}

// The bound oracle on one df64 report (every backend): each output's measured max |df64 - native|
// against the planner's df64 estimate plus its binary64 estimate. False when no output has a
// finite estimate (the oracle then made no check).
bool check_bound(const std::string& glsl, Stage stage, const verify::Spec& spec, const verify::VerifyReport& df64,
                 const std::string& what, const char* oracle, CheckResult* result) {
  if (df64.runs.empty()) return false;
  Options options;
  options.stage = stage;
  options.file_name = "program." + std::string(to_string(stage));
  const plan::PlanOutcome plan = plan::make_plan(glsl, options, scene_of(spec, df64.runs[0]));
  if (!plan.ok) {
    std::string why;
    for (const Diagnostic& d : plan.diagnostics) why += (why.empty() ? "" : "; ") + d.message;
    result->findings.push_back({oracle, "the planner refused a valid program: " + why});
    return true;
  }
  bool any = false;
  for (const plan::OutputRow& row : plan.outputs) {
    const double bound = row.estimate_df64 + row.estimate_exact;
    if (!std::isfinite(bound)) continue;
    any = true;
    for (const verify::BackendRun& run : df64.runs)
      for (const verify::OutputStats& o : run.outputs)
        if (base_name(o.name) == row.name && !(o.max_abs_err <= bound))
          result->findings.push_back(
              {oracle, what + " on " + runner::backend_name(run.backend) + ": output " + o.name + ": measured max |df64 - native| " +
                            show(o.max_abs_err) + " exceeds the planner's bound " + show(bound) + " (df64 " +
                            show(row.estimate_df64) + " + binary64 " + show(row.estimate_exact) + ")"});
  }
  return any;
}

}  // namespace

bool is_continuous(const std::string& glsl) {
  // Comments out first; then any jump: comparisons and ?:, control flow, rounding to integers and
  // the built-ins that select (sign, step, faceforward, refract's total reflection).
  const std::string code = std::regex_replace(glsl, std::regex(R"(//[^\n]*)"), "");
  static const std::regex jump(
      R"([<>?!]|==|\b(if|for|while|do|switch|discard|return|floor|ceil|fract|trunc|round|roundEven|mod|modf|frexp|)"
      R"(step|smoothstep|sign|faceforward|refract|isnan|isinf|int|uint|bool|ivec[234]|uvec[234]|bvec[234])\s*\()"
      R"(|\b(if|for|while|do|switch|discard|return|break|continue|bool)\b)");
  return !std::regex_search(code, jump);
}

bool compiles_natively(const std::string& glsl, const std::string& stage, std::string* error) {
  if (stage == "comp") {
    std::vector<uint32_t> spirv;
    return runner::compile_compute_to_spirv(glsl, &spirv, error);
  }
  runner::GraphicsInterface graphics;
  const runner::GraphicsStage graphics_stage = stage == "vert"   ? runner::GraphicsStage::Vertex
                                              : stage == "geom" ? runner::GraphicsStage::Geometry
                                              : stage == "tesc" ? runner::GraphicsStage::TessControl
                                              : stage == "tese" ? runner::GraphicsStage::TessEvaluation
                                                                : runner::GraphicsStage::Fragment;
  return runner::reflect_graphics(graphics_stage, glsl, &graphics, error);
}

CheckResult check(const std::string& glsl, const std::string& spec_json, const std::string& stage_name,
                  const CheckOptions& options) {
  CheckResult result;
  if (!compiles_natively(glsl, stage_name, &result.invalid)) return result;
  const Stage stage = parse_stage(stage_name).value_or(Stage::Compute);
  verify::Spec spec;
  if (std::string e = verify::parse_spec(spec_json, &spec); !e.empty()) {
    result.invalid = "spec: " + e;
    return result;
  }
  auto wants = [&](const char* oracle) {
    return std::find(options.oracles.begin(), options.oracles.end(), oracle) != options.oracles.end();
  };
  const std::vector<runner::Backend> drivers{runner::Backend::Vulkan, runner::Backend::Gles};

  if (wants("exact") && !options.skip_exact) {
    const Lowering exact{.mode = Mode::Exact, .target = Target::Es310, .sabotaged = true};
    const verify::VerifyReport r = run_verify(glsl, spec, stage, exact, drivers, options, &result);
    if (!failed(r, exact.label(), &result)) {
      result.checked.push_back("exact");
      for (const verify::BackendRun& run : r.runs)
        for (const verify::OutputStats& o : run.outputs) {
          // Zeros of opposite sign are excused: lavapipe's NIR rewrites mix(0, b, t) as b * t even
          // under NoContraction, so native's sign of a zero depends on what it could fold
          // (docs/robustness.md, "Differential testing"); mode exact follows the written formula.
          const Differences d = differences(o.got_values, o.want_values, [&](size_t s) {
            const bool zeros = o.got_values[s] == 0 && o.want_values[s] == 0;
            result.excused_zero_signs += zeros;
            return zeros;
          });
          if (d.count)
            result.findings.push_back(
                {"exact", std::string("mode exact on ") + runner::backend_name(run.backend) + ": output " + o.name + ": " +
                              std::to_string(d.count) + " of " + std::to_string(o.samples) +
                              " samples differ from native; sample " + std::to_string(d.first) + ": " +
                              show(o.got_values[d.first]) + ", native " + show(o.want_values[d.first])});
        }
    }
  }

  const bool bounded = (stage == Stage::Compute || stage == Stage::Vertex) && is_continuous(glsl);
  if (wants("guard") && bounded) {
    // The uniform guard (es310 without GL_EXT_gpu_shader5: the indexed `df_guard`, no `precise`)
    // under the same bound on both drivers: a driver that sees through the guard folds error terms
    // and leaves it (docs/robustness.md, "Differential testing").
    const Lowering guarded{.mode = Mode::Df64, .target = Target::Es310, .sabotaged = true};
    const verify::VerifyReport r = run_verify(glsl, spec, stage, guarded, drivers, options, &result);
    if (!failed(r, guarded.label(), &result) && check_bound(glsl, stage, spec, r, guarded.label() + " (uniform guard)", "guard", &result))
      result.checked.push_back("guard");
  }

  if (wants("int") || wants("targets") || wants("bound")) {
    // es320 declares the runtime `precise`, so no driver contracts a*b + c anywhere in it: two
    // lowerings then differ only where their rules do. es310's uniform guard, and df64-int's
    // default guard (none), leave contracting the parts that are not error-free transformations to
    // the driver, which changes the last bits (docs/robustness.md, "Differential testing").
    const Lowering base{.mode = Mode::Df64, .target = Target::Es320};
    const verify::VerifyReport df64 = run_verify(glsl, spec, stage, base, drivers, options, &result);
    if (!failed(df64, base.label(), &result)) {
      if (wants("int")) {
        const Lowering int_eft{.mode = Mode::Df64Int, .target = Target::Es320, .guard = GuardKind::Precise, .sabotaged = true};
        const verify::VerifyReport with_int = run_verify(glsl, spec, stage, int_eft, drivers, options, &result);
        if (!failed(with_int, int_eft.label(), &result)) {
          result.checked.push_back("int");
          // Zeros of opposite sign are excused too: a product or sum with a compile-time zero (the
          // inverse of a constant matrix times a constant vector) is folded by the drivers under
          // their float rules, which keep no sign of zero (GLSL does not require one), and the two
          // lowerings differ in which float operations the drivers may fold (docs/robustness.md,
          // "Differential testing"; seeds 46123, 47128).
          const auto skip = [&](double want, double a, double b) {
            const bool zeros = a == 0 && b == 0;
            result.excused_int_zero_signs += zeros && std::signbit(a) != std::signbit(b);
            return zeros || outside_int_range(want, a, b);
          };
          for (size_t b = 0; b < df64.runs.size() && b < with_int.runs.size(); ++b)
            compare_runs(with_int.runs[b], df64.runs[b], "int",
                         std::string("df64-int against df64 on ") + runner::backend_name(df64.runs[b].backend), skip,
                         &result.findings);
        }
      }
      if (wants("bound") && bounded) {
        verify::VerifyReport sabotaged;
        const verify::VerifyReport* measured = &df64;
        if (options.sabotage != "none") {  // the other oracles keep their unsabotaged reference
          const Lowering broken{.mode = Mode::Df64, .target = Target::Es320, .sabotaged = true};
          sabotaged = run_verify(glsl, spec, stage, broken, drivers, options, &result);
          measured = failed(sabotaged, broken.label(), &result) ? nullptr : &sabotaged;
        }
        if (measured && check_bound(glsl, stage, spec, *measured, base.label(), "bound", &result)) result.checked.push_back("bound");
      }
      if (wants("targets")) {
        bool all_ran = true;
        for (const Lowering& other_target : {Lowering{.mode = Mode::Df64, .target = Target::Glsl450},
                                             Lowering{.mode = Mode::Df64, .target = Target::Es310, .gpu_shader5 = true}}) {
          const verify::VerifyReport other =
              run_verify(glsl, spec, stage, other_target, {runner::Backend::Vulkan}, options, &result);
          const std::string what = other_target.label();
          if (failed(other, what, &result)) {
            all_ran = false;
            continue;
          }
          compare_runs(other.runs[0], df64.runs[0], "targets", what + " against es320 on lavapipe", outside_pair_range,
                       &result.findings);
        }
        if (options.webgpu && stage == Stage::Compute) {  // verify runs WGSL for compute only
          // The same lowering as the reference, printed as WGSL (sabotaged on request, to show a
          // difference is found).
          const Lowering wgsl{.mode = Mode::Df64, .target = Target::Es320, .sabotaged = true};
          verify::VerifyReport web = run_verify(glsl, spec, stage, wgsl, {runner::Backend::WebGpu}, options, &result);
          const verify::BackendRun* reference = &df64.runs[0];
          verify::VerifyReport few_reference;
          bool reference_ran = true;
          if (web.input_error.find("runs one browser page per dispatch") != std::string::npos) {
            // Uniform inputs: one page per sample in the browser, so a few samples, against es320
            // on lavapipe with the same few.
            CheckOptions few = options;
            few.samples = kWebGpuPagedSamples;
            few_reference = run_verify(glsl, spec, stage, base, {runner::Backend::Vulkan}, few, &result);
            reference_ran = !failed(few_reference, base.label(), &result);
            if (reference_ran) {
              web = run_verify(glsl, spec, stage, wgsl, {runner::Backend::WebGpu}, few, &result);
              reference = &few_reference.runs[0];
            }
          }
          if (!reference_ran)
            all_ran = false;
          else if (is_documented_wgsl_refusal(web.input_error))
            // A documented limit of the WGSL target: named in the run's output, not a finding
            // (docs/robustness.md, "Differential testing").
            result.notes.push_back("WebGPU not compared: " + web.input_error.substr(web.input_error.find('\n') + 1));
          else if (failed(web, "df64 wgsl in WebGPU", &result)) all_ran = false;
          else
            // WGSL lets an implementation ignore the sign of a zero (WGSL §15.7, "Floating Point
            // Evaluation"), and its f32 division need not be correctly rounded (2.5 ulp): Chromium's
            // WebGPU (SwiftShader) divides by a constant differently from lavapipe, which moves the
            // last bits of a float-float quotient (docs/robustness.md, findings). So WebGPU's pairs
            // must agree within 2^-40 relative, not bit for bit.
            compare_runs(web.runs[0], *reference, "targets", "df64 wgsl in WebGPU against es320 on lavapipe",
                         [](double want, double a, double b) {
                           return outside_pair_range(want, a, b) || std::fabs(a - b) <= 0x1p-40 * std::max(std::fabs(a), std::fabs(b));
                         },
                         &result.findings);
        }
        if (all_ran) result.checked.push_back("targets");
      }
    }
  }
  return result;
}

namespace {

// One field per line, newlines inside a field escaped: the child's result through a pipe.
std::string escape(const std::string& s) {
  std::string out;
  for (char c : s) out += c == '\n' ? std::string("\\n") : c == '\\' ? std::string("\\\\") : std::string(1, c);
  return out;
}
std::string unescape(const std::string& s) {
  std::string out;
  for (size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '\\' && i + 1 < s.size()) {
      out += s[i + 1] == 'n' ? '\n' : s[i + 1];
      ++i;
    } else {
      out += s[i];
    }
  }
  return out;
}

std::string serialize(const CheckResult& r) {
  std::string out = "invalid\t" + escape(r.invalid) + "\nexcused\t" + std::to_string(r.excused_zero_signs) +
                    "\nexcused_int\t" + std::to_string(r.excused_int_zero_signs) + "\n";
  for (const std::string& c : r.checked) out += "checked\t" + c + "\n";
  for (const std::string& n : r.notes) out += "note\t" + escape(n) + "\n";
  for (const Finding& f : r.findings) out += "finding\t" + f.oracle + "\t" + escape(f.detail) + "\n";
  for (const auto& [what, s] : r.seconds) out += "seconds\t" + what + "\t" + std::to_string(s) + "\n";
  return out;
}

CheckResult deserialize(const std::string& text) {
  CheckResult r;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    const size_t a = line.find('\t'), b = line.find('\t', a + 1);
    const std::string key = line.substr(0, a), first = line.substr(a + 1, b == std::string::npos ? std::string::npos : b - a - 1);
    const std::string second = b == std::string::npos ? "" : line.substr(b + 1);
    if (key == "invalid") r.invalid = unescape(first);
    else if (key == "excused") r.excused_zero_signs = std::stoull(first);
    else if (key == "excused_int") r.excused_int_zero_signs = std::stoull(first);
    else if (key == "checked") r.checked.push_back(first);
    else if (key == "note") r.notes.push_back(unescape(first));
    else if (key == "finding") r.findings.push_back({first, unescape(second)});
    else if (key == "seconds") r.seconds.emplace_back(first, std::stod(second));
  }
  return r;
}

}  // namespace

CheckResult check_in_child(const std::string& glsl, const std::string& spec_json, const std::string& stage,
                           const CheckOptions& options, double seconds, bool* timed_out) {
  *timed_out = false;
  int fds[2];
  if (pipe(fds) != 0) return check(glsl, spec_json, stage, options);
  const pid_t pid = fork();
  if (pid == 0) {
    close(fds[0]);
    const std::string text = serialize(check(glsl, spec_json, stage, options));
    for (size_t done = 0; done < text.size();) {
      const ssize_t n = write(fds[1], text.data() + done, text.size() - done);
      if (n <= 0) break;
      done += static_cast<size_t>(n);
    }
    _exit(0);  // no static destructors: the drivers' threads are not ours to join
  }
  close(fds[1]);
  std::string text;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) {
      *timed_out = true;
      break;
    }
    pollfd p{fds[0], POLLIN, 0};
    if (poll(&p, 1, static_cast<int>(std::min<long long>(left.count(), 1000))) <= 0) continue;
    char buf[4096];
    const ssize_t n = read(fds[0], buf, sizeof buf);
    if (n <= 0) break;  // the child finished (or died)
    text.append(buf, static_cast<size_t>(n));
  }
  close(fds[0]);
  if (*timed_out) kill(pid, SIGKILL);
  int status = 0;
  waitpid(pid, &status, 0);
  if (!*timed_out && !(WIFEXITED(status) && WEXITSTATUS(status) == 0)) *timed_out = true;
  return *timed_out ? CheckResult{} : deserialize(text);
}

}  // namespace doublet::difftest

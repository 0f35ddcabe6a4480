// `doublet verify SHADER ...`: run the shader natively in fp64 and lowered on real drivers and
// report per-output accuracy (docs/verify.md). The work is doublet::verify::verify(); this file
// only turns the command line into VerifyOptions and the report into output and an exit code.
#include <algorithm>
#include <iostream>

#include <CLI/CLI.hpp>

#include "atomic_file.hpp"
#include "commands.hpp"
#include "input_file.hpp"
#include "plan/planner.hpp"
#include "plan/scene.hpp"
#include "verify/report.hpp"
#include "verify/sweep.hpp"
#include "verify/verify.hpp"

#include "mode_args.hpp"

namespace doublet::cli {
namespace {

struct VerifyArgs {
  std::string shader, stage, target, backend = "both", sabotage = "none";  // target: default_target()
  std::string spec, json;
  std::string scene, plan;  // doublet plan: --scene FILE, --plan FILE (docs/plan.md)
  std::vector<std::string> ranges, defines, include_dirs;
  uint64_t samples = 1024, seed = 1;
  std::optional<double> min_bits;
  std::string sweep, sweep_stage = "comp", heatmap_dir = ".";
  int grid_step = 1;
  std::string mode;                   // --mode, --mode-for: the lowering's precision modes
  std::vector<std::string> mode_for;
};

// Exit codes of verify (docs/verify.md): 1 = accuracy below --min-bits; 3 = a driver failed.
constexpr int kExitBelowMinBits = 1;
constexpr int kExitDriver = 3;

// --target's default: es310 (compute needs 3.10), but ES 3.00 for a vertex/fragment run that
// includes WebGL2 (the webgl2 target once the lowering has one), which runs nothing newer.
std::string default_target(const VerifyArgs& a, std::optional<Stage> stage) {
  if (!a.target.empty()) return a.target;
  if ((a.backend == "webgl2" || a.backend == "all") && stage != Stage::Compute)
    return "webgl2";
  return "es310";
}

int input_error(const std::string& message) {
  std::cerr << "doublet verify: error: " << message << "\n";
  return kExitInput;
}


// --sweep OP|all: per-operation sweeps against MPFR; exit 1 when an op leaves its bound.
int run_sweep(const VerifyArgs& a) {
  if (a.sweep_stage != "comp") return input_error("--sweep supports --stage comp only so far");
  if (a.backend == "webgl2") return input_error("--sweep runs compute shaders, which WebGL2 lacks (--backend vulkan|gles|both)");
  verify::SweepOptions o;
  o.ops = a.sweep == "all" ? verify::sweep_ops() : std::vector<std::string>{a.sweep};
  const std::string target_name = a.target.empty() ? "es310" : a.target;
  const std::optional<Target> target = parse_target(target_name);
  if (!target) return input_error("unknown target '" + target_name + "'");
  if (*target == Target::Wgsl) return input_error("--sweep runs GLSL on lavapipe and Mesa GLES: use --target es310 (--target wgsl prints that lowering as WGSL)");
  o.target = *target;
  o.grid_step = a.grid_step;
  o.heatmap_dir = a.heatmap_dir;
  o.seed = a.seed;
  o.sabotage = verify::parse_sabotage(a.sabotage).value_or(verify::Sabotage::None);
  bool within = true;
  for (runner::Backend b : {runner::Backend::Vulkan, runner::Backend::Gles}) {
    if ((a.backend == "vulkan" && b != runner::Backend::Vulkan) || (a.backend == "gles" && b != runner::Backend::Gles))
      continue;
    std::cout << "[" << (b == runner::Backend::Vulkan ? "vulkan" : "gles") << "] "
              << verify::describe(verify::probe_compute(b)) << "\n" << std::flush;
    o.backend = b;
    std::string error;
    const std::vector<verify::OpSweep> sweeps = verify::sweep(o, &error);
    if (!error.empty()) return error.find("unknown sweep op") == 0 ? input_error(error) : (std::cerr << error << "\n", kExitDriver);
    std::cout << verify::format_sweep(sweeps) << std::flush;
    for (const verify::OpSweep& s : sweeps) within &= s.within_bound;
  }
  return within ? kExitOk : kExitBelowMinBits;
}

// --plan FILE: the plan's modes (command-line --mode-for entries, later, win). --scene FILE: its
// ranges, relations and abs_error thresholds join the spec.
int apply_scene_and_plan(const VerifyArgs& a, verify::VerifyOptions* o, plan::Scene* scene) {
  Diagnostic d;
  std::string text;
  if (!a.plan.empty()) {
    if (std::string e = read_input_file(a.plan, text); !e.empty()) return input_error("cannot read plan '" + a.plan + "': " + e);
    Options from_plan;
    if (!plan::load_plan(text, a.plan, &from_plan, &d)) return (std::cerr << format_diagnostic(d) << "\n", kExitInput);
    merge_plan_modes(from_plan, o->lower);
  }
  if (a.scene.empty()) return kExitOk;
  if (std::string e = read_input_file(a.scene, text); !e.empty()) return input_error("cannot read scene '" + a.scene + "': " + e);
  if (!plan::parse_scene(text, a.scene, scene, &d)) return (std::cerr << format_diagnostic(d) << "\n", kExitInput);
  for (const auto& [name, range] : scene->inputs) {
    verify::InputSpec& in = o->spec.inputs[name];
    for (const plan::Interval& c : range.components) in.component_ranges.emplace_back(c.lo, c.hi);
  }
  for (const plan::Relation& r : scene->relations) {
    // Samples are drawn for inputs; a relation on a value the shader computes cannot steer them.
    for (const std::string& side : {r.a, r.b})
      if (plan::is_computed_value(side))
        return (std::cerr << format_diagnostic(plan::scene_diagnostic(*scene, r.path + "/difference",
                                  "verify cannot sample a relation on '" + side +
                                      "', a value the shader computes: only relations between inputs")) << "\n",
                kExitInput);
    o->spec.relations.push_back({r.a, r.b, r.abs_max});
  }
  for (const auto& [name, req] : scene->outputs) o->spec.outputs[name].max_abs_error = req.abs_error;
  return kExitOk;
}

// Measured max |lowered - native| per scene output (all components, every backend) vs the promise.
std::string scene_summary(const verify::VerifyReport& report, const plan::Scene& scene) {
  std::string s = "\nscene promises (max |lowered - native| over every component and backend):\n";
  for (const auto& [name, req] : scene.outputs) {
    double worst = 0;
    bool seen = false, ok = true;
    for (const verify::BackendRun& run : report.runs)
      for (const verify::OutputStats& st : run.outputs)
        if (st.name == name || st.name.rfind(name + ".", 0) == 0 || st.name.rfind(name + " ", 0) == 0 ||
            st.name.rfind(name + "[", 0) == 0) {
          seen = true;
          worst = std::max(worst, st.max_abs_err);
          ok &= st.abs_passed();
        }
    char line[256];
    std::snprintf(line, sizeof line, "  %-20s measured %-10.3g promised %-10.3g %s\n", name.c_str(), worst,
                  req.abs_error, !seen ? "NOT MEASURED" : ok ? "ok" : "EXCEEDED");
    s += line;
  }
  return s;
}

int run_verify(const VerifyArgs& a) {
  if (!a.sweep.empty()) return run_sweep(a);
  if (a.shader.empty()) return input_error("SHADER is required (or --sweep OP|all)");
  verify::VerifyOptions o;
  o.lower.file_name = a.shader;
  o.lower.stage = a.stage.empty() ? stage_from_path(a.shader) : parse_stage(a.stage);
  if (!o.lower.stage) return input_error("cannot tell the stage of '" + a.shader + "': use -S vert|frag|comp|geom|tesc|tese");
  const std::string target_name = default_target(a, o.lower.stage);
  const std::optional<Target> target = parse_target(target_name);
  if (!target) return input_error("unknown target '" + target_name + "'");
  if (*target == Target::Wgsl)
    return input_error("verify runs the lowered GLSL on lavapipe and Mesa GLES: --target wgsl is not verified here "
                       "(its WGSL is the es310 lowering printed as WGSL; verify --target es310, and see docs/web.md for "
                       "the WGSL accuracy tests on WebGPU)");
  o.lower.target = *target;
  for (const std::string& d : a.defines) {
    const size_t eq = d.find('=');
    o.lower.defines.emplace_back(d.substr(0, eq), eq == std::string::npos ? "1" : d.substr(eq + 1));
  }
  o.lower.include_dirs = a.include_dirs;
  if (std::string e = apply_mode_args(a.mode, a.mode_for, o.lower); !e.empty()) return input_error(e);
  o.samples = a.samples;
  o.seed = a.seed;
  o.min_bits = a.min_bits;
  if (a.backend == "vulkan") o.backends = {runner::Backend::Vulkan};
  else if (a.backend == "gles") o.backends = {runner::Backend::Gles};
  else if (a.backend == "webgl2") o.backends = {runner::Backend::WebGl2};
  else if (a.backend == "webgpu") o.backends = {runner::Backend::WebGpu};
  else if (a.backend == "all") o.backends = {runner::Backend::Vulkan, runner::Backend::Gles, runner::Backend::WebGl2};
  const std::optional<verify::Sabotage> sabotage = verify::parse_sabotage(a.sabotage);
  o.sabotage = sabotage.value_or(verify::Sabotage::None);
  if (!a.spec.empty()) {
    std::string text;
    if (std::string e = read_input_file(a.spec, text); !e.empty()) return input_error("cannot read spec '" + a.spec + "': " + e);
    if (std::string e = verify::parse_spec(text, &o.spec); !e.empty()) return input_error(a.spec + ": " + e);
  }
  for (const std::string& r : a.ranges) {
    std::string name;
    verify::InputSpec in;
    if (std::string e = verify::parse_range(r, &name, &in); !e.empty()) return input_error("--range: " + e);
    o.spec.inputs[name].lo = in.lo;
    o.spec.inputs[name].hi = in.hi;
  }
  plan::Scene scene;
  if (int rc = apply_scene_and_plan(a, &o, &scene); rc != kExitOk) return rc;
  std::string source;
  if (std::string e = read_input_file(a.shader, source); !e.empty()) return input_error("cannot read '" + a.shader + "': " + e);

  // With no threshold anywhere, a float-float mode is judged against the shader demoted to float,
  // so a collapse to float precision cannot pass (docs/verify.md, exit codes).
  const bool any_threshold = o.min_bits || !a.scene.empty() || o.lower.mode == Mode::Exact ||  // exact: identical bits
                             std::any_of(o.spec.outputs.begin(), o.spec.outputs.end(),
                                         [](const auto& out) { return out.second.min_bits.has_value(); });
  o.judge_against_float = !any_threshold;
  const verify::VerifyReport report = verify::verify(source, o);
  const bool json_to_stdout = a.json == "-";
  (json_to_stdout ? std::cerr : std::cout) << verify::format_table(report);
  if (json_to_stdout) std::cout << verify::to_json(report);
  else if (!a.json.empty()) {
    AtomicFile file;
    if (!file.prepare(a.json, verify::to_json(report)) || !file.commit())
      return input_error("cannot write '" + a.json + "': " + file.error());
  }
  if (!a.scene.empty()) (json_to_stdout ? std::cerr : std::cout) << scene_summary(report, scene);
  if (report.input_error.empty() && !any_threshold)
    std::cerr << "doublet verify: note: no accuracy threshold (--min-bits B, a spec's min_bits or --scene): "
                 "each output of a float-float mode must beat the shader demoted to float by "
              << int(verify::OutputStats::kBeyondFloatBits) << " median bits (docs/verify.md)\n";
  if (!report.input_error.empty()) return kExitInput;
  if (report.driver_failed()) return kExitDriver;
  return report.passed() ? kExitOk : kExitBelowMinBits;
}

}  // namespace

Command add_verify_command(CLI::App& app) {
  auto args = std::make_shared<VerifyArgs>();
  CLI::App* cmd = app.add_subcommand(
      "verify", "Run SHADER natively (fp64, lavapipe) and lowered (lavapipe / Mesa GLES / Chromium WebGL2); report accuracy per output");
  cmd->add_option("SHADER", args->shader, "shader file (.vert, .frag or .comp); not with --sweep");
  cmd->add_option("--sweep", args->sweep, "OP|all: per-operation sweep against MPFR (add sub mul div sqrt)");
  cmd->add_option("--stage", args->sweep_stage, "stage of the sweep (comp)");
  cmd->add_option("--heatmap-dir", args->heatmap_dir, "where --sweep writes its PNG heatmaps (default .)");
  cmd->add_option("--grid-step", args->grid_step, "exponent step of the sweep grid (default 1)")
      ->check(CLI::Range(1, 64));
  cmd->add_option("-S", args->stage, "stage: vert|frag|comp|geom|tesc|tese (default: from the extension)");
  cmd->add_option("--target", args->target, "target of the lowering (default es310; webgl2 for vert/frag with --backend webgl2/all)");
  cmd->add_option("--samples", args->samples, "input sets (default 1024)")->check(CLI::PositiveNumber);
  cmd->add_option("--seed", args->seed, "random seed (default 1)");
  cmd->add_option("--range", args->ranges, "NAME=LO:HI input range (repeatable)");
  cmd->add_option("--spec", args->spec, "JSON spec: input values/ranges, output thresholds (docs/verify.md)");
  cmd->add_option("--scene", args->scene, "scene JSON (docs/plan.md): sample its ranges, fail above its abs_error");
  cmd->add_option("--plan", args->plan, "lower with this plan file from `doublet plan` (docs/plan.md)");
  cmd->add_option("--json", args->json, "write the report as JSON to this file ('-': stdout)");
  cmd->add_option("--min-bits", args->min_bits, "exit 1 when any output keeps fewer correct bits");
  cmd->add_option("--backend", args->backend,
                  "vulkan|gles|webgl2|webgpu|both|all: where the lowered shader runs (both = vulkan + gles, the "
                  "default; all = vulkan + gles + webgl2; webgl2 = headless Chromium's WebGL2 (vert/frag); webgpu "
                  "= the WGSL lowering in headless Chromium's WebGPU (comp))")
      ->check(CLI::IsMember({"vulkan", "gles", "webgl2", "webgpu", "both", "all"}));
  cmd->add_option("--sabotage", args->sabotage,
                  "drop-lo|drop-guard|ties-away: break the lowering on purpose (ties-away: mode exact rounds ties "
                  "away from zero)")
      ->check(CLI::IsMember({"none", "drop-lo", "drop-guard", "ties-away"}));
  cmd->add_option("-D", args->defines, "NAME[=VALUE] preprocessor define");
  cmd->add_option("-I", args->include_dirs, "include directory");
  cmd->add_option("--mode", args->mode, "precision mode of the lowering: fp32|rte|df64-fast|df64|df64-int (default df64)");
  cmd->add_option("--mode-for", args->mode_for, "NAME=MODE per global, function or FUNCTION.LOCAL (repeatable)");
  cmd->footer("Exit status: 0 pass, 1 an output below its min bits (--mode exact: any output whose bits differ), 2 input "
              "error, 3 driver failure.");
  return Command{cmd, [args] { return run_verify(*args); }};
}

}  // namespace doublet::cli

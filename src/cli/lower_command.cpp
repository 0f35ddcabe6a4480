// `doublet lower IN... [-o OUT | --out-dir DIR] ...`: lower shaders and write the results
// (and optionally manifests and depfiles). One input goes to -o (or stdout); several go to
// --out-dir, lowered in parallel. Outputs are replaced atomically and only when the
// shader lowered without errors.
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <optional>
#include <memory>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

#include <CLI/CLI.hpp>

#include "commands.hpp"
#include "diagnostic_printer.hpp"
#include "doublet/doublet.hpp"
#include "input_file.hpp"
#include "job_runner.hpp"
#include "lower_job.hpp"
#include "output_paths.hpp"
#include "plan/planner.hpp"
#include "mode_args.hpp"

namespace doublet::cli {
namespace {
namespace fs = std::filesystem;

constexpr Target kAllTargets[] = {Target::Es100,   Target::Es300,   Target::Es310,  Target::Es320,
                                  Target::Glsl330, Target::Glsl450, Target::Webgl2, Target::Wgsl};

std::string target_names(std::string_view sep) {
  std::string s;
  for (Target t : kAllTargets) {
    if (!s.empty()) s += sep;
    s += to_string(t);
  }
  return s;
}

bool is_identifier_char(char c) {
  return c == '_' || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
}

bool is_identifier_tail(std::string_view s) {
  if (s.empty()) return false;
  for (char c : s)
    if (!is_identifier_char(c)) return false;
  return true;
}

bool is_identifier(std::string_view s) { return is_identifier_tail(s) && !(s[0] >= '0' && s[0] <= '9'); }

struct LowerArgs {
  std::vector<std::string> inputs;
  std::string output;  // empty or "-": stdout
  std::string out_dir;
  std::string plan;  // --plan FILE from `doublet plan` (docs/plan.md)
  unsigned jobs = 0;   // 0: one per core
  std::string stage;
  std::string target = "es300";
  std::vector<std::string> defines;
  std::vector<std::string> include_dirs;
  std::vector<std::string> warnings;  // -Wno-NAME, -WNAME, -Werror, in order
  std::string manifest;
  bool depfile = false;         // -MD
  std::string depfile_path;     // -MF
  std::string depfile_target;   // -MT
  std::string guard = "auto";
  std::string hi_suffix = "_hi";
  std::string lo_suffix = "_lo";
  std::string color = "auto";
  bool constant_range_errors = false;
  bool no_optimize = false;           // -O0
  bool inline_exact_calls = false;
  std::string stop_after;             // --stop-after PASS
  std::string mode;                   // --mode (empty: df64)
  std::vector<std::string> mode_for;  // --mode-for NAME=MODE
};

// -Wno-NAME silences lint NAME ("all": every lint), -WNAME turns it back on, -Werror makes
// lint warnings errors; a later flag wins over an earlier one.
template <typename Problem>
void apply_warning_flags(const std::vector<std::string>& flags, Options& opt, Problem&& problem) {
  std::vector<std::string_view> known = lint_names();
  std::vector<std::string_view> on = known;
  for (const std::string& flag : flags) {
    const bool negated = flag.rfind("no-", 0) == 0;
    const std::string name = negated ? flag.substr(3) : flag;
    if (name == "error") {
      opt.lint_errors = !negated;
    } else if (name == "all") {
      on = negated ? std::vector<std::string_view>{} : known;
    } else if (std::find(known.begin(), known.end(), name) != known.end()) {
      std::erase(on, name);
      if (!negated) on.push_back(*std::find(known.begin(), known.end(), name));
    } else {
      std::string list;
      for (std::string_view k : known) list += std::string(k) + ", ";
      problem("-W" + flag + ": unknown warning (expected -Wno-NAME or -WNAME with NAME one of " + list +
              "all; or -Werror)");
    }
  }
  for (std::string_view k : known)
    if (std::find(on.begin(), on.end(), k) == on.end()) opt.disabled_lints.emplace_back(k);
}

// Options shared by every input; the usage error, if any, in `error`.
Options common_options(const LowerArgs& a, std::string& error) {
  auto problem = [&](std::string message) {  // the first problem is reported
    if (error.empty()) error = std::move(message);
  };
  Options opt;
  if (auto t = parse_target(a.target))
    opt.target = *t;
  else
    problem("unknown target '" + a.target + "' (expected one of " + target_names(", ") + ")");
  if (!a.stage.empty()) {
    opt.stage = parse_stage(a.stage);
    if (!opt.stage) problem("unknown stage '" + a.stage + "' (expected vert, frag or comp)");
  }
  for (const std::string& d : a.defines) {
    auto eq = d.find('=');
    std::string name = d.substr(0, eq);
    if (!is_identifier(name)) problem("-D: '" + name + "' is not a valid macro name");
    opt.defines.emplace_back(name, eq == std::string::npos ? std::string() : d.substr(eq + 1));
  }
  if (!is_identifier_tail(a.hi_suffix) || !is_identifier_tail(a.lo_suffix))
    problem("--hi-suffix/--lo-suffix must be non-empty and contain only letters, digits and _");
  else if (a.hi_suffix.find("__") != std::string::npos || a.lo_suffix.find("__") != std::string::npos)
    problem("--hi-suffix/--lo-suffix must not contain '__': GLSL reserves names with a double underscore");
  else if (a.hi_suffix == a.lo_suffix)
    problem("--hi-suffix and --lo-suffix must differ");
  opt.include_dirs = a.include_dirs;
  apply_warning_flags(a.warnings, opt, problem);
  opt.hi_suffix = a.hi_suffix;
  opt.lo_suffix = a.lo_suffix;
  opt.constant_range_errors = a.constant_range_errors;
  opt.optimize = !a.no_optimize;
  opt.share_exact_calls = !a.inline_exact_calls;
  opt.stop_after = a.stop_after;
  opt.guard = parse_guard(a.guard).value_or(GuardKind::Auto);  // CLI11 checked the name
  if (std::string mode_error = apply_mode_args(a.mode, a.mode_for, opt); !mode_error.empty()) problem(mode_error);
  return opt;
}

// The stage for `input`: -S, else from the file name. Empty string on success.
// A stage doublet does not lower is not a usage error: it goes to `refusal`, which the job reports
// as the file's diagnostic (exit 2).
std::string resolve_stage(const std::string& input, Options& opt, std::string& refusal) {
  if (opt.stage) return {};
  if (input == "-") return "reading the shader from stdin requires -S vert|frag|comp|geom|tesc|tese";
  opt.stage = stage_from_path(input);
  if (opt.stage) return {};
  // A stage doublet does not lower, named by glslang's extensions: say which, not "cannot tell"
  // (glslang's own test suite has 186 such files).
  static const std::pair<const char*, const char*> kOtherStages[] = {
      {".mesh", "a mesh shader"},
      {".task", "a task shader"},             {".rgen", "a ray generation shader"},
      {".rint", "a ray intersection shader"}, {".rahit", "an any-hit shader"},
      {".rchit", "a closest-hit shader"},     {".rmiss", "a miss shader"},
      {".rcall", "a callable shader"}};
  std::string name = input;
  if (name.size() > 5 && name.compare(name.size() - 5, 5, ".glsl") == 0) name.resize(name.size() - 5);
  for (const auto& [ext, what] : kOtherStages) {
    const size_t len = std::char_traits<char>::length(ext);
    if (name.size() > len && name.compare(name.size() - len, len, ext) == 0) {
      refusal = std::string("this is ") + what + ": doublet lowers vertex, fragment, compute, geometry and tessellation shaders only";
      return {};
    }
  }
  return "cannot tell the shader stage from the file name '" + input +
         "' (expected .vert, .frag, .comp, .geom, .tesc, .tese, optionally followed by .glsl); use -S";
}

// One input, output to -o FILE or stdout.
std::string plan_single(const LowerArgs& a, const Options& common, std::vector<LowerJob>& jobs) {
  LowerJob job;
  job.input = a.inputs.front();
  job.options = common;
  if (std::string e = resolve_stage(job.input, job.options, job.refusal); !e.empty()) return e;
  job.options.file_name = job.input == "-" ? "<stdin>" : job.input;
  job.output = a.output == "-" ? std::string() : a.output;
  job.manifest = a.manifest;
  if (job.manifest == "-" && job.output.empty())
    return "--manifest - needs -o FILE: the shader already goes to stdout";
  if (a.depfile || !a.depfile_path.empty()) {
    job.depfile = !a.depfile_path.empty() ? a.depfile_path : job.output.empty() ? "" : job.output + ".d";
    job.depfile_target = !a.depfile_target.empty() ? a.depfile_target : job.output;
    if (job.depfile.empty() || job.depfile_target.empty())
      return "-MD with the shader on stdout needs -MF FILE and -MT TARGET (the depfile names the output)";
  }
  jobs.push_back(std::move(job));
  return {};
}

// Inputs lowered into --out-dir: DIR/NAME, DIR/NAME.json and, with -MD, DIR/NAME.d.
std::string plan_batch(const LowerArgs& a, const Options& common, std::vector<LowerJob>& jobs) {
  if (a.out_dir.empty()) return "several inputs need --out-dir DIR";
  if (!a.output.empty()) return "-o and --out-dir cannot be combined (use --out-dir alone)";
  if (!a.manifest.empty()) return "--manifest is for one input; --out-dir writes DIR/NAME.json for each";
  if (!a.depfile_path.empty() || !a.depfile_target.empty())
    return "-MF/-MT are for one input; with --out-dir, -MD writes DIR/NAME.d for each";
  for (const std::string& input : a.inputs) {
    if (input == "-") return "stdin ('-') cannot be used with --out-dir";
    LowerJob job;
    job.input = input;
    job.options = common;
    job.options.file_name = input;
    if (std::string e = resolve_stage(input, job.options, job.refusal); !e.empty()) return e;
    std::string name = fs::path(input).filename().string();
    job.output = (fs::path(a.out_dir) / name).string();
    job.manifest = job.output + ".json";
    if (a.depfile) {
      job.depfile = job.output + ".d";
      job.depfile_target = job.output;
    }
    jobs.push_back(std::move(job));
  }
  return {};
}

// Every file the jobs would write, named for messages: -o/--manifest/-MF for one input,
// "the output 'DIR/NAME' of 'IN'" and so on for a batch.
std::vector<NamedFile> planned_outputs(const std::vector<LowerJob>& jobs, const LowerArgs& a, bool batch) {
  std::vector<NamedFile> outputs;
  for (const LowerJob& job : jobs) {
    auto add = [&](const std::string& path, const std::string& flag, const char* what) {
      outputs.push_back({path, batch ? std::string(what) + " '" + path + "' of '" + job.input + "'" : flag + " '" + path + "'"});
    };
    if (!job.output.empty()) add(job.output, "-o", "the output");
    if (!job.manifest.empty() && job.manifest != "-") add(job.manifest, "--manifest", "the manifest");
    if (!job.depfile.empty()) add(job.depfile, a.depfile_path.empty() ? "the depfile (-MD)" : "-MF", "the depfile");
  }
  return outputs;
}

// Refuses, before anything is written, outputs that are one file twice or that are an
// input: `-o x --manifest ./x`, -MF naming the input, --out-dir holding the inputs, two
// batch inputs whose outputs share a name (a.vert's manifest is a.vert.json).
std::string refuse_clobbering(const std::vector<LowerJob>& jobs, const LowerArgs& a, bool batch) {
  std::vector<NamedFile> inputs;
  for (const LowerJob& job : jobs)
    if (job.input != "-") inputs.push_back({job.input, "the input '" + job.input + "'"});
  if (!a.plan.empty()) inputs.push_back({a.plan, "the --plan file '" + a.plan + "'"});
  std::optional<FileClash> clash = find_file_clash(planned_outputs(jobs, a, batch), inputs);
  if (!clash) return {};
  if (clash->other_is_input)
    return clash->describe() + ": writing it would destroy the input; " +
           (batch ? "use an --out-dir that holds no input" : "name another output file");
  return clash->describe() + ": " +
         (batch ? "lower these inputs into different --out-dir directories" : "give each output its own name");
}

int run_lower(const CLI::App& cmd, const LowerArgs& a) {
  std::string error;
  Options common = common_options(a, error);
  if (!error.empty()) return usage_error(cmd, error);
  if (!a.plan.empty()) {  // the plan's modes first: --mode-for entries on the command line win
    std::string text;
    const std::string read_error = read_input_file(a.plan, text);
    Options from_plan;
    Diagnostic d{a.plan, 0, 0, Severity::Error, "cannot read the plan file: " + read_error};
    if (!read_error.empty() || !plan::load_plan(text, a.plan, &from_plan, &d)) {
      std::cerr << format_diagnostic(d) << "\n";
      return kExitInput;
    }
    merge_plan_modes(from_plan, common);
  }
  std::optional<ColorChoice> color = parse_color_choice(a.color);
  if (!color) return usage_error(cmd, "--color must be auto, always or never");

  std::vector<LowerJob> jobs;
  const bool batch = a.inputs.size() > 1 || !a.out_dir.empty();
  error = batch ? plan_batch(a, common, jobs) : plan_single(a, common, jobs);
  if (error.empty()) error = refuse_clobbering(jobs, a, batch);
  if (!error.empty()) return usage_error(cmd, error);

  const bool use_color = stderr_wants_color(*color);
  if (batch) {
    std::error_code ec;
    fs::create_directories(a.out_dir, ec);
    if (ec) {
      std::cerr << render_diagnostic(tool_error("cannot create '" + a.out_dir + "': " + ec.message()), use_color);
      return kExitInput;
    }
  }
  unsigned threads = a.jobs != 0 ? a.jobs : std::max(1u, std::thread::hardware_concurrency());
  return run_jobs(jobs, threads, use_color);
}

}  // namespace

Command add_lower_command(CLI::App& app) {
  auto args = std::make_shared<LowerArgs>();
  CLI::App* cmd = app.add_subcommand("lower", "Lower shaders that use doubles to float-float GLSL");
  cmd->footer(
      "Examples:\n"
      "  doublet lower globe.vert -o globe.es300.vert --manifest globe.json\n"
      "  doublet lower mandelbrot.frag --target es320 -o out/mandelbrot.frag -MD -MF out/mandelbrot.d\n"
      "  doublet lower shaders/*.vert shaders/*.comp --out-dir lowered -j 8 -MD\n"
      "      (writes lowered/NAME, lowered/NAME.json and lowered/NAME.d for each input)\n"
      "  cat shader.glsl | doublet lower - -S frag --target es320\n"
      "\n"
      "-MD writes a Make-style depfile listing the input and every #include'd file (as GCC\n"
      "does); -MF FILE names it (default: OUT.d) and implies -MD; -MT TARGET names the rule's\n"
      "target (default: OUT). Diagnostics are coloured on a terminal unless NO_COLOR is set.");

  cmd->add_option("IN", args->inputs, "Input shaders; '-' reads stdin (then -S is required)")
      ->required()
      ->type_name("FILE...");
  cmd->add_option("-o,--output", args->output, "Output file (one input); '-' or absent: stdout")->type_name("OUT");
  cmd->add_option("--out-dir", args->out_dir,
                  "Write DIR/NAME and DIR/NAME.json for each input (created if missing)")
      ->type_name("DIR");
  cmd->add_option("-j,--jobs", args->jobs, "Lower N shaders at a time (default: one per core)")
      ->type_name("N")
      ->check(CLI::PositiveNumber);
  cmd->add_option("-S,--stage", args->stage, "Shader stage: vert, frag or comp (default: from IN's extension)")
      ->type_name("STAGE");
  cmd->add_option("--target", args->target, "Output dialect: " + target_names("|") + " (default es300)")
      ->type_name("TARGET");
  cmd->add_option("-D,--define", args->defines, "Define a preprocessor macro (VALUE defaults to empty)")
      ->type_name("NAME[=VALUE]")
      ->allow_extra_args(false);
  cmd->add_option("-I,--include-dir", args->include_dirs, "Add a directory searched by #include")
      ->type_name("DIR")
      ->allow_extra_args(false);
  cmd->add_option("-W", args->warnings,
                  "-Wno-NAME silences a lint (float-literal, wasted-double, smooth-double-varying; all), "
                  "-WNAME turns it back on, -Werror makes lint warnings errors")
      ->type_name("no-NAME|NAME|error")
      ->allow_extra_args(false);
  cmd->add_option("--manifest", args->manifest, "Write the interface manifest (JSON) to FILE; '-' with -o FILE: stdout")
      ->type_name("FILE");
  cmd->add_flag("--MD", args->depfile, "(-MD) Write a depfile: OUT.d, or DIR/NAME.d with --out-dir");
  cmd->add_option("--MF", args->depfile_path, "(-MF FILE) Write the depfile to FILE (implies -MD)")->type_name("FILE");
  cmd->add_option("--plan", args->plan, "Apply a plan file from `doublet plan` (modes per declaration/function)")
      ->type_name("FILE");
  cmd->add_option("--MT", args->depfile_target, "(-MT TARGET) The depfile's target (default: OUT)")
      ->type_name("TARGET");
  cmd->add_option("--guard", args->guard,
                  "How error terms are protected from the driver's optimizer: auto (precise where the "
                  "target has it, else uniform), precise or uniform (default auto)")
      ->type_name("KIND")
      ->check(CLI::IsMember({"auto", "precise", "uniform"}));
  cmd->add_option("--hi-suffix", args->hi_suffix, "Suffix of the high part of split variables (default _hi)")
      ->type_name("S");
  cmd->add_option("--lo-suffix", args->lo_suffix, "Suffix of the low part of split variables (default _lo)")
      ->type_name("S");
  cmd->add_flag("--no-optimize", args->no_optimize,
                "(-O0) Skip the whole-shader optimizer: every double operation gets its general rule "
                "(docs/performance.md, optimize_df)");
  cmd->add_flag("--inline-exact-calls", args->inline_exact_calls,
                "Mode exact: inline every operation where it is called instead of sharing one call site per "
                "run of statements (runs faster, compiles slower; docs/performance.md, share_exact_calls)");
  {
    std::string passes;
    for (std::string_view p : pass_names()) passes += (passes.empty() ? "" : ", ") + std::string(p);
    cmd->add_option("--stop-after", args->stop_after,
                    "Stop after this pass and write the IR as it is then, not re-validated (docs/architecture.md); "
                    "the passes, in order: " + passes)
        ->type_name("PASS");
  }
  cmd->add_flag("--constant-range-errors", args->constant_range_errors,
                "Make double constants too small for float-float (e.g. 1e-300lf) errors, not warnings");
  cmd->add_option("--color", args->color, "Colour diagnostics: auto (terminal, no NO_COLOR), always, never")
      ->type_name("WHEN");
  cmd->add_option("--mode", args->mode,
                  "Precision mode (docs/modes.md): fp32, rte, df64-fast, df64, df64-int, native, exact or rte-exact "
                  "(default df64; df64-int needs ES 3.00+; native needs --target glsl450; exact: IEEE binary64 in "
                  "integer arithmetic, ES 3.00+; rte-exact: binary64 storage, float arithmetic, a - b exact and "
                  "rounded once to float, ES 3.00+)")
      ->type_name("MODE");
  cmd->add_option("--mode-for", args->mode_for,
                  "Mode of one global, function (all overloads) or FUNCTION.LOCAL, as '#pragma doublet "
                  "mode(MODE)' before its declaration (repeatable; a later one wins)")
      ->type_name("NAME=MODE");

  return {cmd, [cmd, args] { return run_lower(*cmd, *args); }};
}

}  // namespace doublet::cli

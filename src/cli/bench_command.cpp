// `doublet bench [SHADER]`: throughput per precision mode on lavapipe and Mesa GLES
// (docs/modes.md). The work is doublet::bench::run_bench(); this file maps the command line to
// BenchOptions and prints the Markdown table (and the JSON file with --json).
#include <algorithm>
#include <filesystem>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>

#include <CLI/CLI.hpp>

#include "atomic_file.hpp"
#include "bench/bench.hpp"
#include "bench/compile_time.hpp"
#include "bench/compiler.hpp"
#include "bench/handwritten.hpp"
#include "bench/plot.hpp"
#include "bench/transcendental_bench.hpp"
#include "bench/kernels.hpp"
#include "bench/peer_bench.hpp"
#include "bench/user_shader.hpp"
#include "commands.hpp"

namespace doublet::cli {
namespace {

struct BenchArgs {
  std::vector<std::string> include_dirs;
  std::string shader, ops = "all", modes = "all", backend = "both", target = "es320", json, plot;
  int elements = 16384, steps = 0, warmup = 2, reps = 7;
  bool handwritten = false, compiler = false, transcendentals = false, peer_luma = false, compile_time = false;
  int lines = 5000;
  std::string scaling;  // --compiler: comma list of further sizes
  std::vector<std::string> corpus;  // --compile-time: shader directories
  int mandelbrot_size = 128, mandelbrot_iterations = 1000;
  std::string peer_mesa_fp64;  // Mesa's float64.glsl: exact vs Mesa's soft-fp64
  int check_inputs = 1 << 16;
};

std::vector<std::string> split_commas(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, ',');)
    if (!item.empty()) out.push_back(item);
  return out;
}

int run_handwritten_command(const CLI::App& cmd, const BenchArgs& a, const std::string& command_line) {
  bench::HandwrittenOptions o;
  if (a.ops != "all") o.ops = split_commas(a.ops);
  for (const std::string& op : o.ops)
    if (std::find(bench::handwritten_ops().begin(), bench::handwritten_ops().end(), op) == bench::handwritten_ops().end())
      return usage_error(cmd, "unknown op '" + op + "' for --handwritten (add,sub,mul,div,sqrt,mulf,mandelbrot)");
  o.elements = a.elements;
  o.steps = a.steps ? a.steps : 1024;
  o.warmup = a.warmup;
  o.repetitions = a.reps;
  o.mandelbrot_size = a.mandelbrot_size;
  o.mandelbrot_iterations = a.mandelbrot_iterations;
  bench::HandwrittenReport report;
  report.command = command_line;
  std::string error;
  if (!bench::run_handwritten(o, &report, &error)) {
    std::cerr << "doublet bench: error: " << error << "\n";
    return kExitInput;
  }
  std::cout << bench::format_handwritten_markdown(report) << std::flush;
  for (const bench::HandwrittenRow& r : report.rows)
    if (!r.ok) return 3;
  return kExitOk;
}

// --backend vulkan or gles narrows the options' default (both).
void narrow_backends(const BenchArgs& a, std::vector<runner::Backend>* backends) {
  if (a.backend == "vulkan") *backends = {runner::Backend::Vulkan};
  else if (a.backend == "gles") *backends = {runner::Backend::Gles};
}

// --target for the compute kernels: es310, es320 or glsl450 (nullopt otherwise).
std::optional<Target> compute_target(const BenchArgs& a) {
  const std::optional<Target> t = parse_target(a.target);
  if (!t || (*t != Target::Es310 && *t != Target::Es320 && *t != Target::Glsl450)) return std::nullopt;
  return t;
}

int run_peer_command(const CLI::App& cmd, const BenchArgs& a, const std::string& command_line) {
  bench::PeerOptions o;
  o.peer_path = a.peer_mesa_fp64;
  if (a.ops != "all") o.ops = split_commas(a.ops);
  for (const std::string& op : o.ops)
    if (std::find(bench::peer_ops().begin(), bench::peer_ops().end(), op) == bench::peer_ops().end())
      return usage_error(cmd, "unknown op '" + op + "' for --peer-mesa-fp64 (add,sub,mul,div,sqrt)");
  narrow_backends(a, &o.backends);
  const std::optional<Target> target = parse_target(a.target);
  if (!target || (*target != Target::Es310 && *target != Target::Es320))
    return usage_error(cmd, "--target must be es310 or es320 with --peer-mesa-fp64 (both backends run it)");
  if (a.elements < 1 || a.steps < 0 || a.reps < 1 || a.warmup < 0 || a.check_inputs < 1)
    return usage_error(cmd, "--elements, --reps and --check-inputs must be at least 1, --steps and --warmup at least 0");
  o.target = *target;
  o.elements = a.elements;
  if (a.steps) o.steps = a.steps;
  o.warmup = a.warmup;
  o.repetitions = a.reps;
  o.check_inputs = a.check_inputs;
  bench::PeerReport report;
  report.command = command_line;
  std::string error;
  if (!bench::run_peer_bench(o, &report, &error)) {
    std::cerr << "doublet bench: error: " << error << "\n";
    return kExitInput;
  }
  std::cout << bench::format_peer_markdown(report) << std::flush;
  for (const bench::PeerTiming& t : report.timings)
    if (!t.ok && !t.not_applicable) return 3;
  for (const bench::PeerBits& b : report.bits)
    if (!b.ok) return 3;
  return kExitOk;
}

int run_compiler_command(const CLI::App& cmd, const BenchArgs& a, const std::string& command_line) {
  bench::CompilerOptions o;
  o.lines = a.lines;
  o.repetitions = a.reps;
  const std::optional<Target> target = compute_target(a);
  if (!target) return usage_error(cmd, "--target must be es310, es320 or glsl450 (compute shaders)");
  if (o.lines < 100) return usage_error(cmd, "--lines must be at least 100");
  for (const std::string& size : split_commas(a.scaling)) {
    const int lines = std::atoi(size.c_str());
    if (lines < 100 || lines > 1000000) return usage_error(cmd, "--scaling sizes must be 100 to 1000000 lines");
    o.scaling_lines.push_back(lines);
  }
  o.target = *target;
  bench::CompilerReport report;
  report.command = command_line;
  const bool ok = bench::run_compiler_bench(o, &report);
  std::cout << bench::format_compiler_markdown(report) << std::flush;
  return ok ? kExitOk : 3;
}

int run_transcendental_command(const CLI::App& cmd, const BenchArgs& a, const std::string& command_line) {
  bench::TranscendentalOptions o;
  if (a.ops != "all") o.functions = split_commas(a.ops);
  narrow_backends(a, &o.backends);
  const std::optional<Target> target = compute_target(a);
  if (!target) return usage_error(cmd, "--target must be es310, es320 or glsl450 (compute shaders)");
  o.target = *target;
  o.elements = a.elements;
  if (a.steps) o.steps = a.steps;
  o.warmup = a.warmup;
  o.repetitions = a.reps;
  o.peer_luma = a.peer_luma;
  bench::TranscendentalReport report;
  report.command = command_line;
  std::string error;
  if (!bench::run_transcendental_bench(o, &report, &error)) return usage_error(cmd, error);
  std::cout << bench::format_transcendental_markdown(report) << std::flush;
  for (const bench::TranscendentalRow& r : report.rows)
    if (!r.ok && !r.not_applicable && !(r.variant == bench::TranscendentalVariant::Luma && report.luma_version.empty()))
      return 3;  // a driver (or the lowering) failed
  return kExitOk;
}

std::string corpus_arguments(const BenchArgs& a) {
  std::string out;
  for (const std::string& dir : a.corpus) out += " --corpus " + dir;
  return out;
}

int run_compile_time_command(const CLI::App& cmd, const BenchArgs& a, const std::string& command_line) {
  bench::CompileTimeOptions o;
  if (a.ops != "all") {
    o.ops.clear();
    for (const std::string& n : split_commas(a.ops)) {
      const int ops = std::atoi(n.c_str());
      if (ops < 1 || ops > 4096) return usage_error(cmd, "--compile-time: --ops is a list of operation counts, 1 to 4096");
      o.ops.push_back(ops);
    }
  }
  if (a.modes != "all") {
    o.modes = split_commas(a.modes);
    for (const std::string& m : o.modes)
      if (m != "native" && !parse_mode(m)) return usage_error(cmd, "unknown mode '" + m + "'");
  }
  for (const std::string& dir : a.corpus)
    if (!std::filesystem::is_directory(dir)) return usage_error(cmd, "--corpus: '" + dir + "' is not a directory");
  o.corpus_dirs = a.corpus;
  if (!a.corpus.empty() && a.ops == "all") o.ops.clear();  // the corpus alone unless --ops asks for the series too
  narrow_backends(a, &o.backends);
  const std::optional<Target> target = compute_target(a);
  if (!target) return usage_error(cmd, "--target must be es310, es320 or glsl450 (compute shaders)");
  o.target = *target;
  o.rounds = cmd.count("--reps") ? std::max(1, a.reps) : 3;
  std::string devices;
  const std::vector<bench::CompileTimeRow> rows = bench::run_compile_time_bench(o, &devices);
  std::cout << bench::format_compile_time_markdown(o, rows, command_line, devices) << std::flush;
  for (const bench::CompileTimeRow& r : rows)
    if (!r.ok && !r.not_applicable) return 3;
  return kExitOk;
}

int run_bench_command(const CLI::App& cmd, const BenchArgs& a, const std::string& command_line) {
  if (a.compile_time) return run_compile_time_command(cmd, a, command_line);
  if (a.compiler) return run_compiler_command(cmd, a, command_line);
  if (a.transcendentals) return run_transcendental_command(cmd, a, command_line);
  if (a.handwritten) return run_handwritten_command(cmd, a, command_line);
  if (!a.peer_mesa_fp64.empty()) return run_peer_command(cmd, a, command_line);
  bench::BenchOptions o;
  if (a.ops == "all") {
    for (const bench::Kernel& k : bench::kernels()) o.ops.push_back(k.op);
  } else {
    o.ops = split_commas(a.ops);
    for (const std::string& op : o.ops)
      if (!bench::find_kernel(op)) return usage_error(cmd, "unknown op '" + op + "'");
  }
  if (a.modes == "all") {
    o.modes = bench::all_bench_modes();
  } else {
    o.modes.clear();
    for (const std::string& m : split_commas(a.modes)) {
      const std::optional<bench::Mode> mode = bench::parse_mode(m);
      if (!mode) return usage_error(cmd, "unknown mode '" + m + "' (fp32, rte, df64-fast, df64, native, exact)");
      o.modes.push_back(*mode);
    }
  }
  narrow_backends(a, &o.backends);
  const std::optional<Target> target = compute_target(a);
  if (!target) return usage_error(cmd, "--target must be es310, es320 or glsl450 (compute shaders)");
  o.target = *target;
  o.elements = a.elements;
  o.steps = a.steps;
  o.warmup = a.warmup;
  o.repetitions = a.reps;
  if (!a.shader.empty()) {
    std::string text, error;
    if (!bench::expand_includes(a.shader, a.include_dirs, &text, &error)) {
      std::cerr << "doublet bench: error: " << error << "\n";
      return kExitInput;
    }
    o.shader_path = a.shader;
    o.shader_source = bench::as_desktop_450(text);
  }
  bench::BenchReport report;
  report.command = command_line;
  std::string error;
  if (!bench::run_bench(o, &report, &error)) {
    std::cerr << "doublet bench: error: " << error << "\n";
    return kExitInput;
  }
  std::cout << bench::format_markdown(report) << std::flush;
  if (!a.json.empty()) {
    if (std::string e = write_file_atomically(a.json, bench::format_json(report)); !e.empty()) {
      std::cerr << "doublet bench: error: " << e << "\n";
      return kExitInput;
    }
  }
  if (!a.plot.empty()) {
    int points = 0;
    if (std::string e = bench::write_cost_plot(report, a.plot, &points); !e.empty()) {
      std::cerr << "doublet bench: error: " << e << "\n";
      return kExitInput;
    }
    std::cerr << "doublet bench: wrote " << a.plot << " (" << points << " points)\n";
  }
  for (const bench::Measurement& r : report.rows)
    if (!r.ok && !r.not_applicable) return 3;  // a driver (or the lowering) failed
  return kExitOk;
}

}  // namespace

Command add_bench_command(CLI::App& app) {
  auto args = std::make_shared<BenchArgs>();
  CLI::App* cmd = app.add_subcommand("bench", "Measure throughput per precision mode (fp32, df64, native fp64)");
  cmd->add_option("SHADER", args->shader, "a #version 450 compute shader with doubles (default: per-op kernels)");
  cmd->add_option("-I", args->include_dirs, "include directory for SHADER's #include \"...\"");
  cmd->add_option("--ops", args->ops, "all, or a comma list of add,sub,mul,div,sqrt,add3,dot3,length3,mat4");
  cmd->add_option("--modes", args->modes, "all, or a comma list of fp32,rte,df64-fast,df64,df64-int,native,exact (the compiler's --mode; all = every mode but exact)");
  cmd->add_option("--backend", args->backend, "vulkan|gles|both")->check(CLI::IsMember({"vulkan", "gles", "both"}));
  cmd->add_option("--target", args->target, "df64 lowering target: es310 (uniform guard), es320 (precise), glsl450");
  cmd->add_option("--elements", args->elements, "invocations per dispatch (default 16384)");
  cmd->add_option("--steps", args->steps, "dependent operations per invocation, rounded up to a multiple of 8 (default: per op, docs/modes.md)");
  cmd->add_option("--warmup", args->warmup, "discarded dispatches before timing (default 2)");
  cmd->add_option("--reps", args->reps, "timed dispatches; the median is reported (default 7)");
  cmd->add_option("--json", args->json, "also write the results as JSON (keys: docs/modes.md)");
  cmd->add_option("--plot", args->plot, "also write a PNG of cost (time / fp32, log) against bits per mode (docs/performance.md)");
  cmd->add_flag("--compiler", args->compiler,
                "time doublet::lower against glslang's parse of the same generated shader (--lines, --reps, --target)");
  cmd->add_option("--lines", args->lines, "--compiler: lines of the generated shader (default 5000)");
  cmd->add_option("--scaling", args->scaling,
                  "--compiler: also time these sizes in lines, e.g. 1000,10000,100000 (per phase and per line)");
  cmd->add_flag("--handwritten", args->handwritten,
                "compare with a hand-written float-float library on Mesa GLES (ops add,sub,mul,div,sqrt,mulf,mandelbrot; "
                "docs/performance.md)");
  cmd->add_option("--peer-mesa-fp64", args->peer_mesa_fp64,
                  "mode exact against Mesa's soft-fp64 GLSL FILE (float64.glsl; scripts/fetch-mesa-fp64), native fp64 "
                  "and fp32: time and bit identity per op (add,sub,mul,div,sqrt; docs/modes.md)");
  cmd->add_option("--check-inputs", args->check_inputs, "--peer-mesa-fp64: inputs of the bit-identity check per op (default 65536)");
  cmd->add_flag("--transcendentals", args->transcendentals,
                "exp,log,sin,cos,tan (--ops): fp32 built-ins, df64 rules and the same algorithms in native fp64, "
                "time per call and bits (docs/transcendentals.md)");
  cmd->add_flag("--peer-luma", args->peer_luma,
                "--transcendentals: also luma.gl's fp64 module (npm @luma.gl/shadertools, tools/peers)");
  cmd->add_flag("--compile-time", args->compile_time,
                "time from shader text to first result on lavapipe and Mesa GLES per mode, for a loop series of "
                "--ops N,... double operations per iteration (default 1,2,4,...,64; --reps rounds, default 3 here; "
                "docs/performance.md; the browser's share: tools/browser/compile-time-suite.mjs)");
  cmd->add_option("--corpus", args->corpus,
                  "--compile-time: also time every shader of DIR (fed as verify feeds it, DIR/x.json its spec, "
                  "DIR/include its headers); only these unless --ops is given");
  cmd->add_option("--mandelbrot-size", args->mandelbrot_size, "--handwritten: pixels per side (default 128)");
  cmd->add_option("--mandelbrot-iterations", args->mandelbrot_iterations, "--handwritten: iteration limit (default 1000)");
  return {cmd, [cmd, args] {
            // The full command with every default spelled out, so the docs can quote it as run.
            const BenchArgs& a = *args;
            if (a.compile_time)
              return run_bench_command(*cmd, a,
                                       "doublet bench --compile-time" + corpus_arguments(a) +
                                           (!a.corpus.empty() && a.ops == "all" ? "" : " --ops " + a.ops) + " --modes " + a.modes +
                                           " --backend " + a.backend + " --target " + a.target + " --reps " +
                                           std::to_string(cmd->count("--reps") ? a.reps : 3));
            if (a.compiler)
              return run_bench_command(*cmd, a,
                                       "doublet bench --compiler --lines " + std::to_string(a.lines) + " --reps " +
                                           std::to_string(a.reps) + " --target " + a.target +
                                           (a.scaling.empty() ? "" : " --scaling " + a.scaling));
            if (a.transcendentals)
              return run_bench_command(*cmd, a,
                                       "doublet bench --transcendentals" + std::string(a.peer_luma ? " --peer-luma" : "") +
                                           " --ops " + a.ops + " --backend " + a.backend + " --target " + a.target +
                                           " --elements " + std::to_string(a.elements) + " --steps " +
                                           std::to_string(a.steps ? a.steps : 256) + " --warmup " +
                                           std::to_string(a.warmup) + " --reps " + std::to_string(a.reps));
            if (a.handwritten)
              return run_bench_command(*cmd, a,
                                       "doublet bench --handwritten --ops " + a.ops + " --elements " +
                                           std::to_string(a.elements) + " --steps " + std::to_string(a.steps ? a.steps : 1024) +
                                           " --warmup " + std::to_string(a.warmup) + " --reps " + std::to_string(a.reps) +
                                           " --mandelbrot-size " + std::to_string(a.mandelbrot_size) +
                                           " --mandelbrot-iterations " + std::to_string(a.mandelbrot_iterations));
            if (!a.peer_mesa_fp64.empty())
              return run_bench_command(*cmd, a,
                                       "doublet bench --peer-mesa-fp64 " + a.peer_mesa_fp64 + " --ops " + a.ops +
                                           " --backend " + a.backend + " --target " + a.target + " --elements " +
                                           std::to_string(a.elements) + " --steps " + std::to_string(a.steps ? a.steps : 512) +
                                           " --warmup " + std::to_string(a.warmup) + " --reps " + std::to_string(a.reps) +
                                           " --check-inputs " + std::to_string(a.check_inputs));
            std::string line = "doublet bench" + (a.shader.empty() ? "" : " " + a.shader) + " --ops " + a.ops +
                               " --modes " + a.modes + " --backend " + a.backend + " --target " + a.target +
                               " --elements " + std::to_string(a.elements) +
                               (a.steps ? " --steps " + std::to_string(a.steps) : std::string()) +
                               " --warmup " + std::to_string(a.warmup) + " --reps " + std::to_string(a.reps);
            return run_bench_command(*cmd, a, line);
          }};
}

}  // namespace doublet::cli

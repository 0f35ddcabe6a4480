// doublet-difftest: generated double programs through the oracles of oracles.hpp (scripts/fuzz --diff;
// docs/robustness.md, "Differential testing").
//   doublet-difftest run --seconds N [--seed S] [--out DIR] [--samples N] [--no-reduce] [--webgpu]
//   doublet-difftest print SEED          the program (and its spec) a seed makes
//   doublet-difftest check FILE...       every oracle on saved programs (FILE.comp/.vert/.frag, spec:
//                                        FILE.json); exit 1 on a finding
//   doublet-difftest reduce FILE --oracle NAME
// `run` ends after N seconds (a reduction in progress finishes first) and prints as its last line
//   programs: P, failures: F, oracles: exact=.. int=.. bound=.. guard=.. targets=..
// with the programs each oracle checked; exit 1 when F > 0.
#include <CLI/CLI.hpp>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>

#include "difftest/generator.hpp"
#include "difftest/oracles.hpp"
#include "difftest/reduce.hpp"

namespace fs = std::filesystem;
using namespace doublet::difftest;

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

bool read_file(const fs::path& path, std::string* out) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::ostringstream s;
  s << in.rdbuf();
  *out = s.str();
  return true;
}

bool write_file(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  return static_cast<bool>(out);
}

fs::path spec_path(const fs::path& program) { return fs::path(program).replace_extension(".json"); }
std::string stage_of(const fs::path& program) { return program.extension().string().substr(1); }

void print_findings(const CheckResult& r) {
  for (const std::string& n : r.notes) std::cout << "  note: " << n << "\n";
  for (const Finding& f : r.findings) std::cout << "  [" << f.oracle << "] " << f.detail << "\n";
}

struct RunArgs {
  double seconds = 60, reduce_seconds = 600, program_seconds = 90;
  uint64_t seed = 1, samples = 256;
  std::string out = "build/difftest";
  bool reduce = true, webgpu = false;
  std::vector<std::string> skip_passes;
};

int run(const RunArgs& a) {
  const auto start = Clock::now();
  fs::create_directories(a.out);
  std::map<std::string, uint64_t> checked;
  std::set<std::string> covered;
  uint64_t programs = 0, failures = 0, invalid = 0, excused = 0, excused_int = 0, timeouts = 0;
  for (uint64_t seed = a.seed; seconds_since(start) < a.seconds; ++seed) {
    const Program p = generate(seed);
    CheckOptions options;
    options.samples = a.samples;
    options.skip_exact = uses_native_non_ieee(p);
    options.webgpu = a.webgpu;
    options.skip_passes = a.skip_passes;
    bool timed_out = false;
    const CheckResult r = check_in_child(p.glsl, p.spec_json, p.stage, options, a.program_seconds, &timed_out);
    ++programs;
    if (timed_out) {
      // A driver that does not finish compiling is not doublet's finding; it is counted and shown.
      ++timeouts;
      std::cout << "seed " << seed << ": no result within " << a.program_seconds << " s (a driver's compiler, or a crash); skipped\n";
      continue;
    }
    covered.insert(p.features.begin(), p.features.end());
    for (const std::string& o : r.checked) ++checked[o];
    excused += r.excused_zero_signs;
    excused_int += r.excused_int_zero_signs;
    if (!r.invalid.empty()) {
      ++invalid;
      std::cout << "seed " << seed << ": the generated program is invalid (a generator bug):\n" << r.invalid << "\n";
      write_file(fs::path(a.out) / ("invalid-" + std::to_string(seed) + "." + p.stage), p.glsl);
      continue;
    }
    double spent = 0;
    for (const auto& timing : r.seconds) spent += timing.second;
    std::cout << "seed " << seed << ": " << (r.findings.empty() ? "ok" : "FAIL") << " (";
    for (size_t i = 0; i < r.checked.size(); ++i) std::cout << (i ? " " : "") << r.checked[i];
    std::cout << "; " << static_cast<int>(spent + 0.5) << " s)\n";
    if (r.findings.empty()) {
      print_findings(r);  // its notes
      continue;
    }
    ++failures;
    const fs::path base = fs::path(a.out) / ("finding-" + std::to_string(seed));
    write_file(base.string() + "." + p.stage, p.glsl);
    write_file(base.string() + ".json", p.spec_json);
    std::cout << "seed " << seed << ": " << r.findings.size() << " finding(s), program " << base.string() << "." << p.stage
              << "\n";
    print_findings(r);
    if (!a.reduce) continue;
    const auto reduce_start = Clock::now();
    CheckOptions reduce_options = options;
    reduce_options.samples = std::min<uint64_t>(a.samples, 128);
    const Reduction red = reduce(p.glsl, p.spec_json, p.stage, r.findings.front().oracle, reduce_options, a.reduce_seconds, [&](const std::string& s) {
      std::cout << "  reducing: " << s << " (" << static_cast<int>(seconds_since(reduce_start)) << " s)\n" << std::flush;
    });
    write_file(base.string() + ".reduced." + p.stage, red.program);
    write_file(base.string() + ".reduced.json", p.spec_json);
    std::cout << "  reduced in " << red.checks << " checks, " << static_cast<int>(seconds_since(reduce_start))
              << " s: " << base.string() << ".reduced." << p.stage << "\n  [" << red.finding.oracle << "] " << red.finding.detail << "\n";
  }
  const double minutes = seconds_since(start) / 60;
  size_t known = 0;
  for (const std::string& f : all_features()) known += covered.count(f);
  std::cout << "coverage: " << known << " of " << all_features().size() << " operators, built-ins and statement kinds ("
            << (100 * known / all_features().size()) << "%)";
  std::string missing;
  for (const std::string& f : all_features())
    if (!covered.count(f)) missing += " " + f;
  if (!missing.empty()) std::cout << "; not reached:" << missing;
  std::cout << "\nthroughput: " << static_cast<double>(programs) / std::max(minutes, 1e-9) << " programs per minute\n";
  if (invalid) std::cout << "invalid programs (generator bugs): " << invalid << "\n";
  if (timeouts) std::cout << "programs without a result in time (skipped): " << timeouts << "\n";
  if (excused) std::cout << "exact: " << excused << " result(s) were zeros of the other sign than native's (excused)\n";
  if (excused_int)
    std::cout << "int: " << excused_int << " result(s) were zeros of the other sign than df64's (excused)\n";
  std::cout << "programs: " << programs << ", failures: " << failures + invalid << ", oracles: exact=" << checked["exact"]
            << " int=" << checked["int"] << " bound=" << checked["bound"] << " guard=" << checked["guard"]
            << " targets=" << checked["targets"] << std::endl;
  return failures + invalid > 0 ? 1 : 0;
}

int check_files(const std::vector<std::string>& files, uint64_t samples, bool webgpu,
                const std::vector<std::string>& skip_passes) {
  int status = 0;
  for (const std::string& file : files) {
    std::string glsl, spec;
    if (!read_file(file, &glsl) || !read_file(spec_path(file), &spec)) {
      std::cerr << file << ": error: cannot read the program or its spec " << spec_path(file).string() << "\n";
      return 2;
    }
    CheckOptions options;
    options.samples = samples;
    options.webgpu = webgpu;
    options.skip_passes = skip_passes;
    bool timed_out = false;
    const CheckResult r = check_in_child(glsl, spec, stage_of(file), options, 600, &timed_out);
    if (timed_out) {
      std::cout << file << ": no result within 600 s\n";
      status = std::max(status, 1);
      continue;
    }
    if (!r.invalid.empty()) {
      std::cout << file << ": invalid program: " << r.invalid << "\n";
      status = std::max(status, 2);
      continue;
    }
    std::cout << file << ": " << (r.findings.empty() ? "ok" : "FAIL") << " (oracles:";
    for (const std::string& o : r.checked) std::cout << " " << o;
    std::cout << ")";
    if (r.excused_zero_signs) std::cout << "; exact: " << r.excused_zero_signs << " zeros of native's other sign excused";
    if (r.excused_int_zero_signs) std::cout << "; int: " << r.excused_int_zero_signs << " zeros of df64's other sign excused";
    for (const auto& [what, s] : r.seconds) std::cout << "; " << what << " " << static_cast<int>(s * 1000) << " ms";
    std::cout << "\n";
    print_findings(r);
    if (!r.findings.empty()) status = std::max(status, 1);
  }
  return status;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"doublet-difftest: differential testing of doublet's lowering"};
  app.require_subcommand(1);
  RunArgs run_args;
  CLI::App* run_cmd = app.add_subcommand("run", "generate programs and check them for --seconds");
  run_cmd->add_option("--seconds", run_args.seconds, "time budget");
  run_cmd->add_option("--seed", run_args.seed, "first seed (each program takes the next)");
  run_cmd->add_option("--samples", run_args.samples, "inputs per program");
  run_cmd->add_option("--out", run_args.out, "where findings are written");
  run_cmd->add_option("--reduce-seconds", run_args.reduce_seconds, "time for reducing one finding");
  run_cmd->add_option("--program-seconds", run_args.program_seconds, "time one program's checks may take");
  bool no_reduce = false;
  run_cmd->add_flag("--no-reduce", no_reduce, "keep findings as generated");
  run_cmd->add_flag("--webgpu", run_args.webgpu, "also compare the wgsl lowering in Chromium's WebGPU");
  run_cmd->add_option("--skip-pass", run_args.skip_passes,
                      "leave a pass out of every lowering (a bug put back on purpose, to see it found)");

  uint64_t print_seed = 1;
  CLI::App* print_cmd = app.add_subcommand("print", "print the program a seed makes, then its spec");
  print_cmd->add_option("seed", print_seed)->required();

  std::vector<std::string> files;
  uint64_t samples = 256;
  bool webgpu = false;
  CLI::App* check_cmd = app.add_subcommand("check", "run every oracle on saved programs (FILE.comp/.vert/.frag with FILE.json)");
  check_cmd->add_option("files", files)->required();
  check_cmd->add_option("--samples", samples);
  check_cmd->add_flag("--webgpu", webgpu);
  std::vector<std::string> check_skip_passes;
  check_cmd->add_option("--skip-pass", check_skip_passes, "leave a pass out of every lowering (to see a case fail without its fix)");

  std::string reduce_file, oracle = "exact";
  CLI::App* reduce_cmd = app.add_subcommand("reduce", "reduce a saved program while an oracle still fails on it");
  reduce_cmd->add_option("file", reduce_file)->required();
  reduce_cmd->add_option("--oracle", oracle, "exact, int, bound, guard, targets or lowering");

  CLI11_PARSE(app, argc, argv);
  std::cout << std::unitbuf;  // progress is seen as it happens, also through a pipe
  run_args.reduce = !no_reduce;
  if (run_cmd->parsed()) return run(run_args);
  if (print_cmd->parsed()) {
    const Program p = generate(print_seed);
    std::cout << "// stage: " << p.stage << "\n// features:";
    for (const std::string& f : p.features) std::cout << " " << f;
    std::cout << "\n" << p.glsl << "// spec:\n" << p.spec_json;
    return 0;
  }
  if (check_cmd->parsed()) return check_files(files, samples, webgpu, check_skip_passes);
  std::string glsl, spec;
  if (!read_file(reduce_file, &glsl) || !read_file(spec_path(reduce_file), &spec)) {
    std::cerr << reduce_file << ": error: cannot read the program or its spec\n";
    return 2;
  }
  const Reduction r = reduce(glsl, spec, stage_of(reduce_file), oracle, CheckOptions{}, 600, [](const std::string& s) { std::cout << s << "\n"; });
  std::cout << r.program << "// " << r.checks << " checks; [" << r.finding.oracle << "] " << r.finding.detail << "\n";
  return 0;
}

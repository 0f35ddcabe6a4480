// `doublet lower IN [-o OUT] ...`: lower one shader and write the result (and
// optionally its interface manifest). Outputs are replaced atomically and only
// when the whole run succeeds.
#include <cerrno>
#include <cstring>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <CLI/CLI.hpp>

#include "atomic_file.hpp"
#include "commands.hpp"
#include "doublet/doublet.hpp"

namespace doublet::cli {
namespace {

constexpr Target kAllTargets[] = {Target::Es100, Target::Es300,   Target::Es310,
                                  Target::Es320, Target::Glsl330, Target::Glsl450};

std::string target_names(std::string_view sep) {
  std::string s;
  for (Target t : kAllTargets) {
    if (!s.empty()) s += sep;
    s += to_string(t);
  }
  return s;
}

bool is_identifier(std::string_view s) {
  if (s.empty() || (s[0] >= '0' && s[0] <= '9')) return false;
  for (char c : s)
    if (!(c == '_' || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9')))
      return false;
  return true;
}

bool is_identifier_tail(std::string_view s) {
  if (s.empty()) return false;
  for (char c : s)
    if (!(c == '_' || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9')))
      return false;
  return true;
}

struct LowerArgs {
  std::string input;
  std::string output;  // empty or "-": stdout
  std::string stage;
  std::string target = "es300";
  std::vector<std::string> defines;
  std::vector<std::string> include_dirs;
  std::string manifest;
  std::string guard = "auto";
  std::string hi_suffix = "_hi";
  std::string lo_suffix = "_lo";
};

// Reads a whole file (or stdin for fd 0). Returns errno on failure.
int read_fd(int fd, std::string& out) {
  struct stat st {};
  if (::fstat(fd, &st) == 0 && S_ISDIR(st.st_mode)) return EISDIR;
  char buf[1 << 16];
  for (;;) {
    ssize_t n = ::read(fd, buf, sizeof buf);
    if (n == 0) return 0;
    if (n < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    out.append(buf, static_cast<size_t>(n));
  }
}

int read_input(const std::string& path, std::string& out) {
  if (path == "-") return read_fd(STDIN_FILENO, out);
  int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return errno;
  int err = read_fd(fd, out);
  ::close(fd);
  return err;
}

void print_diagnostic(const Diagnostic& d) {
  std::string text = format_diagnostic(d);
  if (text.empty() || text.back() != '\n') text += '\n';
  std::cerr << text;
}

bool write_stdout(std::string_view text) {
  std::cout.write(text.data(), static_cast<std::streamsize>(text.size()));
  std::cout.flush();
  return static_cast<bool>(std::cout);
}

int run_lower(const CLI::App& cmd, const LowerArgs& a) {
  const bool from_stdin = a.input == "-";
  const bool out_to_stdout = a.output.empty() || a.output == "-";
  const bool manifest_to_stdout = a.manifest == "-";

  // --- Usage checks (exit 1) -------------------------------------------------
  Options opt;
  if (auto t = parse_target(a.target)) {
    opt.target = *t;
  } else {
    return usage_error(cmd, "unknown target '" + a.target + "' (expected one of " +
                                target_names(", ") + ")");
  }
  if (!a.stage.empty()) {
    opt.stage = parse_stage(a.stage);
    if (!opt.stage) return usage_error(cmd, "unknown stage '" + a.stage + "' (expected vert, frag or comp)");
  } else if (from_stdin) {
    return usage_error(cmd, "reading the shader from stdin requires -S vert|frag|comp");
  } else {
    opt.stage = stage_from_path(a.input);
    if (!opt.stage)
      return usage_error(cmd, "cannot tell the shader stage from the file name '" + a.input +
                                  "' (expected .vert, .frag, .comp, optionally followed by .glsl); use -S");
  }
  if (manifest_to_stdout && out_to_stdout)
    return usage_error(cmd, "--manifest - needs -o FILE: the shader already goes to stdout");
  if (!out_to_stdout && !a.manifest.empty() && !manifest_to_stdout && a.manifest == a.output)
    return usage_error(cmd, "-o and --manifest name the same file");
  for (const std::string& d : a.defines) {
    auto eq = d.find('=');
    std::string name = d.substr(0, eq);
    if (!is_identifier(name)) return usage_error(cmd, "-D: '" + name + "' is not a valid macro name");
    opt.defines.emplace_back(name, eq == std::string::npos ? std::string() : d.substr(eq + 1));
  }
  if (!is_identifier_tail(a.hi_suffix) || !is_identifier_tail(a.lo_suffix))
    return usage_error(cmd, "--hi-suffix/--lo-suffix must be non-empty and contain only letters, digits and _");
  if (a.hi_suffix == a.lo_suffix) return usage_error(cmd, "--hi-suffix and --lo-suffix must differ");

  opt.file_name = from_stdin ? "<stdin>" : a.input;
  opt.include_dirs = a.include_dirs;
  opt.hi_suffix = a.hi_suffix;
  opt.lo_suffix = a.lo_suffix;
  opt.guard = a.guard == "precise"   ? GuardKind::Precise
              : a.guard == "uniform" ? GuardKind::Uniform
                                     : GuardKind::Auto;

  // --- Input (exit 2) --------------------------------------------------------
  std::string source;
  if (int err = read_input(a.input, source); err != 0) {
    print_diagnostic({opt.file_name, 0, 0, Severity::Error, std::string("cannot read file: ") + std::strerror(err)});
    return kExitInput;
  }

  Result result = lower(source, opt);
  bool has_error = !result.ok;
  for (const Diagnostic& d : result.diagnostics) {
    print_diagnostic(d);
    if (d.severity == Severity::Error) has_error = true;
  }
  if (has_error) {
    if (result.ok) std::cerr << "doublet: error: compilation reported errors; nothing written\n";
    return kExitInput;
  }

  // --- Output: all files prepared first, then renamed into place --------------
  std::string manifest_json;
  if (!a.manifest.empty()) {
    manifest_json = result.manifest.to_json();
    if (manifest_json.empty() || manifest_json.back() != '\n') manifest_json += '\n';
  }
  AtomicFile out_file, manifest_file;
  if (!out_to_stdout && !out_file.prepare(a.output, result.output)) {
    std::cerr << "doublet: error: " << out_file.error() << "\n";
    return kExitInput;
  }
  if (!a.manifest.empty() && !manifest_to_stdout && !manifest_file.prepare(a.manifest, manifest_json)) {
    std::cerr << "doublet: error: " << manifest_file.error() << "\n";
    return kExitInput;  // out_file's temporary is removed by its destructor
  }
  if (!out_to_stdout && !out_file.commit()) {
    std::cerr << "doublet: error: " << out_file.error() << "\n";
    return kExitInput;
  }
  if (!a.manifest.empty() && !manifest_to_stdout && !manifest_file.commit()) {
    std::cerr << "doublet: error: " << manifest_file.error() << "\n";
    return kExitInput;
  }
  if (out_to_stdout && !write_stdout(result.output)) {
    std::cerr << "doublet: error: cannot write to stdout\n";
    return kExitInput;
  }
  if (manifest_to_stdout && !write_stdout(manifest_json)) {
    std::cerr << "doublet: error: cannot write to stdout\n";
    return kExitInput;
  }
  return kExitOk;
}

}  // namespace

Command add_lower_command(CLI::App& app) {
  auto args = std::make_shared<LowerArgs>();
  CLI::App* cmd = app.add_subcommand("lower", "Lower a shader that uses doubles to float-float GLSL");
  cmd->footer(
      "Examples:\n"
      "  doublet lower examples/rte.vert -o rte.es300.vert --manifest rte.json\n"
      "  cat shader.glsl | doublet lower - -S frag --target es320");

  cmd->add_option("IN", args->input, "Input shader; '-' reads stdin (then -S is required)")
      ->required()
      ->type_name("FILE");
  cmd->add_option("-o,--output", args->output, "Output file; '-' or absent: stdout")->type_name("OUT");
  cmd->add_option("-S,--stage", args->stage,
                  "Shader stage: vert, frag or comp (default: from IN's extension)")
      ->type_name("STAGE");
  cmd->add_option("--target", args->target, "Output dialect: " + target_names("|") + " (default es300)")
      ->type_name("TARGET");
  cmd->add_option("-D,--define", args->defines, "Define a preprocessor macro (VALUE defaults to empty)")
      ->type_name("NAME[=VALUE]")
      ->allow_extra_args(false);
  cmd->add_option("-I,--include-dir", args->include_dirs, "Add a directory searched by #include")
      ->type_name("DIR")
      ->allow_extra_args(false);
  cmd->add_option("--manifest", args->manifest,
                  "Write the interface manifest (JSON) to FILE; '-' with -o FILE: stdout")
      ->type_name("FILE");
  cmd->add_option("--guard", args->guard,
                  "How error terms are protected from the driver's optimizer: auto (precise where the "
                  "target has it, else uniform), precise or uniform (default auto)")
      ->type_name("KIND")
      ->check(CLI::IsMember({"auto", "precise", "uniform"}));
  cmd->add_option("--hi-suffix", args->hi_suffix, "Suffix of the high part of split variables (default _hi)")
      ->type_name("S");
  cmd->add_option("--lo-suffix", args->lo_suffix, "Suffix of the low part of split variables (default _lo)")
      ->type_name("S");

  return {cmd, [cmd, args] { return run_lower(*cmd, *args); }};
}

}  // namespace doublet::cli

#include "diagnostic_printer.hpp"

#include <cstdlib>
#include <optional>

#include <unistd.h>

#ifdef __EMSCRIPTEN__
#include <emscripten.h>
#endif

namespace doublet::cli {
namespace {

constexpr std::string_view kBold = "\033[1m";
constexpr std::string_view kReset = "\033[0m";

std::string_view severity_color(Severity s) {
  switch (s) {
    case Severity::Error: return "\033[1;31m";
    case Severity::Warning: return "\033[1;35m";
    case Severity::Note: return "\033[1;36m";
  }
  return kBold;
}

std::string_view severity_tag(Severity s) {
  switch (s) {
    case Severity::Error: return "error:";
    case Severity::Warning: return "warning:";
    case Severity::Note: return "note:";
  }
  return "error:";
}

bool env_set_non_empty(const char* name) {
  const char* v = std::getenv(name);
  return v != nullptr && *v != '\0';
}

}  // namespace

std::optional<ColorChoice> parse_color_choice(std::string_view name) {
  if (name == "auto") return ColorChoice::Auto;
  if (name == "always") return ColorChoice::Always;
  if (name == "never") return ColorChoice::Never;
  return std::nullopt;
}

#ifdef __EMSCRIPTEN__
// The WebAssembly CLI (wasm/CMakeLists.txt): Emscripten's isatty() answers 1 for every standard
// stream; Node knows whether stderr is a terminal.
EM_JS(int, node_stderr_is_tty, (), {
  return typeof process === 'object' && process.stderr && process.stderr.isTTY ? 1 : 0;
});
#endif

bool stderr_wants_color(ColorChoice choice) {
  if (choice != ColorChoice::Auto) return choice == ColorChoice::Always;
  if (env_set_non_empty("NO_COLOR")) return false;
  const char* term = std::getenv("TERM");
  if (term != nullptr && std::string_view(term) == "dumb") return false;
#ifdef __EMSCRIPTEN__
  return node_stderr_is_tty() == 1;
#else
  return ::isatty(STDERR_FILENO) == 1;
#endif
}

std::string render_diagnostic(const Diagnostic& d, bool color) {
  std::string plain = format_diagnostic(d);
  if (!plain.empty() && plain.back() == '\n') plain.pop_back();
  if (!color) return plain + "\n";
  // format_diagnostic gives "<place>: <tag> <message>"; colour the place and the tag.
  std::string tag = std::string(": ") + std::string(severity_tag(d.severity)) + " ";
  size_t at = plain.find(tag, d.file.empty() ? 0 : d.file.size() - 1);
  if (at == std::string::npos) return plain + "\n";
  std::string out;
  out.append(kBold).append(plain, 0, at + 1).append(kReset).append(" ");
  out.append(severity_color(d.severity)).append(severity_tag(d.severity)).append(kReset).append(" ");
  out.append(plain, at + tag.size());
  return out + "\n";
}

Diagnostic tool_error(std::string message) { return {"doublet", 0, 0, Severity::Error, std::move(message)}; }

}  // namespace doublet::cli

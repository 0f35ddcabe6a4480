// Mode names and the per-mode shader text (see modes.hpp).
#include "demo/modes.hpp"
#include "frontend/demote.hpp"

#include <algorithm>
#include <regex>

namespace doublet::demo {

std::string_view mode_name(Mode m) {
  switch (m) {
    case Mode::Fp32: return "fp32";
    case Mode::Df64: return "df64";
    default: return "native";
  }
}

std::optional<Mode> parse_mode(std::string_view name) {
  for (Mode m : all_modes())
    if (mode_name(m) == name) return m;
  return std::nullopt;
}

std::vector<Mode> all_modes() { return {Mode::Fp32, Mode::Df64, Mode::Native}; }

bool parse_modes(const std::vector<std::string>& names, std::vector<Mode>* out, std::string* error) {
  out->clear();
  for (const std::string& n : names) {
    const std::optional<Mode> m = parse_mode(n);
    if (!m) {
      *error = "unknown mode '" + n + "' (available: fp32, df64, native; rte and df64-fast are not implemented yet)";
      return false;
    }
    if (std::find(out->begin(), out->end(), *m) == out->end()) out->push_back(*m);
  }
  if (out->empty()) *out = all_modes();
  return true;
}

bool shader_for_mode(Mode mode, std::string_view source, Stage stage, Target target, std::string* out,
                     std::string* error) {
  if (mode == Mode::Fp32) {
    *out = frontend::demote_doubles(source);
    return true;
  }
  if (mode == Mode::Native) {
    *out = std::regex_replace(std::string(source), std::regex(R"(#version[^\n]*)"), "#version 450",
                              std::regex_constants::format_first_only);
    return true;
  }
  Options o;
  o.stage = stage;
  o.target = target;
  o.file_name = "<demo>";
  const Result r = lower(source, o);
  if (!r.ok) {
    error->clear();
    for (const Diagnostic& d : r.diagnostics) *error += format_diagnostic(d) + "\n";
    return false;
  }
  *out = r.output;
  return true;
}

}  // namespace doublet::demo

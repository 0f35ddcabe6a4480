#include "bench/variants.hpp"

#include <algorithm>
#include <cctype>
#include <sstream>
#include <vector>

namespace doublet::bench {

const char* mode_name(Mode m) {
  switch (m) {
    case Mode::Fp32: return "fp32";
    case Mode::Rte: return "rte";
    case Mode::Df64Fast: return "df64-fast";
    case Mode::Df64: return "df64";
    case Mode::Df64Int: return "df64-int";
    case Mode::Native: return "native";
    case Mode::Exact: return "exact";
  }
  return "?";
}

const std::vector<Mode>& all_bench_modes() {
  static const std::vector<Mode> modes{Mode::Fp32, Mode::Rte, Mode::Df64Fast, Mode::Df64, Mode::Df64Int, Mode::Native};
  return modes;
}

std::optional<Mode> parse_mode(const std::string& s) {
  for (Mode m : all_bench_modes())
    if (s == mode_name(m)) return m;
  if (s == mode_name(Mode::Exact)) return Mode::Exact;
  return std::nullopt;
}

namespace {

// Replaces the `#version` line (desktop 450 → ES 3.20 with highp defaults).
std::string with_es_header(const std::string& source) {
  const size_t v = source.find("#version");
  if (v == std::string::npos) return source;
  const size_t eol = source.find('\n', v);
  return source.substr(0, v) + "#version 320 es\nprecision highp float;\nprecision highp int;\n" +
         (eol == std::string::npos ? "" : source.substr(eol + 1));
}
}  // namespace

Variant make_variant(Mode mode, runner::Backend backend, const std::string& source, Target target,
                     const std::string& file_name) {
  Variant v;
  if (mode == Mode::Native) {
    if (backend == runner::Backend::Gles) v.note = "GLES has no fp64", v.not_applicable = true;
    else v.glsl = source;
    return v;
  }
  if (backend == runner::Backend::Gles && !target_is_es(target)) {
    v.note = "desktop target " + std::string(to_string(target)) + " does not run on GLES";
    v.not_applicable = true;
    return v;
  }
  Options o;
  o.stage = Stage::Compute;
  o.target = target;
  o.file_name = file_name;
  o.mode = mode == Mode::Fp32     ? doublet::Mode::Fp32
           : mode == Mode::Rte    ? doublet::Mode::Rte
           : mode == Mode::Df64Fast ? doublet::Mode::Df64Fast
           : mode == Mode::Df64Int  ? doublet::Mode::Df64Int
           : mode == Mode::Exact  ? doublet::Mode::Exact
                                  : doublet::Mode::Df64;
  Result r = lower(source, o);
  if (r.ok) {
    v.glsl = std::move(r.output);
  } else {
    v.note = "doublet::lower --mode " + std::string(mode_name(mode)) + " failed:";
    for (const Diagnostic& d : r.diagnostics) v.note += " " + format_diagnostic(d) + ";";
  }
  return v;
}

ShaderSize shader_size(const std::string& glsl) {
  ShaderSize s;
  std::istringstream in(glsl);
  for (std::string line; std::getline(in, line);)
  {
    const size_t first = line.find_first_not_of(" \t\r");
    if (first != std::string::npos && line.compare(first, 2, "//") != 0) ++s.glsl_lines;  // code, not comments
  }
  std::vector<uint32_t> words;
  std::string error;
  if (runner::compile_compute_to_spirv(glsl, &words, &error))
    for (size_t i = 5; i < words.size(); i += std::max<uint32_t>(1, words[i] >> 16)) {
      const uint32_t op = words[i] & 0xffff;
      // Debug instructions (OpSource* / OpName / OpString / OpLine / OpNoLine / OpModuleProcessed) are not code.
      if (!((op >= 2 && op <= 8) || op == 317 || op == 330)) ++s.spirv_instructions;
    }
  return s;
}

}  // namespace doublet::bench

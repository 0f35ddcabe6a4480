// The JSON entry point of the WebAssembly compiler (wasm/CMakeLists.txt, docs/web.md "The compiler
// as WebAssembly"): js/src/compiler.mjs calls doublet_lower_json(source, options) and gets back
// {"ok", "output", "manifest", "diagnostics", "includedFiles"}. The options are doublet::Options
// spelled as the CLI spells them (target, mode, modeFor, defines, ...); #include is answered by the
// host's `doubletInclude(requested, includerPath)` callback, synchronously.
#include <cstdlib>
#include <cstring>
#include <optional>
#include <string>

#include <emscripten.h>
#include <nlohmann/json.hpp>

#include "doublet/doublet.hpp"

namespace {

using nlohmann::json;

// Calls Module.doubletInclude(requested, includerPath); returns a malloc'ed JSON string
// {"path","contents"} or 0 when the host has no callback or the file is not found.
EM_JS(char*, doublet_host_include, (const char* requested, const char* includer), {
  const callback = Module["doubletInclude"];
  if (!callback) return 0;
  const found = callback(UTF8ToString(requested), UTF8ToString(includer));
  if (found === null || found === undefined) return 0;
  const text = JSON.stringify({path: String(found.path), contents: String(found.contents)});
  const bytes = lengthBytesUTF8(text) + 1;
  const out = _malloc(bytes);
  stringToUTF8(text, out, bytes);
  return out;
});

class HostIncluder : public doublet::Includer {
 public:
  std::optional<doublet::IncludeResult> include(std::string_view requested, std::string_view includer_path) override {
    char* answer = doublet_host_include(std::string(requested).c_str(), std::string(includer_path).c_str());
    if (answer == nullptr) return std::nullopt;
    json found = json::parse(answer, nullptr, false);
    std::free(answer);
    if (!found.is_object()) return std::nullopt;
    return doublet::IncludeResult{found.value("path", std::string(requested)), found.value("contents", "")};
  }
};

const char* severity_name(doublet::Severity s) {
  switch (s) {
    case doublet::Severity::Error: return "error";
    case doublet::Severity::Warning: return "warning";
    case doublet::Severity::Note: return "note";
  }
  return "error";
}

// One diagnostic as the answer spells it, whether from the lowering or from the options.
json diagnostic_json(const doublet::Diagnostic& d) {
  return {{"file", d.file}, {"line", d.line}, {"column", d.column}, {"severity", severity_name(d.severity)},
          {"message", d.message}, {"text", doublet::format_diagnostic(d)}};
}

std::string option_error(const std::string& message) {
  const doublet::Diagnostic d{"", 0, 0, doublet::Severity::Error, message};
  return json{{"ok", false}, {"output", ""}, {"manifest", nullptr}, {"diagnostics", json::array({diagnostic_json(d)})},
              {"includedFiles", json::array()}}.dump();
}

// Reads the options; returns an error message or "".
std::string read_options(const json& o, doublet::Options& options, bool& use_host_includer) {
  if (o.contains("stage")) {
    auto stage = doublet::parse_stage(o["stage"].get<std::string>());
    if (!stage) return "unknown stage '" + o["stage"].get<std::string>() + "'";
    options.stage = stage;
  }
  if (o.contains("fileName")) options.file_name = o["fileName"].get<std::string>();
  if (!options.stage) options.stage = doublet::stage_from_path(options.file_name);
  if (!options.stage) return "no stage: give options.stage (vert, frag, comp) or a fileName with that extension";
  if (o.contains("target")) {
    auto target = doublet::parse_target(o["target"].get<std::string>());
    if (!target) return "unknown target '" + o["target"].get<std::string>() + "'";
    options.target = *target;
  }
  if (o.contains("mode")) {
    auto mode = doublet::parse_mode(o["mode"].get<std::string>());
    if (!mode) return "unknown mode '" + o["mode"].get<std::string>() + "'";
    options.mode = *mode;
  }
  // value() returns a copy: kept alive for the loops (items() only refers to it).
  const json mode_for = o.value("modeFor", json::object());
  const json defines = o.value("defines", json::object());
  for (const auto& [name, value] : mode_for.items()) {
    auto mode = doublet::parse_mode(value.get<std::string>());
    if (!mode) return "unknown mode '" + value.get<std::string>() + "' for " + name;
    options.mode_for.emplace_back(name, *mode);
  }
  for (const auto& [name, value] : defines.items())
    options.defines.emplace_back(name, value.is_string() ? value.get<std::string>() : value.dump());
  options.include_dirs = o.value("includeDirs", std::vector<std::string>{});
  if (o.contains("guard")) {
    std::string guard = o["guard"].get<std::string>();
    std::optional<doublet::GuardKind> kind = doublet::parse_guard(guard);
    if (!kind) return "unknown guard '" + guard + "' (auto, precise, uniform)";
    options.guard = *kind;
  }
  options.allow_gpu_shader5 = o.value("gpuShader5", false);
  options.guard_uniform_name = o.value("guardUniform", options.guard_uniform_name);
  options.hi_suffix = o.value("hiSuffix", options.hi_suffix);
  options.lo_suffix = o.value("loSuffix", options.lo_suffix);
  options.optimize = o.value("optimize", true);
  options.disabled_lints = o.value("disabledLints", std::vector<std::string>{});
  options.lint_errors = o.value("lintErrors", false);
  options.constant_range_errors = o.value("constantRangeErrors", false);
  use_host_includer = o.value("hostIncludes", false);
  return "";
}

}  // namespace

extern "C" EMSCRIPTEN_KEEPALIVE char* doublet_lower_json(const char* source, const char* options_json) {
  std::string answer;
  json o = json::parse(options_json, nullptr, false);
  doublet::Options options;
  HostIncluder includer;
  bool use_host_includer = false;
  std::string error;
  if (!o.is_object()) {
    error = "options must be a JSON object";
  } else {
    try {
      error = read_options(o, options, use_host_includer);
    } catch (const json::exception& e) {
      error = std::string("malformed options: ") + e.what();
    }
  }
  if (!error.empty()) {
    answer = option_error(error);
  } else {
    if (use_host_includer) options.includer = &includer;
    doublet::Result r = doublet::lower(source, options);
    json diagnostics = json::array();
    for (const doublet::Diagnostic& d : r.diagnostics) diagnostics.push_back(diagnostic_json(d));
    answer = json{{"ok", r.ok}, {"output", r.output},
                  {"manifest", r.ok ? json::parse(r.manifest.to_json()) : json(nullptr)},
                  {"diagnostics", diagnostics}, {"includedFiles", r.included_files}}.dump();
  }
  char* out = static_cast<char*>(std::malloc(answer.size() + 1));
  std::memcpy(out, answer.c_str(), answer.size() + 1);
  return out;
}

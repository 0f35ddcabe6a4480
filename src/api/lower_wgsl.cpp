// See lower_wgsl.hpp. WGSL has no `precise`, so the guard is the uniform one (or none, for the
// sabotage tests); doublet does not validate the WGSL itself (no WGSL front end is linked in):
// the browser tests compile every golden WGSL file in Chromium's WebGPU (docs/web.md).
#include "api/lower_wgsl.hpp"

#include <algorithm>
#include <utility>
#include <cstring>
#include <chrono>
#include <regex>

#include "api/big_stack.hpp"
#include "api/c_locale.hpp"
#include "emit/wgsl_printer.hpp"
#include "frontend/frontend.hpp"
#include "frontend/import.hpp"

namespace doublet {
namespace {

bool has_error(const std::vector<Diagnostic>& diags) {
  return std::any_of(diags.begin(), diags.end(), [](const Diagnostic& d) { return d.severity == Severity::Error; });
}

// The front end refuses identifiers with doublet's runtime prefixes df_ and (mode exact) ex_
// (users may not declare them), so the runtime's names cross the re-import under other prefixes
// and come back after.
constexpr const char* kCarrierPrefix = "doublet_rt_";
constexpr const char* kExactCarrierPrefix = "doublet_rx_";

std::string restore_prefix(std::string text) {
  for (const auto& [carrier, prefix] : {std::pair{kCarrierPrefix, "df_"}, std::pair{kExactCarrierPrefix, "ex_"}})
    for (size_t at = text.find(carrier); at != std::string::npos; at = text.find(carrier, at))
      text.replace(at, std::strlen(carrier), prefix);
  return text;
}

void print_from_glsl(Result& result, const Options& options, const std::string& glsl_with_runtime_names) {
  // ES precision statements for opaque types (atomic_uint, images) do not parse as desktop GLSL,
  // which the front end reads: they go; the WGSL printer refuses those types at their declaration.
  const std::string glsl = std::regex_replace(
      std::regex_replace(std::regex_replace(glsl_with_runtime_names, std::regex(R"(\bdf_)"), kCarrierPrefix),
                         std::regex(R"(\bex_)"), kExactCarrierPrefix),
      std::regex(R"(precision highp (?!float;|int;)\w+;)"), "");
  Options internal = options;
  internal.target = Target::Es310;
  internal.defines.clear();
  internal.includer = nullptr;
  internal.mode_for.clear();
  frontend::ParsedShader parsed;
  std::vector<Diagnostic> diags;
  ir::Module module;
  if (!frontend::parse(glsl, internal, parsed, diags) || !frontend::import_module(parsed, internal, module, diags)) {
    for (auto& d : diags) d.message = "internal error: the intermediate es310 GLSL does not re-import: " + d.message;
    result.diagnostics.insert(result.diagnostics.end(), diags.begin(), diags.end());
    return;
  }
  const std::string note = " (position in the intermediate GLSL: see `doublet lower --target es310 --guard uniform " +
                           options.file_name + "`)";
  emit::WgslPrintResult printed = emit::print_wgsl(module, options.file_name, note);
  for (auto& d : printed.diagnostics) d.message = restore_prefix(d.message);
  result.diagnostics.insert(result.diagnostics.end(), printed.diagnostics.begin(), printed.diagnostics.end());
  if (has_error(result.diagnostics)) return;
  for (auto& v : result.manifest.variables)
    for (const auto& b : printed.block_bindings)
      if ((v.storage == "uniform" || v.storage == "buffer") && (v.name == b.block || (!b.instance.empty() && v.name == b.instance))) {
        v.group = 0;
        v.binding = b.binding;
      }
  if (!printed.uniform_buffer.name.empty()) {
    for (auto& m : printed.uniform_buffer.members) m.name = restore_prefix(m.name);
    result.manifest.variables.push_back(printed.uniform_buffer);
  }
  result.output = restore_prefix(printed.text);
  result.ok = true;
}

}  // namespace

Result lower_wgsl(std::string_view source, const Options& options) {
  if (options.guard == GuardKind::Precise) {
    Result r;
    r.diagnostics.push_back({options.file_name, 0, 0, Severity::Error,
                             "target wgsl has no 'precise' qualifier; use --guard uniform (the default there)"});
    return r;
  }
  if (options.mode == Mode::Native) {
    Result r;
    r.diagnostics.push_back({options.file_name, 0, 0, Severity::Error,
                             "--mode native keeps the doubles, and WGSL has no f64: use --mode df64 (the default)"});
    return r;
  }
  if (options.mode == Mode::RteExact) {
    Result r;
    r.diagnostics.push_back({options.file_name, 0, 0, Severity::Error,
                             "--mode rte-exact is not available for target wgsl yet: use --mode exact (binary64 in integer "
                             "arithmetic) or df64-int on wgsl"});
    return r;
  }
  Options glsl_options = options;
  glsl_options.target = Target::Es310;
  glsl_options.allow_gpu_shader5 = false;
  // df64-int needs no guard (its error terms are integer arithmetic): es310's Auto gives it none.
  if (glsl_options.guard == GuardKind::Auto && options.mode != Mode::Df64Int) glsl_options.guard = GuardKind::Uniform;
  Result result = lower(source, glsl_options);
  result.manifest.target = "wgsl";
  if (!result.ok) return result;
  const std::string glsl = std::move(result.output);
  result.output.clear();
  result.ok = false;
  const auto start = std::chrono::steady_clock::now();
  try {
    ScopedCLocale c_locale;
    if (!run_with_big_stack([&] { print_from_glsl(result, options, glsl); })) print_from_glsl(result, options, glsl);
  } catch (const std::exception& e) {
    result.ok = false;
    result.output.clear();
    result.diagnostics.push_back({options.file_name, 0, 0, Severity::Error, std::string("internal error: ") + e.what()});
  }
  result.phase_seconds.emplace_back("wgsl", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  return result;
}

}  // namespace doublet

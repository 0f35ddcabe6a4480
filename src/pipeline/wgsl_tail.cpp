#include "pipeline/wgsl_tail.hpp"

#include <cstring>
#include <regex>
#include <utility>

#include "emit/wgsl_printer.hpp"
#include "frontend/import.hpp"

namespace doublet::pipeline {
namespace {

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

// A diagnostic of the WGSL printer names a line of the intermediate GLSL: the statement printed
// on that line (or the last one before it) carries the user's place. Runtime code has none and
// keeps the intermediate position and its note.
void place_in_user_source(Diagnostic& d, const std::vector<std::pair<int, ir::Loc>>& source_lines,
                          const std::string& note) {
  const ir::Loc* place = nullptr;
  for (const auto& [line, loc] : source_lines) {
    if (line > d.line) break;
    place = &loc;
  }
  if (d.line <= 0 || !place) return;
  d.file = ir::file_of(*place, d.file);
  d.line = place->line;
  d.column = place->column;
  if (const size_t at = d.message.find(note); at != std::string::npos) d.message.erase(at, note.size());
}

}  // namespace

bool print_wgsl(State& state) {
  Result& result = state.result;
  // ES precision statements for opaque types (atomic_uint, images) do not parse as desktop GLSL,
  // which the front end reads: they go; the WGSL printer refuses those types at their declaration.
  const std::string glsl = std::regex_replace(
      std::regex_replace(std::regex_replace(state.printed.text, std::regex(R"(\bdf_)"), kCarrierPrefix),
                         std::regex(R"(\bex_)"), kExactCarrierPrefix),
      std::regex(R"(precision highp (?!float;|int;)\w+;)"), "");
  Options internal = state.frontend_options;
  internal.target = target::kWgslIntermediate;
  internal.defines.clear();
  internal.includer = nullptr;
  internal.mode_for.clear();
  frontend::ParsedShader parsed;
  std::vector<Diagnostic> diags;
  ir::Module module;
  if (!frontend::parse(glsl, internal, parsed, diags) || !frontend::import_module(parsed, internal, module, diags)) {
    for (auto& d : diags) d.message = "internal error: the intermediate es310 GLSL does not re-import: " + d.message;
    result.diagnostics.insert(result.diagnostics.end(), diags.begin(), diags.end());
    return false;
  }
  const std::string note = " (position in the intermediate GLSL: see `doublet lower --target es310 --guard uniform " +
                           state.config.file_name + "`)";
  std::map<std::string, int> groups;  // Vulkan GLSL's sets (frontend::ParsedShader::descriptor_sets)
  for (const auto& v : state.module.globals)
    if (v->type.base == ir::Base::Block && v->layout.set > 0) groups[v->type.name] = v->layout.set;
  emit::WgslPrintResult printed = emit::print_wgsl(module, state.config.file_name, note, groups);
  for (auto& d : printed.diagnostics) {
    d.message = restore_prefix(d.message);
    place_in_user_source(d, state.printed.source_lines, note);
  }
  result.diagnostics.insert(result.diagnostics.end(), printed.diagnostics.begin(), printed.diagnostics.end());
  if (has_error(result.diagnostics)) return false;
  for (auto& v : result.manifest.variables)
    for (const auto& b : printed.block_bindings)
      if ((v.storage == "uniform" || v.storage == "buffer") && (v.name == b.block || (!b.instance.empty() && v.name == b.instance))) {
        v.group = b.group;
        v.binding = b.binding;
      }
  if (!printed.uniform_buffer.name.empty()) {
    for (auto& m : printed.uniform_buffer.members) m.name = restore_prefix(m.name);
    result.manifest.variables.push_back(printed.uniform_buffer);
  }
  state.printed.text = restore_prefix(printed.text);
  return true;
}

}  // namespace doublet::pipeline

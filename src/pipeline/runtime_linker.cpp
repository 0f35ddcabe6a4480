#include "pipeline/runtime_linker.hpp"

#include <algorithm>

#include "emit/printer.hpp"
#include "emit/webgl_rules.hpp"
#include "lower/matrix_helpers.hpp"

namespace doublet::pipeline {
namespace {

// df_* pair types for the widths the lowered code names, where the emitted rules do not define them.
// Binary64 words: the words are uint (hi = the pattern's high word, lo = its low word).
std::string missing_pair_types(std::vector<int> widths, const std::string& rules_text, bool words) {
  std::sort(widths.begin(), widths.end());
  std::string out;
  for (int w : widths) {
    const std::string name = passes::df_type_name(w);
    if (rules_text.find("struct " + name) != std::string::npos) continue;
    const std::string f = w == 1 ? (words ? "uint" : "float") : (words ? "uvec" : "vec") + std::to_string(w);
    out += rules::pair_struct_definition(name, f + " hi", f + " lo", false);
  }
  return out;
}

// df_dmatCxR { matCxR hi; matCxR lo; } for every matrix shape named; binary64 words: GLSL has no
// uint matrices, so the words are arrays of uint column vectors.
std::string matrix_pair_types(std::vector<std::pair<int, int>> shapes, bool words) {
  std::sort(shapes.begin(), shapes.end());
  std::string out;
  for (auto [cols, rows] : shapes) {
    const std::string m = passes::matrix::float_type_name(cols, rows), u = "uvec" + std::to_string(rows);
    const std::string columns = "[" + std::to_string(cols) + "]";
    out += rules::pair_struct_definition(passes::matrix::type_name(cols, rows), words ? u + " hi" + columns : m + " hi",
                                         words ? u + " lo" + columns : m + " lo", false);
  }
  return out;
}

// The generated helpers in request order, their IR expressions spelled for the target.
std::string helper_text(const passes::Context& requests, Target target) {
  std::string out;
  for (const auto& name : requests.helper_order) {
    const passes::Helper& h = requests.helpers.at(name);
    out += "\n" + h.head + (h.expression ? emit::expression_text(h.expression, target) : "") + h.tail;
  }
  return out;
}

Diagnostic at_first_use(const Config& config, const passes::Context& requests, const std::string& rule,
                        const std::string& message) {
  auto use = requests.rule_first_use.find(rule);
  const ir::Loc at = use != requests.rule_first_use.end() ? use->second : ir::Loc{};
  return {config.file_name, at.line, at.column, Severity::Error, message};
}

}  // namespace

LinkedRuntime link_runtime(const Config& config, const passes::Context& requests, std::vector<Diagnostic>& diags) {
  LinkedRuntime linked;
  linked.guard.kind = "none";
  linked.after_structs = requests.struct_helpers;
  if (requests.rules_used.empty() && requests.widths_used.empty()) return linked;
  const bool words = config.binary64_words();
  rules::EmitRequest request;
  request.used = requests.rules_used;
  request.guard = config.guard;
  request.exact_words = words;
  request.guard_uniform = config.guard_uniform;
  request.indexed_guard = config.indexed_guard();
  request.es_version = config.facts->es ? config.facts->version : 320;
  request.integer_eft = config.integer_eft;
  request.integer_functions = config.facts->integer_functions;
  request.bit_casts = config.facts->bit_casts;
  if (words)  // an operation rules/exact.glsl does not have yet: said where the shader first uses it
    for (const auto& ref : requests.rules_used)
      if (!rules::RuleLibrary::builtin().has(ref)) {
        diags.push_back(at_first_use(config, requests, ref.name,
                                     "this double operation (" + ref.name.substr(3) + ", width " + std::to_string(ref.width) +
                                         ") is not implemented by --mode " + std::string(to_string(config.requested_mode)) +
                                         " yet; use --mode df64 for it"));
        linked.ok = false;
        return linked;
      }
  rules::EmitResult emitted = rules::RuleLibrary::builtin().emit(request);
  if (!emitted.ok) {  // a rule the target lacks: at the first expression that needs it
    diags.push_back(at_first_use(config, requests, emitted.error_rule, emitted.error));
    linked.ok = false;
    return linked;
  }
  linked.types = missing_pair_types(requests.widths_used, emitted.text, words) +
                 matrix_pair_types(requests.matrices_used, words) + emitted.text.substr(0, emitted.types_end);
  linked.text = emitted.text.substr(emitted.types_end) + helper_text(requests, config.target);
  if (config.facts->webgl_rules) {
    linked.types = emit::spell_float_max_for_webgl(linked.types);
    linked.text = emit::spell_float_max_for_webgl(linked.text);
  }
  // Who reads the guard: the rules (uniform guard), and outside them the shader's float-float
  // constants (guard-constants) and double uniforms (Config::reads_uniforms_through_guard). The
  // rule library declares it with the rules; otherwise it is declared here.
  const bool rules_read_guard = !words && !requests.rules_used.empty() && config.guard == rules::GuardStyle::Uniform;
  const std::string suffix = config.guard_is_indexed() ? "[" + std::to_string(rules::kIndexedGuardElements) + "]" : "";
  if (requests.guard_read_outside_rules && !rules_read_guard)
    linked.text = "uniform highp float " + config.guard_uniform + suffix + ";  // never set: GL zero-fills it at link\n" + linked.text;
  if (!words && !requests.rules_used.empty() && config.guard == rules::GuardStyle::Precise) linked.guard.kind = "precise";
  if (rules_read_guard || requests.guard_read_outside_rules) {
    if (config.guard == rules::GuardStyle::Uniform) linked.guard.kind = "uniform";
    linked.guard_uniform = config.guard_uniform;
    linked.guard.uniform_name = config.guard_uniform;
    linked.guard.uniform_type = "float" + suffix;
  }
  return linked;
}

}  // namespace doublet::pipeline

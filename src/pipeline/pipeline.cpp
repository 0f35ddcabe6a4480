// The pass table and the loop that runs it (docs/architecture.md, "Passes"). A new pass is one
// row: its name, its phase, when the Config wants it, and a function of the State.
#include "pipeline/pipeline.hpp"

#include <algorithm>
#include <chrono>
#include <string_view>

#include "frontend/import.hpp"
#include "ir/check.hpp"
#include "lower/apply_modes.hpp"
#include "lower/exact_functions.hpp"
#include "lower/lints.hpp"
#include "lower/optimize_df.hpp"
#include "pipeline/runtime_linker.hpp"
#include "pipeline/validation.hpp"
#include "pipeline/wgsl_tail.hpp"

namespace doublet::pipeline {

bool has_error(const std::vector<Diagnostic>& diags) {
  return std::any_of(diags.begin(), diags.end(), [](const Diagnostic& d) { return d.severity == Severity::Error; });
}

namespace {

bool always(const Config&) { return true; }
bool lowers_doubles(const Config& c) { return !c.native(); }
bool float_float(const Config& c) { return !c.native() && !c.binary64_words(); }

bool parse(State& s) {
  auto& diags = s.result.diagnostics;
  if (!frontend::parse(s.source, s.frontend_options, s.parsed, diags)) return false;
  s.result.included_files = s.parsed.included_files;
  s.pragmas = frontend::scan_mode_pragmas(s.source, s.config.file_name, diags);
  if (has_error(diags)) return false;
  const std::string mode_name(to_string(s.config.requested_mode));
  if (s.config.binary64_words() && !s.pragmas.empty()) {
    const auto& p = s.pragmas.front();
    diags.push_back({s.config.file_name, p.line, p.column, Severity::Error,
                     "'#pragma doublet mode(" + std::string(to_string(p.mode)) + ")' cannot be combined with --mode " +
                         mode_name + ", which applies to the whole shader"});
    return false;
  }
  if (s.config.native())
    for (const auto& p : s.pragmas)
      diags.push_back({s.config.file_name, p.line, p.column, Severity::Warning,
                       "'#pragma doublet mode(" + std::string(to_string(p.mode)) + ")' is ignored: --mode native keeps every double"});
  s.user_extensions = extensions_to_carry(s.parsed, s.config.target);
  return true;
}

bool import(State& s) {
  if (!frontend::import_module(s.parsed, s.frontend_options, s.module, s.result.diagnostics)) return false;
  s.parsed.release_ast();  // the IR owns everything now: free glslang's memory before the passes
  return true;
}

bool link_runtime_pass(State& s) {
  LinkedRuntime linked = link_runtime(s.config, s.ctx, s.result.diagnostics);
  if (!linked.ok) return false;
  if (s.exact) {  // the exact functions' runtime, under its own names, then the conversions
    LinkedRuntime exact = link_runtime(s.exact->config, *s.exact->ctx, s.result.diagnostics);
    if (!exact.ok) return false;
    linked.types += passes::rename_exact_runtime(exact.types);
    linked.text += passes::rename_exact_runtime(exact.text) + passes::exact_conversions(*s.exact);
    linked.after_structs += passes::rename_exact_runtime(exact.after_structs);
  }
  s.print_options.runtime_types = std::move(linked.types);
  s.print_options.runtime = std::move(linked.text);
  s.print_options.after_structs = std::move(linked.after_structs);
  s.print_options.guard_uniform = linked.guard_uniform;
  s.result.manifest.guard = linked.guard;
  return true;
}

bool print(State& s) {
  s.print_options.target = s.config.target;
  s.print_options.target_name = s.config.target_name();
  // The stage's, the guard's and the helpers' extensions, in that order, each once.
  auto add_extensions = [&](const auto& list) {
    for (const std::string& e : list)
      if (std::find(s.print_options.extensions.begin(), s.print_options.extensions.end(), e) == s.print_options.extensions.end())
        s.print_options.extensions.push_back(e);
  };
  add_extensions(s.config.stage_extensions);
  add_extensions(s.config.guard_extensions);
  add_extensions(s.ctx.extensions);
  s.print_options.user_extensions = s.user_extensions;
  s.printed = emit::print(s.module, s.print_options, s.config.file_name);
  auto& diags = s.result.diagnostics;
  diags.insert(diags.end(), s.printed.diagnostics.begin(), s.printed.diagnostics.end());
  return !has_error(diags);
}

// The IR passes: (name, phase, wanted, run).
#define IR_PASS(NAME, PHASE, WANTED, CALL) \
  Pass { NAME, PHASE, WANTED, [](State& s) { return CALL; }, true }

}  // namespace

const std::vector<Pass>& pass_table() {
  static const std::vector<Pass> passes = {
      {"parse", "parse", always, parse, false},
      {"import", "import", always, import, true},
      IR_PASS("flatten-io-blocks", "import", [](const Config& c) { return !c.facts->io_blocks; },
              passes::flatten_io_blocks(s.module, s.ctx)),
      IR_PASS("uniform-defaults", "import", always, passes::uniform_defaults(s.module, s.ctx)),
      // On the IR as imported, before any pass rewrites it.
      IR_PASS("lints", "lints", always, (passes::run_lints(s.module, s.source, s.ctx), true)),
      IR_PASS("modes", "modes", lowers_doubles, passes::apply_modes(s.module, s.ctx, s.pragmas)),
      IR_PASS("exact-functions", "lower", float_float, passes::extract_exact_functions(s.module, s.ctx, s.exact)),
      IR_PASS("out-argument-temporaries", "lower", lowers_doubles, passes::out_argument_temporaries(s.module, s.ctx)),
      IR_PASS("lower-doubles", "lower", lowers_doubles, passes::lower_doubles(s.module, s.ctx)),
      // Rewrites float-float rule calls; binary64 words have none.
      IR_PASS("optimize", "optimize", [](const Config& c) { return c.optimize && !c.binary64_words() && !c.native(); },
              passes::optimize_df(s.module, s.ctx)),
      IR_PASS("exact-functions-join", "optimize", float_float,
              !s.exact || passes::join_exact_functions(s.module, s.ctx, *s.exact)),
      IR_PASS("global-inits", "interfaces", always, passes::move_global_initialisers(s.module, s.ctx)),
      IR_PASS("exact-block-words", "interfaces", [](const Config& c) { return c.binary64_words(); },
              passes::exact_block_words(s.module, s.ctx)),
      // c.facts is the target the IR is lowered for: for --target wgsl, its GLSL ES 3.10 intermediate.
      IR_PASS("output-locations", "interfaces", [](const Config& c) { return c.facts->es && c.facts->version >= 300; },
              passes::assign_fragment_output_locations(s.module, s.ctx)),
      IR_PASS("split-interfaces", "interfaces", always, passes::split_interfaces(s.module, s.ctx, s.result.manifest)),
      IR_PASS("wgsl-io-locations", "interfaces", [](const Config& c) { return target::facts(c.output).wgsl; },
              passes::assign_wgsl_io_locations(s.module, s.result.manifest)),
      IR_PASS("rename-builtins", "interfaces", [](const Config& c) { return !c.facts->overloads_builtin_names; },
              passes::rename_functions_named_like_builtins(s.module, s.ctx)),
      IR_PASS("select-structs", "interfaces", always, passes::select_structs(s.module, s.ctx)),
      IR_PASS("wgsl-expression-effects", "interfaces", [](const Config& c) { return target::facts(c.output).wgsl; },
              passes::wgsl_expression_effects(s.module, s.ctx)),
      IR_PASS("wgsl-out-arguments", "interfaces", [](const Config& c) { return target::facts(c.output).wgsl; },
              passes::wgsl_out_argument_temporaries(s.module, s.ctx)),
      IR_PASS("hoist-commas", "interfaces", [](const Config& c) { return target::facts(c.output).wgsl; },
              passes::hoist_commas(s.module, s.ctx)),
      IR_PASS("share-exact-calls", "interfaces", [](const Config& c) { return c.binary64_words() && c.share_exact_calls; },
              passes::share_exact_calls(s.module, s.ctx)),
      IR_PASS("guard-uniform-reads", "interfaces", [](const Config& c) { return c.reads_uniforms_through_guard(); },
              passes::guard_uniform_reads(s.module, s.ctx)),
      IR_PASS("guard-constants", "interfaces", passes::guards_constants, passes::guard_constants(s.module, s.ctx)),
      IR_PASS("check-target", "interfaces", always, passes::check_target(s.module, s.ctx)),
      {"link-runtime", "print", always, link_runtime_pass, false},
      {"print", "print", always, print, false},
      {"validate", "validate", always, validate_output, false},
      {"wgsl", "wgsl", [](const Config& c) { return c.output != c.target; }, print_wgsl, false},
  };
  return passes;
}

void run(State& s) {
  const Config& c = s.config;
  Result& result = s.result;
  result.manifest.stage = std::string(to_string(c.stage));
  result.manifest.target = std::string(to_string(c.output));
  result.manifest.mode = std::string(to_string(c.requested_mode));
  result.manifest.guard.kind = "none";
  // Each phase's wall-clock time goes to result.phase_seconds once all its passes have finished.
  std::string phase;
  auto phase_start = std::chrono::steady_clock::now();
  auto finish_phase = [&] {
    const auto now = std::chrono::steady_clock::now();
    if (!phase.empty()) result.phase_seconds.emplace_back(phase, std::chrono::duration<double>(now - phase_start).count());
    phase_start = now;
  };
  bool printed = false;
  for (const Pass& pass : pass_table()) {
    const bool wanted = pass.wanted(c);
    // Every phase of the GLSL pipeline is reported, even where its passes do not run (native has
    // no "modes"); the target's tail (wgsl) only when it runs.
    if (!wanted && &pass == &pass_table().back()) continue;
    if (pass.phase != phase) {
      finish_phase();
      phase = pass.phase;
    }
    const bool skipped = std::find(c.skip_passes.begin(), c.skip_passes.end(), pass.name) != c.skip_passes.end();
    if (wanted && !skipped && !pass.run(s)) return;
    printed = printed || std::string_view(pass.name) == "print";
    if (c.check_ir && pass.on_ir)
      if (const std::string problem = ir::check(s.module); !problem.empty()) {
        result.diagnostics.push_back({c.file_name, 0, 0, Severity::Error,
                                      "internal error: the IR is inconsistent after pass '" + std::string(pass.name) +
                                          "' (please report this with the input): " + problem});
        return;
      }
    if (c.stop_after == pass.name) {
      finish_phase();
      // The IR as this pass left it (what the passes before the printer hold), not re-validated.
      if (!printed) {
        emit::PrintOptions o = s.print_options;
        o.target = c.target;
        result.output = emit::print(s.module, o, c.file_name).text;
      } else {
        result.output = s.printed.text;
      }
      result.ok = true;
      return;
    }
  }
  finish_phase();
  result.output = std::move(s.printed.text);
  result.ok = true;
}

}  // namespace doublet::pipeline

namespace doublet {
std::vector<std::string_view> pass_names() {
  std::vector<std::string_view> names;
  for (const auto& p : pipeline::pass_table()) names.push_back(p.name);
  return names;
}
}  // namespace doublet

// Every refusal of an option combination, in one place (docs/architecture.md, "Config").
#include "pipeline/config.hpp"

#include <algorithm>

namespace doublet::pipeline {
namespace {

using rules::GuardStyle;

// Refusals that only the WGSL target makes; then the GLSL profile it is printed from decides.
bool refuse_for_wgsl(const Options& o, std::vector<Diagnostic>& diags) {
  auto refuse = [&](const std::string& message) {
    diags.push_back({o.file_name, 0, 0, Severity::Error, message});
    return false;
  };
  if (o.guard == GuardKind::Precise)
    return refuse("target wgsl has no 'precise' qualifier; use --guard uniform (the default there)");
  if (o.mode == Mode::Native)
    return refuse("--mode native keeps the doubles, and WGSL has no f64: use --mode df64 (the default)");
  if (o.mode == Mode::RteExact)
    return refuse("--mode rte-exact is not available for target wgsl yet: use --mode exact (binary64 in integer "
                  "arithmetic) or df64-int on wgsl");
  return true;
}

// `precise` where the target has it (or ES 3.10 with GL_EXT_gpu_shader5 when allowed), else the
// opaque uniform (docs/numerics.md, "The guard").
bool choose_guard(const Options& o, GuardKind kind, Config& c, std::vector<Diagnostic>& diags) {
  const bool via_extension = c.facts->precise_via_gpu_shader5 && o.allow_gpu_shader5;
  switch (kind) {
    case GuardKind::None: c.guard = GuardStyle::None; return true;
    case GuardKind::Uniform: c.guard = GuardStyle::Uniform; return true;
    case GuardKind::Auto: c.guard = c.facts->precise || via_extension ? GuardStyle::Precise : GuardStyle::Uniform; break;
    case GuardKind::Precise:
      if (!c.facts->precise && !via_extension) {
        diags.push_back({o.file_name, 0, 0, Severity::Error,
                         "target " + std::string(c.facts->name) +
                             " has no 'precise' qualifier (it needs ES 3.20, desktop 4.00+, or ES 3.10 with "
                             "GL_EXT_gpu_shader5); use --guard uniform"});
        return false;
      }
      c.guard = GuardStyle::Precise;
      break;
  }
  if (c.guard == GuardStyle::Precise && via_extension && !c.facts->precise) c.guard_extensions.push_back("GL_EXT_gpu_shader5");
  return true;
}

}  // namespace

std::optional<Config> resolve_config(const Options& o, std::vector<Diagnostic>& diags) {
  auto refuse = [&](const std::string& message) {
    diags.push_back({o.file_name, 0, 0, Severity::Error, message});
    return std::nullopt;
  };
  Config c;
  c.output = o.target;
  c.target = o.target;
  GuardKind guard = o.guard;
  const bool wgsl = target::facts(o.target).wgsl;
  if (wgsl) {
    if (!refuse_for_wgsl(o, diags)) return std::nullopt;
    c.target = target::kWgslIntermediate;
    // WGSL has no `precise`: the uniform guard, except for df64-int, which needs none.
    if (guard == GuardKind::Auto && o.mode != Mode::Df64Int) guard = GuardKind::Uniform;
  }
  c.facts = &target::facts(c.target);
  const std::string target_name = c.facts->name;
  if (!o.stage) return refuse("the shader stage is unknown: name the file .vert/.frag/.comp or pass -S");
  c.stage = *o.stage;
  if (!target::has_stage(target::facts(o.target), c.stage)) {
    std::string have;
    for (Target t : target::all_targets())
      if (target::has_stage(target::facts(t), c.stage)) have += std::string(have.empty() ? "" : ", ") + target::facts(t).name;
    return refuse("target " + std::string(target::facts(o.target).name) + " has no " + target::stage_noun(c.stage) +
                  " shaders; the targets that have them: " + have);
  }
  if (const char* extension = target::stage_extension(*c.facts, c.stage)) c.stage_extensions.push_back(extension);
  c.requested_mode = o.mode;
  c.mode = o.mode;
  // df64-int is df64 with the integer error-free transformations of rules/int.glsl: the passes
  // see df64; the rule library swaps the EFTs. They need no guard, so Auto means None.
  if (o.mode == Mode::Df64Int) {
    if (!c.facts->uint_and_bit_ops)
      return refuse("--mode df64-int needs uint and floatBitsToUint (GLSL ES 3.00 or later): use --target es300 or "
                    "later, or --mode df64");
    c.integer_eft = true;
    c.mode = Mode::Df64;
    if (guard == GuardKind::Auto) guard = GuardKind::None;
  }
  Options guard_options = o;
  if (wgsl) guard_options.allow_gpu_shader5 = false;
  if (!choose_guard(guard_options, guard, c, diags)) return std::nullopt;
  const std::string mode_name(to_string(o.mode));
  if (o.mode == Mode::Native) {
    if (c.target != Target::Glsl450)
      return refuse("--mode native keeps the doubles, which only desktop GLSL 4.00+ has: use --target glsl450 (target " +
                    target_name + " has no double type)");
    c.representation = Representation::Native;
  }
  if (o.mode == Mode::Exact || o.mode == Mode::RteExact) {
    if (!c.facts->uint_and_bit_ops)
      return refuse("--mode " + mode_name +
                    " needs 32-bit integers (uint and bit operations), which GLSL ES 1.00 lacks: use --target es300 or "
                    "later");
    c.representation = Representation::Binary64Words;
  }
  if ((c.binary64_words() || c.native()) && !o.mode_for.empty())
    return refuse("--mode " + mode_name + " applies to the whole shader: it cannot be combined with --mode-for " +
                  o.mode_for.front().first + "=" + std::string(to_string(o.mode_for.front().second)));
  if (c.binary64_words()) {  // integer arithmetic: no guard, no extension for it
    c.guard = GuardStyle::None;
    c.guard_extensions.clear();
  }
  // What the passes read of the user's options, copied as they are.
  c.guard_uniform = o.guard_uniform_name, c.optimize = o.optimize, c.file_name = o.file_name;
  c.share_exact_calls = o.share_exact_calls;
  c.hi_suffix = o.hi_suffix, c.lo_suffix = o.lo_suffix, c.mode_for = o.mode_for;
  c.constant_range_errors = o.constant_range_errors, c.disabled_lints = o.disabled_lints, c.lint_errors = o.lint_errors;
  if (!o.stop_after.empty()) {
    const auto names = pass_names();
    if (std::find(names.begin(), names.end(), o.stop_after) == names.end()) {
      std::string list;
      for (auto n : names) list += (list.empty() ? "" : ", ") + std::string(n);
      return refuse("--stop-after " + o.stop_after + ": no pass has that name (the passes, in order: " + list + ")");
    }
  }
  c.stop_after = o.stop_after;
  c.skip_passes = o.skip_passes;
  c.check_ir = o.check_ir;
  return c;
}

Options frontend_options(const Options& options, const Config& config) {
  Options o = options;  // target: the user's, which the front end only names in diagnostics
  if (config.output != config.target) o.allow_gpu_shader5 = false;
  return o;
}

}  // namespace doublet::pipeline

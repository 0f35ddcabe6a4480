// doublet::lower: front end → import → lowering passes → print → re-validate.
#include <glslang/MachineIndependent/localintermediate.h>

#include <algorithm>
#include <chrono>
#include <exception>
#include <map>
#include <mutex>
#include <set>

#include "api/big_stack.hpp"
#include "api/c_locale.hpp"
#include "api/lower_wgsl.hpp"
#include "doublet/doublet.hpp"
#include "emit/printer.hpp"
#include "emit/validate.hpp"
#include "emit/webgl_rules.hpp"
#include "frontend/frontend.hpp"
#include "frontend/import.hpp"
#include "frontend/mode_pragmas.hpp"
#include "frontend/text_scan.hpp"
#include "frontend/read_limited.hpp"
#include "lower/apply_modes.hpp"
#include "lower/lints.hpp"
#include "lower/lower.hpp"
#include "lower/matrix_helpers.hpp"
#include "lower/optimize_df.hpp"
#include "rules/rule_library.hpp"

namespace doublet {
namespace {

bool target_has_precise(Target t) { return t == Target::Es320 || t == Target::Glsl450; }

struct GuardChoice {
  rules::GuardStyle style = rules::GuardStyle::Uniform;
  std::vector<std::string> extensions;
};

bool choose_guard(const Options& o, GuardChoice& out, std::vector<Diagnostic>& diags) {
  bool via_extension = o.target == Target::Es310 && o.allow_gpu_shader5;
  switch (o.guard) {
    case GuardKind::None: out.style = rules::GuardStyle::None; return true;
    case GuardKind::Uniform: out.style = rules::GuardStyle::Uniform; return true;
    case GuardKind::Auto:
      out.style = target_has_precise(o.target) || via_extension ? rules::GuardStyle::Precise : rules::GuardStyle::Uniform;
      break;
    case GuardKind::Precise:
      if (!target_has_precise(o.target) && !via_extension) {
        diags.push_back({o.file_name, 0, 0, Severity::Error,
                         "target " + std::string(to_string(o.target)) +
                             " has no 'precise' qualifier (it needs ES 3.20, desktop 4.00+, or ES 3.10 with "
                             "GL_EXT_gpu_shader5); use --guard uniform"});
        return false;
      }
      out.style = rules::GuardStyle::Precise;
      break;
  }
  if (out.style == rules::GuardStyle::Precise && via_extension && !target_has_precise(o.target))
    out.extensions.push_back("GL_EXT_gpu_shader5");
  return true;
}

// The df_* struct for every width the lowered code names, where the emitted
// rules did not already define it.
// Mode exact: the words are uint (hi = the binary64 pattern's high word, lo = its low word).
std::string missing_struct_types(const std::vector<int>& widths, const std::string& runtime, bool exact) {
  std::string out;
  std::vector<int> sorted = widths;
  std::sort(sorted.begin(), sorted.end());
  for (int w : sorted) {
    std::string name = passes::df_type_name(w);
    if (runtime.find("struct " + name) != std::string::npos) continue;
    std::string f = w == 1 ? (exact ? "uint" : "float") : (exact ? "uvec" : "vec") + std::to_string(w);
    out += "struct " + name + " {\n  " + f + " hi;\n  " + f + " lo;\n};\n";
  }
  return out;
}

// struct df_dmatCxR { matCxR hi; matCxR lo; } for every matrix shape the lowered code names.
// Mode exact: GLSL has no uint matrices, so the words are arrays of uint column vectors.
std::string matrix_struct_types(std::vector<std::pair<int, int>> shapes, bool exact) {
  std::sort(shapes.begin(), shapes.end());
  std::string out;
  for (auto [cols, rows] : shapes) {
    const std::string m = passes::matrix::float_type_name(cols, rows), u = "uvec" + std::to_string(rows);
    const std::string suffix = "[" + std::to_string(cols) + "]";
    out += "struct " + passes::matrix::type_name(cols, rows) + " {\n  " + (exact ? u + " hi" + suffix : m + " hi") +
           ";\n  " + (exact ? u + " lo" + suffix : m + " lo") + ";\n};\n";
  }
  return out;
}

// The targets whose language has the built-in variable `name` in `stage`, asked of glslang with a
// one-line probe per target (cached): compatibility-profile names (gl_Vertex) are in none.
std::string targets_with_builtin_variable(const std::string& name, Stage stage) {
  static std::mutex mutex;
  static std::map<std::pair<std::string, Stage>, std::string> known;
  std::lock_guard<std::mutex> lock(mutex);
  auto [it, inserted] = known.try_emplace({name, stage});
  if (!inserted) return it->second;
  for (Target t : {Target::Es100, Target::Es300, Target::Es310, Target::Es320, Target::Glsl330, Target::Glsl450}) {  // webgl2 = es300 here
    const std::string version = emit::version_directive(t);
    const std::string layout = stage == Stage::Compute ? "layout(local_size_x = 1) in;\n" : "";
    const std::string log = emit::validate(version + "\nprecision highp float;\n" + layout + "void main() { " + name + "; }\n",
                                           stage, t);
    if (log.find("undeclared identifier") == std::string::npos)
      it->second += (it->second.empty() ? "" : ", ") + std::string(to_string(t));
  }
  return it->second;
}

// glslang's re-validation is the authority on which built-in variables and functions a target
// and stage have (gl_ClipDistance on ES, gl_FragDepth or texelFetch on ES 1.00, ...). When it
// rejects one the user's shader uses, say so at the use instead of an internal error.
bool report_builtins_the_target_lacks(const std::string& log,
                                      const std::map<std::string, emit::PrintResult::BuiltinUse>& first_use,
                                      const Options& options, std::vector<Diagnostic>& diags) {
  static const char* const kMissing[] = {"' : undeclared identifier", "' : no matching overloaded function found"};
  std::set<std::string> reported;
  for (size_t start = 0; start < log.size();) {
    size_t end = log.find('\n', start);
    if (end == std::string::npos) end = log.size();
    const std::string_view line(log.data() + start, end - start);
    start = end + 1;
    for (const char* missing : kMissing) {
      const size_t tail = line.find(missing);
      const size_t open = tail == std::string_view::npos ? tail : line.rfind('\'', tail == 0 ? 0 : tail - 1);
      if (open == std::string_view::npos) continue;
      const std::string name(line.substr(open + 1, tail - open - 1));
      auto use = first_use.find(name);
      if (use == first_use.end() || !reported.insert(name).second) continue;
      const std::string target(to_string(options.target));
      const std::string& written = use->second.source_name;
      const char* stage = *options.stage == Stage::Vertex ? "vertex" : *options.stage == Stage::Fragment ? "fragment" : "compute";
      const bool variable = name.rfind("gl_", 0) == 0;
      std::string message = "the built-in '" + written + "'" + (written != name ? " (" + name + " there)" : "") +
                            (variable ? " does not exist in " : " has no such overload in ") + target + " " + stage +
                            " shaders";
      if (!variable) {
        message += "; remove it";
        if (options.target != Target::Glsl450) message += ", or target glsl450 (desktop GLSL 4.50 has it)";
      } else if (const std::string have = targets_with_builtin_variable(written, *options.stage); !have.empty()) {
        message += "; remove it, or target one that has it (" + have + ")";
      } else {
        message += " (a compatibility-profile built-in: doublet's desktop targets are core profiles); pass the value "
                   "as a uniform or an attribute instead";
      }
      diags.push_back({ir::file_of(use->second.loc, options.file_name), use->second.loc.line, use->second.loc.column,
                      Severity::Error, message});
    }
  }
  return !reported.empty();
}

// The extensions the shader enables (#extension, as glslang's preprocessor saw them: inactive #if
// branches and #includes resolved), carried into the output: without them its uses of their
// built-ins (gl_SubgroupSize, gl_BaseVertexARB, ...) failed re-validation, an internal error.
// Left out: the ones doublet's front end or the lowering makes moot (includes are expanded, doubles
// are gone); the target's compiler decides about the rest, as the re-validation does here. WebGL
// enables extensions from JavaScript, never in the shader (emit/webgl_rules.cpp), so none there.
std::vector<std::string> carried_extensions(const frontend::ParsedShader& parsed, Target target) {
  static const std::set<std::string> kMoot = {"GL_GOOGLE_include_directive", "GL_GOOGLE_cpp_style_line_directive",
                                              "GL_ARB_gpu_shader_fp64", "GL_EXT_shader_explicit_arithmetic_types_float64",
                                              "all"};
  std::vector<std::string> names;
  if (target == Target::Webgl2 || !parsed.intermediate) return names;
  for (const std::string& name : parsed.intermediate->getRequestedExtensions())
    if (!kMoot.count(name)) names.push_back(name);
  return names;
}

// glslang's "ERROR: 0:<line>: <message>" entries of the main string, as (line, message); the
// closing "compilation terminated" and the count are left out.
std::vector<std::pair<int, std::string>> main_string_errors(std::string_view log) {
  std::vector<std::pair<int, std::string>> errors;
  for (size_t start = 0; start < log.size();) {
    size_t end = log.find('\n', start);
    if (end == std::string_view::npos) end = log.size();
    std::string_view line = log.substr(start, end - start);
    start = end + 1;
    if (line.substr(0, 9) != "ERROR: 0:") continue;
    line.remove_prefix(9);
    const size_t colon = line.find(':');
    if (colon == std::string_view::npos || colon == 0) continue;
    int number = 0;
    for (char c : line.substr(0, colon)) number = frontend::is_digit(c) && number < 100000000 ? number * 10 + (c - '0') : -1;
    std::string_view message = frontend::trim_blanks(line.substr(colon + 1));
    if (number <= 0 || message.find("compilation terminated") != std::string_view::npos) continue;
    errors.emplace_back(number, std::string(message));
  }
  return errors;
}

// When the lowered text fails re-validation, the construct may be the user's: a desktop shader's
// vertex input array or non-flat `out int`, a built-in of an extension, for an ES target. glslang
// compiling the user's own text as the target (its #version line replaced, doubles read as floats,
// line numbers kept) says so: when its first complaint about the lowered text is one it also makes
// about the user's text, refuse at the user's lines (each complaint both texts get) instead of
// reporting an internal error. A complaint about anything doublet wrote (its names, its types)
// does not match, and stays an internal error.
bool report_what_the_source_lacks(std::string_view source, const std::string& lowered_log, const Options& options,
                                  std::vector<Diagnostic>& diags) {
  const auto lowered = main_string_errors(lowered_log);
  if (lowered.empty()) return false;
  // Only the main file is recompiled: a shader with #include keeps the internal error.
  frontend::LogicalLines lines(source);
  std::string_view logical, rest;
  int version_line = 0, last_extension_line = 0;
  std::set<int> extension_lines;  // WebGL: none in the shader (carried_extensions)
  while (lines.next(logical)) {
    const std::string_view name = frontend::directive_name(logical, rest);
    if (name == "include") return false;
    if (name == "version" && version_line == 0) version_line = lines.line();
    if (name == "extension") {
      last_extension_line = lines.line();
      if (options.target == Target::Webgl2) extension_lines.insert(lines.line());
    }
  }
  if (version_line == 0) return false;
  // What an ES target needs before the user's code, after the #version and #extension lines (which
  // must come first), then `#line` so that the user's line numbers stay (ES and 3.30+: #line N
  // numbers the next line N).
  const int prelude_after = std::max(version_line, last_extension_line);
  std::string prelude = "#define double float\n";  // ES stops at the reserved word `double`
  for (const char* n : {"2", "3", "4"}) {
    prelude += std::string("#define dvec") + n + " vec" + n + "\n#define dmat" + n + " mat" + n + "\n";
    for (const char* m : {"2", "3", "4"}) prelude += std::string("#define dmat") + n + "x" + m + " mat" + n + "x" + m + "\n";
  }
  for (const auto& [name, value] : options.defines) prelude += "#define " + name + " " + value + "\n";
  if (target_is_es(options.target)) {
    prelude += "precision highp float;\nprecision highp int;\n";  // desktop shaders declare none
    if (target_version(options.target) >= 300)
      for (const char* t : {"sampler3D", "samplerCubeShadow", "sampler2DShadow", "sampler2DArray", "sampler2DArrayShadow",
                            "isampler2D", "isampler3D", "isamplerCube", "isampler2DArray", "usampler2D", "usampler3D",
                            "usamplerCube", "usampler2DArray"})
        prelude += std::string("precision highp ") + t + ";\n";
  }
  prelude += "#line " + std::to_string(prelude_after + 1) + "\n";
  const frontend::LineIndex index(source);
  std::string text;
  for (int n = 1; n <= index.line_count(); ++n) {
    if (n == version_line)
      text += emit::version_directive(options.target) + "\n";
    else
      text += extension_lines.count(n) ? "\n" : std::string(index.line(n)) + "\n";
    if (n == prelude_after) text += prelude;
  }
  const auto original = main_string_errors(emit::validate(text, *options.stage, options.target));
  std::set<std::string> original_messages;
  for (const auto& e : original) original_messages.insert(e.second);
  // glslang stops at some errors, in either text, so the lists need not be equal; the first
  // complaint about the lowered text decides (once the user has fixed it, any other shows).
  if (!original_messages.count(lowered.front().second)) return false;
  const std::set<std::string> lowered_messages = [&] {
    std::set<std::string> m;
    for (const auto& e : lowered) m.insert(e.second);
    return m;
  }();
  const std::string target(to_string(options.target));
  std::set<std::pair<int, std::string>> reported;
  for (const auto& [line, message] : original) {
    if (!lowered_messages.count(message) || !reported.insert({line, message}).second) continue;
    // glslang quotes the construct first ('vertex input arrays', 'gl_SubgroupSize', 'int'); point at it.
    std::string token;
    if (message.size() > 1 && message[0] == '\'') token = message.substr(1, message.find('\'', 1) - 1);
    const int column = frontend::column_in_row(index.line(line), token);
    diags.push_back({options.file_name, line, column, Severity::Error,
                     "target " + target + " does not allow this (glslang, compiling the shader itself as " + target +
                         ": " + message + "); change it, or choose a target that allows it"});
  }
  return true;
}

Result lower_unchecked(std::string_view source, const Options& options) {
  ScopedCLocale c_locale;  // '.' in every number printed or read, whatever the application's locale
  Result result;
  auto& diags = result.diagnostics;
  if (!options.stage) {
    diags.push_back({options.file_name, 0, 0, Severity::Error,
                     "the shader stage is unknown: name the file .vert/.frag/.comp or pass -S"});
    return result;
  }
  if (*options.stage == Stage::Compute && (options.target == Target::Es100 || options.target == Target::Es300 ||
                                            options.target == Target::Webgl2 || options.target == Target::Glsl330)) {
    diags.push_back({options.file_name, 0, 0, Severity::Error,
                     "target " + std::string(to_string(options.target)) +
                         " has no compute shaders (they need ES 3.10 or desktop 4.30); use --target es310, es320 "
                         "or glsl450"});
    return result;
  }
  // df64-int is df64 with the integer error-free transformations of rules/int.glsl: the passes
  // see df64; the rule library swaps the EFTs. They need no guard, so Auto means None.
  const bool integer_eft = options.mode == Mode::Df64Int;
  if (integer_eft && options.target == Target::Es100) {
    diags.push_back({options.file_name, 0, 0, Severity::Error,
                     "--mode df64-int needs uint and floatBitsToUint (GLSL ES 3.00 or later): use --target es300 or "
                     "later, or --mode df64"});
    return result;
  }
  Options df64_options = options;
  if (integer_eft) {
    df64_options.mode = Mode::Df64;
    if (df64_options.guard == GuardKind::Auto) df64_options.guard = GuardKind::None;
  }
  GuardChoice guard;
  if (!choose_guard(df64_options, guard, diags)) return result;
  const bool native = options.mode == Mode::Native;
  if (native && options.target != Target::Glsl450) {
    diags.push_back({options.file_name, 0, 0, Severity::Error,
                     "--mode native keeps the doubles, which only desktop GLSL 4.00+ has: use --target glsl450 (target " +
                         std::string(to_string(options.target)) + " has no double type)"});
    return result;
  }
  const bool exact = passes::binary64_words(options);  // exact, rte-exact: binary64 words
  const std::string mode_name(to_string(options.mode));
  if (exact && options.target == Target::Es100) {
    diags.push_back({options.file_name, 0, 0, Severity::Error,
                     "--mode " + mode_name + " needs 32-bit integers (uint and bit operations), which GLSL ES 1.00 "
                     "lacks: use --target es300 or later"});
    return result;
  }
  if (exact && !options.mode_for.empty()) {
    diags.push_back({options.file_name, 0, 0, Severity::Error,
                     "--mode " + mode_name + " applies to the whole shader: it cannot be combined with --mode-for " +
                         options.mode_for.front().first + "=" + std::string(to_string(options.mode_for.front().second))});
    return result;
  }
  if (native && !options.mode_for.empty()) {
    diags.push_back({options.file_name, 0, 0, Severity::Error,
                     "--mode native applies to the whole shader: it cannot be combined with --mode-for " +
                         options.mode_for.front().first + "=" + std::string(to_string(options.mode_for.front().second))});
    return result;
  }

  // Each phase's wall-clock time goes to result.phase_seconds as the next one starts.
  auto phase_start = std::chrono::steady_clock::now();
  std::string phase_name = "parse";
  auto next_phase = [&](const char* name) {
    const auto now = std::chrono::steady_clock::now();
    result.phase_seconds.emplace_back(phase_name, std::chrono::duration<double>(now - phase_start).count());
    phase_start = now;
    phase_name = name;
  };
  frontend::ParsedShader parsed;
  if (!frontend::parse(source, options, parsed, diags)) return result;
  result.included_files = parsed.included_files;

  std::vector<frontend::ModePragma> pragmas = frontend::scan_mode_pragmas(source, options.file_name, diags);
  if (std::any_of(diags.begin(), diags.end(), [](const Diagnostic& d) { return d.severity == Severity::Error; }))
    return result;
  if (exact && !pragmas.empty()) {
    diags.push_back({options.file_name, pragmas.front().line, pragmas.front().column, Severity::Error,
                     "'#pragma doublet mode(" + std::string(to_string(pragmas.front().mode)) +
                         ")' cannot be combined with --mode " + mode_name + ", which applies to the whole shader"});
    return result;
  }
  if (native)
    for (const auto& p : pragmas)
      diags.push_back({options.file_name, p.line, p.column, Severity::Warning,
                       "'#pragma doublet mode(" + std::string(to_string(p.mode)) +
                           ")' is ignored: --mode native keeps every double"});

  const std::vector<std::string> user_extensions = carried_extensions(parsed, options.target);
  ir::Module module;
  next_phase("import");
  if (!frontend::import_module(parsed, options, module, diags)) return result;
  parsed.release_ast();  // the IR owns everything now: free glslang's memory before the passes

  passes::Context ctx{df64_options, diags};
  if (!passes::flatten_io_blocks(module, ctx)) return result;
  next_phase("lints");
  passes::run_lints(module, source, ctx);  // on the IR as imported, before any pass rewrites it
  result.manifest.stage = std::string(to_string(*options.stage));
  result.manifest.target = std::string(to_string(options.target));
  result.manifest.mode = std::string(to_string(options.mode));
  next_phase("modes");
  if (!native && !passes::apply_modes(module, ctx, pragmas)) return result;
  next_phase("lower");
  if (!native && !passes::lower_doubles(module, ctx)) return result;
  next_phase("optimize");
  // optimize_df rewrites float-float rule calls; exact mode has none.
  if (options.optimize && !exact && !passes::optimize_df(module, ctx)) return result;
  next_phase("interfaces");
  if (!passes::move_global_initialisers(module, ctx)) return result;
  if (exact && !passes::exact_block_words(module, ctx)) return result;
  if (!passes::split_interfaces(module, ctx, result.manifest)) return result;
  if (!passes::rename_functions_named_like_builtins(module, ctx)) return result;
  if (!passes::select_structs(module, ctx)) return result;
  if (!passes::check_target(module, ctx)) return result;
  next_phase("print");

  emit::PrintOptions print_options;
  print_options.target = options.target;
  if (!exact) print_options.extensions = guard.extensions;  // exact: no guard, no extension for it
  print_options.user_extensions = user_extensions;
  result.manifest.guard.kind = "none";
  if (!ctx.rules_used.empty() || !ctx.widths_used.empty()) {
    rules::EmitRequest request;
    request.used = ctx.rules_used;
    request.guard = exact ? rules::GuardStyle::None : guard.style;  // integer arithmetic needs no guard
    request.exact_words = exact;
    request.guard_uniform = options.guard_uniform_name;
    request.es_version = target_is_es(options.target) ? target_version(options.target) : 320;
    request.integer_eft = integer_eft;
    request.integer_functions = options.target == Target::Es310 || options.target == Target::Es320 ||
                                options.target == Target::Glsl450;  // umulExtended, findMSB
    if (exact)  // an operation rules/exact.glsl does not have yet: said where the shader first uses it
      for (const auto& ref : ctx.rules_used)
        if (!rules::RuleLibrary::builtin().has(ref)) {
          auto use = ctx.rule_first_use.find(ref.name);
          ir::Loc at = use != ctx.rule_first_use.end() ? use->second : ir::Loc{};
          diags.push_back({options.file_name, at.line, at.column, Severity::Error,
                           "this double operation (" + ref.name.substr(3) + ", width " + std::to_string(ref.width) +
                               ") is not implemented by --mode " + mode_name + " yet; use --mode df64 for it"});
          return result;
        }
    rules::EmitResult emitted = rules::RuleLibrary::builtin().emit(request);
    if (!emitted.ok) {
      // A rule the target lacks: point at the first expression that needs it.
      auto use = ctx.rule_first_use.find(emitted.error_rule);
      ir::Loc at = use != ctx.rule_first_use.end() ? use->second : ir::Loc{};
      diags.push_back({options.file_name, at.line, at.column, Severity::Error, emitted.error});
      return result;
    }
    std::string helpers;
    for (const auto& name : ctx.helper_order) helpers += "\n" + ctx.helpers[name];
    print_options.runtime = missing_struct_types(ctx.widths_used, emitted.text, exact) +
                            matrix_struct_types(ctx.matrices_used, exact) + emitted.text + helpers;
    if (options.target == Target::Webgl2) print_options.runtime = emit::spell_float_max_for_webgl(print_options.runtime);
    if (!ctx.rules_used.empty() && !exact) {
      if (guard.style == rules::GuardStyle::Precise) result.manifest.guard.kind = "precise";
      if (guard.style == rules::GuardStyle::Uniform) {
        print_options.guard_uniform = options.guard_uniform_name;
        result.manifest.guard.kind = "uniform";
        result.manifest.guard.uniform_name = options.guard_uniform_name;
        result.manifest.guard.uniform_type = "float";
        result.manifest.guard.required_value = 0;
      }
    }
  }
  print_options.after_structs = ctx.struct_helpers;
  emit::PrintResult printed = emit::print(module, print_options, options.file_name);
  diags.insert(diags.end(), printed.diagnostics.begin(), printed.diagnostics.end());
  if (std::any_of(diags.begin(), diags.end(), [](const Diagnostic& d) { return d.severity == Severity::Error; }))
    return result;

  next_phase("validate");
  std::string log = emit::validate(printed.text, *options.stage, options.target);
  next_phase("");
  if (!log.empty() && report_builtins_the_target_lacks(log, printed.builtin_first_use, options, diags)) return result;
  if (!log.empty() && report_what_the_source_lacks(source, log, options, diags)) return result;
  if (!log.empty()) {
    // Quote the emitted lines glslang names, so the report is actionable.
    const frontend::LineIndex lines(printed.text);
    std::string quoted;
    std::set<int> seen;
    for (int line : frontend::error_lines_of_main_string(log)) {
      if (!seen.insert(line).second || line > lines.line_count()) continue;
      quoted += "  line " + std::to_string(line) + ": " + std::string(lines.line(line)) + "\n";
    }
    log += quoted;
    diags.push_back({options.file_name, 0, 0, Severity::Error,
                     "internal error: the lowered shader is not valid " + std::string(to_string(options.target)) +
                         " GLSL (please report this with the input):\n" + log});
    return result;
  }
  if (options.target == Target::Webgl2) {
    std::string broken;
    for (const auto& v : emit::webgl_violations(printed.text))
      broken += "  line " + std::to_string(v.line) + ": " + v.message + "\n";
    if (!broken.empty()) {
      diags.push_back({options.file_name, 0, 0, Severity::Error,
                       "internal error: the lowered shader breaks WebGL 2.0's rules (please report this with the "
                       "input):\n" + broken});
      return result;
    }
  }
  result.output = std::move(printed.text);
  result.ok = true;
  return result;
}

// A file of 80,000 faulty lines gives 80,000 diagnostics: report the first
// kMaxDiagnostics and say how many more there were.
constexpr std::size_t kMaxDiagnostics = 100;

void cap_diagnostics(std::vector<Diagnostic>& diags, const std::string& file_name) {
  if (diags.size() <= kMaxDiagnostics) return;
  const auto hidden_errors = std::count_if(diags.begin() + kMaxDiagnostics, diags.end(),
                                           [](const Diagnostic& d) { return d.severity == Severity::Error; });
  const std::size_t hidden = diags.size() - kMaxDiagnostics;
  diags.resize(kMaxDiagnostics);
  diags.push_back({file_name, 0, 0, Severity::Note,
                   std::to_string(hidden) + " more diagnostics not shown (" + std::to_string(hidden_errors) +
                       " errors): fix the first ones and run again"});
}

}  // namespace

Result lower(std::string_view source, const Options& options) {
  if (options.target == Target::Wgsl) return lower_wgsl(source, options);
  try {
    if (source.size() > kMaxSourceBytes) {
      Result r;
      r.diagnostics.push_back({options.file_name, 1, 1, Severity::Error, frontend::source_too_large_message("input")});
      return r;
    }
    if (std::size_t depth = max_statement_operators(source); depth > kMaxStatementOperators) {
      Result r;
      r.diagnostics.push_back({options.file_name, 1, 1, Severity::Error, too_many_operators_message(depth, false)});
      return r;
    }
    Result result;
    std::exception_ptr failure;
    bool ran = run_with_big_stack([&] {
      try {
        result = lower_unchecked(source, options);
      } catch (...) {
        failure = std::current_exception();
      }
    });
    if (!ran) result = lower_unchecked(source, options);
    if (failure) std::rethrow_exception(failure);
    cap_diagnostics(result.diagnostics, options.file_name);
    return result;
  } catch (const std::exception& e) {
    Result r;
    r.diagnostics.push_back({options.file_name, 0, 0, Severity::Error, std::string("internal error: ") + e.what()});
    return r;
  } catch (...) {
    Result r;
    r.diagnostics.push_back({options.file_name, 0, 0, Severity::Error, "internal error"});
    return r;
  }
}

}  // namespace doublet

// The output checks at the end of the pipeline: glslang re-validates the printed text in the
// target's profile; what it rejects is reported at the user's code where the construct is the
// user's (a built-in or a construct the target lacks), and as an internal error otherwise.
#include "pipeline/validation.hpp"

#include <glslang/MachineIndependent/localintermediate.h>

#include <algorithm>
#include <map>
#include <set>

#include "emit/webgl_rules.hpp"
#include "frontend/demote.hpp"
#include "frontend/read_limited.hpp"
#include "frontend/text_scan.hpp"
#include "target/glslang_checks.hpp"
#include "target/target.hpp"

namespace doublet::pipeline {
namespace {

// glslang's re-validation is the authority on which built-in variables and functions a target
// and stage have (gl_ClipDistance on ES, gl_FragDepth or texelFetch on ES 1.00, ...). When it
// rejects one the user's shader uses, say so at the use instead of an internal error.
bool report_builtins_the_target_lacks(const std::string& log,
                                      const std::map<std::string, emit::PrintResult::BuiltinUse>& first_use,
                                      const State& state, std::vector<Diagnostic>& diags) {
  const Options& options = state.frontend_options;
  const Target profile = state.config.target;  // the GLSL profile lowered for (es310 under wgsl)
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
      const std::string target = state.config.target_name();
      const std::string& written = use->second.source_name;
      const char* stage = target::stage_noun(*options.stage);
      const bool variable = name.rfind("gl_", 0) == 0;
      std::string message = "the built-in '" + written + "'" + (written != name ? " (" + name + " there)" : "") +
                            (variable ? " does not exist in " : " has no such overload in ") + target + " " + stage +
                            " shaders";
      if (!variable) {
        message += "; remove it";
        if (profile != Target::Glsl450) message += ", or target glsl450 (desktop GLSL 4.50 has it)";
      } else if (const std::string have = target::targets_with_builtin_variable(written, *options.stage); !have.empty()) {
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
  if (!target::facts(target).carries_extensions || !parsed.intermediate) return names;
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
    // glslang lists the extensions that would allow a construct on the lines after its error.
    if (!errors.empty() && line.substr(0, 3) == "GL_" && errors.back().second.find("include:") != std::string::npos) {
      std::string& message = errors.back().second;
      message += (message.ends_with("include:") ? " " : ", ") + std::string(frontend::trim_blanks(line));
      continue;
    }
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
                                  const Config& config, std::vector<Diagnostic>& diags) {
  const Target profile = config.target;  // the GLSL profile lowered for (es310 under wgsl)
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
      if (!target::facts(profile).carries_extensions) extension_lines.insert(lines.line());
    }
  }
  if (version_line == 0) return false;
  // What an ES target needs before the user's code, after the #version and #extension lines (which
  // must come first), then `#line` so that the user's line numbers stay (ES and 3.30+: #line N
  // numbers the next line N).
  const int prelude_after = std::max(version_line, last_extension_line);
  std::string prelude;
  // The stage's own extension (es310 geometry and tessellation), as the lowering declares it.
  if (const char* extension = target::stage_extension(target::facts(profile), *options.stage))
    prelude += std::string("#extension ") + extension + " : require\n";
  for (const auto& [name, value] : options.defines) prelude += "#define " + name + " " + frontend::demote_doubles(value) + "\n";
  if (target_is_es(profile)) {
    prelude += "precision highp float;\nprecision highp int;\n";  // desktop shaders declare none
    if (target_version(profile) >= 300)
      for (const char* t : {"sampler3D", "samplerCubeShadow", "sampler2DShadow", "sampler2DArray", "sampler2DArrayShadow",
                            "isampler2D", "isampler3D", "isamplerCube", "isampler2DArray", "usampler2D", "usampler3D",
                            "usamplerCube", "usampler2DArray"})
        prelude += std::string("precision highp ") + t + ";\n";
  }
  prelude += "#line " + std::to_string(prelude_after + 1) + "\n";
  const frontend::LineIndex index(source);
  // The user's text with doubles read as floats, line for line (ES stops at the reserved word
  // `double`; `1.5lf` becomes `1.5`): frontend::demote_doubles, as verify's drop-lo uses it; its
  // `precise` blanked, which doublet drops with a warning where the target lacks it.
  const std::string demoted = frontend::blank_precise(frontend::demote_doubles(source));
  const frontend::LineIndex demoted_index(demoted);
  std::string text;
  for (int n = 1; n <= index.line_count(); ++n) {
    if (n == version_line)
      text += target::version_directive(profile) + "\n";
    else
      text += extension_lines.count(n) ? "\n" : std::string(demoted_index.line(n)) + "\n";
    if (n == prelude_after) text += prelude;
  }
  auto original = main_string_errors(target::validate(text, *options.stage, profile));
  // What doublet lowers is not the user's to change: a uniform's initializer goes to the manifest
  // on targets without them (uniform-defaults).
  std::erase_if(original, [](const auto& e) { return e.second.find("cannot initialize this type of qualifier") != std::string::npos; });
  std::set<std::string> original_messages;
  for (const auto& e : original) original_messages.insert(e.second);
  // glslang stops at some errors, in either text, so the lists need not be equal; the first
  // complaint about the lowered text decides (once the user has fixed it, any other shows). When the
  // shader itself stops earlier as the target, on something else (`uint % 4` has no implicit
  // conversion in ES, while the lowered text spells 4u), that is what the user must change first:
  // reported as such, not as an internal error (glslang's subgroup tests lowered for es310).
  if (original.empty()) return false;
  const bool same_complaint = original_messages.count(lowered.front().second) > 0;
  const std::set<std::string> lowered_messages = [&] {
    std::set<std::string> m;
    for (const auto& e : lowered) m.insert(e.second);
    return m;
  }();
  const std::string target = config.target_name();
  const std::string compiled_as = config.output == profile ? target
                                                           : std::string(to_string(profile)) + ", the GLSL " + target + " is lowered through";
  std::set<std::pair<int, std::string>> reported;
  for (const auto& [line, message] : original) {
    if ((same_complaint && !lowered_messages.count(message)) || !reported.insert({line, message}).second) continue;
    // glslang quotes the construct first ('vertex input arrays', 'gl_SubgroupSize', 'int'); point at it.
    std::string token;
    if (message.size() > 1 && message[0] == '\'') token = message.substr(1, message.find('\'', 1) - 1);
    const int column = frontend::column_in_row(index.line(line), token);
    diags.push_back({options.file_name, line, column, Severity::Error,
                     "target " + target + " does not allow this (glslang, compiling the shader itself as " + compiled_as +
                         ": " + message + "); change it, or choose a target that allows it"});
  }
  return true;
}

}  // namespace

std::vector<std::string> extensions_to_carry(const frontend::ParsedShader& parsed, Target target) {
  return carried_extensions(parsed, target);
}

bool validate_output(State& state) {
  auto& diags = state.result.diagnostics;
  const std::string& text = state.printed.text;
  const Config& config = state.config;
  std::string log = target::validate(text, config.stage, config.target);
  if (!log.empty() && report_builtins_the_target_lacks(log, state.printed.builtin_first_use, state, diags)) return false;
  if (!log.empty() && report_what_the_source_lacks(state.source, log, state.frontend_options, config, diags)) return false;
  if (!log.empty()) {
    // Quote the emitted lines glslang names, so the report is actionable.
    const frontend::LineIndex lines(text);
    std::string quoted;
    std::set<int> seen;
    for (int line : frontend::error_lines_of_main_string(log)) {
      if (!seen.insert(line).second || line > lines.line_count()) continue;
      quoted += "  line " + std::to_string(line) + ": " + std::string(lines.line(line)) + "\n";
    }
    log += quoted;
    diags.push_back({config.file_name, 0, 0, Severity::Error,
                     "internal error: the lowered shader is not valid " + std::string(to_string(config.target)) +
                         " GLSL (please report this with the input):\n" + log});
    return false;
  }
  if (config.facts->webgl_rules) {
    std::string broken;
    for (const auto& v : emit::webgl_violations(text))
      broken += "  line " + std::to_string(v.line) + ": " + v.message + "\n";
    if (!broken.empty()) {
      diags.push_back({config.file_name, 0, 0, Severity::Error,
                       "internal error: the lowered shader breaks WebGL 2.0's rules (please report this with the "
                       "input):\n" + broken});
      return false;
    }
  }
  return true;
}

}  // namespace doublet::pipeline

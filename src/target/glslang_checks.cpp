#include "target/glslang_checks.hpp"

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>

#include "frontend/glslang_stage.hpp"

#include <map>
#include <mutex>

#include "frontend/frontend.hpp"
#include "target/target.hpp"

namespace doublet::target {

std::string validate(std::string_view text, Stage stage, Target target) {
  frontend::ensure_glslang_initialized();
  EShLanguage lang = frontend::glslang_stage(stage);
  glslang::TShader shader(lang);
  std::string source(text);
  const char* strings[] = {source.c_str()};
  shader.setStrings(strings, 1);
  shader.setEnvInput(glslang::EShSourceGlsl, lang, glslang::EShClientNone, 100);
  shader.setEnvClient(glslang::EShClientNone, glslang::EShTargetClientVersion(0));
  shader.setEnvTarget(glslang::EShTargetNone, glslang::EShTargetLanguageVersion(0));
  EProfile profile = facts(target).es ? EEsProfile : ECoreProfile;
  if (shader.parse(&frontend::resource_limits(), facts(target).version, profile, false, false, EShMsgDefault)) return "";
  std::string log = shader.getInfoLog();
  return log.empty() ? "glslang rejected the output without a message" : log;
}

// glslang calls a missing opaque type a reserved word or does not parse it as a type at all.
bool opaque_type_exists(const std::string& name, Target target) {
  static std::mutex mutex;
  static std::map<std::pair<std::string, Target>, bool> known;
  std::lock_guard<std::mutex> lock(mutex);
  auto [it, inserted] = known.try_emplace({name, target}, true);
  if (inserted) {
    const std::string log = validate(version_directive(target) + "\nprecision highp float;\nuniform highp " + name +
                                         " probe;\nvoid main() {}\n",
                                     Stage::Fragment, target);
    it->second = log.find("Reserved word") == std::string::npos && log.find("syntax error") == std::string::npos;
  }
  return it->second;
}

// glslang reports a prototype of a built-in name as "'NAME' : function name is redeclaration of
// existing name" and stops at the first, so the probe is parsed again without it until it passes
// (one parse per built-in name found, plus one; about 200 built-in names exist, so this is bounded
// whatever the shader).
std::set<std::string> builtin_function_names(std::set<std::string> names, Target target, Stage stage) {
  const std::string header = version_directive(target) + "\nprecision highp float;\n";
  const std::string marker = "' : function name is redeclaration of existing name";
  std::set<std::string> builtins;
  while (!names.empty()) {
    std::string probe = header;
    for (const auto& name : names) probe += "void " + name + "(int doublet_probe, int doublet_probe2, int doublet_probe3);\n";
    if (stage == Stage::Compute) probe += "layout(local_size_x = 1) in;\n";
    probe += "void main() {}\n";
    const std::string log = validate(probe, stage, target);
    const size_t at = log.find(marker);
    if (at == std::string::npos) break;
    const size_t open = log.rfind('\'', at - 1);
    const std::string name = open == std::string::npos ? "" : log.substr(open + 1, at - open - 1);
    if (!names.erase(name)) break;  // not one of ours: stop rather than loop
    builtins.insert(name);
  }
  return builtins;
}

// One one-line probe per target (webgl2 is es300 here): compatibility-profile names are in none.
std::string targets_with_builtin_variable(const std::string& name, Stage stage) {
  static std::mutex mutex;
  static std::map<std::pair<std::string, Stage>, std::string> known;
  std::lock_guard<std::mutex> lock(mutex);
  auto [it, inserted] = known.try_emplace({name, stage});
  if (!inserted) return it->second;
  for (Target t : all_targets(false)) {
    if (facts(t).webgl_rules) continue;
    const std::string layout = stage == Stage::Compute ? "layout(local_size_x = 1) in;\n" : "";
    const std::string log =
        validate(version_directive(t) + "\nprecision highp float;\n" + layout + "void main() { " + name + "; }\n", stage, t);
    if (log.find("undeclared identifier") == std::string::npos)
      it->second += (it->second.empty() ? "" : ", ") + std::string(facts(t).name);
  }
  return it->second;
}

}  // namespace doublet::target

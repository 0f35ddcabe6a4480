#include "emit/validate.hpp"

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>

#include "frontend/frontend.hpp"

namespace doublet::emit {

std::string version_directive(Target target) {
  const std::string version = "#version " + std::to_string(target_version(target));
  return target == Target::Es100 ? version : version + (target_is_es(target) ? " es" : " core");
}

std::string validate(std::string_view text, Stage stage, Target target) {
  frontend::ensure_glslang_initialized();
  EShLanguage lang = stage == Stage::Vertex ? EShLangVertex : stage == Stage::Fragment ? EShLangFragment : EShLangCompute;
  glslang::TShader shader(lang);
  std::string source(text);
  const char* strings[] = {source.c_str()};
  shader.setStrings(strings, 1);
  shader.setEnvInput(glslang::EShSourceGlsl, lang, glslang::EShClientNone, 100);
  shader.setEnvClient(glslang::EShClientNone, glslang::EShTargetClientVersion(0));
  shader.setEnvTarget(glslang::EShTargetNone, glslang::EShTargetLanguageVersion(0));
  EProfile profile = target_is_es(target) ? EEsProfile : ECoreProfile;
  if (shader.parse(&frontend::resource_limits(), target_version(target), profile, false, false, EShMsgDefault)) return "";
  std::string log = shader.getInfoLog();
  return log.empty() ? "glslang rejected the output without a message" : log;
}

}  // namespace doublet::emit

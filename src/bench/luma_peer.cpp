#include "bench/luma_peer.hpp"

#include <sys/stat.h>

#include <cstdlib>
#include <mutex>
#include <regex>

#include <nlohmann/json.hpp>

#include "runner/browser.hpp"

namespace doublet::bench {

std::string peer_tools_dir() {
  if (const char* dir = std::getenv("DOUBLET_PEER_TOOLS"); dir && *dir) return dir;
  return DOUBLET_SOURCE_DIR "/tools/peers";
}

namespace {

LumaLibrary load() {
  LumaLibrary lib;
  const std::string tools = peer_tools_dir();
  struct stat st {};
  if (::stat((tools + "/node_modules/@luma.gl/shadertools").c_str(), &st) != 0) {
    lib.unavailable = true;
    lib.error = "@luma.gl/shadertools is not installed (cd " + tools + " && npm ci)";
    return lib;
  }
  const runner::NodeScriptRun run = runner::run_node_script(tools + "/luma-fp64.mjs", {}, 60000);
  if (!run.ok) {
    lib.unavailable = run.unavailable;
    lib.error = run.error;
    return lib;
  }
  const nlohmann::json j = nlohmann::json::parse(run.out, nullptr, false);
  if (j.is_discarded() || !j.contains("glsl") || !j.contains("uniforms") || !j.contains("version")) {
    lib.error = "luma-fp64.mjs printed no library";
    return lib;
  }
  lib.version = j["version"].get<std::string>();
  std::string glsl = j["glsl"].get<std::string>();
  // The module's uniform block, as luma.gl declares it: `uniform fp64arithmeticUniforms {...} fp64;`.
  const std::regex block(R"(layout\(std140\)\s*uniform\s+fp64arithmeticUniforms\s*\{[^}]*\}\s*fp64\s*;)");
  if (!std::regex_search(glsl, block)) {
    lib.error = "@luma.gl/shadertools " + lib.version + ": no fp64arithmeticUniforms block (the module changed)";
    return lib;
  }
  glsl = std::regex_replace(glsl, block, "uniform float luma_fp64_ONE;\nuniform float luma_fp64_SPLIT;");
  glsl = std::regex_replace(glsl, std::regex(R"(\bfp64\.(ONE|SPLIT)\b)"), "luma_fp64_$1");
  for (const char* name : {"ONE", "SPLIT"}) {
    if (!j["uniforms"].contains(name)) {
      lib.error = std::string("luma-fp64.mjs: no default for uniform ") + name;
      return lib;
    }
    lib.uniforms[std::string("luma_fp64_") + name] = j["uniforms"][name].get<float>();
  }
  lib.glsl = std::move(glsl);
  lib.ok = true;
  return lib;
}

}  // namespace

const LumaLibrary& luma_fp64_library() {
  static std::once_flag once;
  static LumaLibrary lib;
  std::call_once(once, [] { lib = load(); });
  return lib;
}

}  // namespace doublet::bench

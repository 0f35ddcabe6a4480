// Every webgl2 golden output (tests/golden/expected/*.webgl2.glsl) compiled and linked by the real
// WebGL2 of headless Chromium (ANGLE → Vulkan → SwiftShader, through tools/browser): each shader
// is linked with a trivial partner stage (a fragment shader writing one colour; for a fragment
// shader, a vertex shader writing every input it reads), and ANGLE's info logs come back.
// The same page compiles the es300 output of webgl2_ternaries.frag, which keeps its struct
// ternaries: ANGLE must reject it, so the check is shown to catch what select_structs removes.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "browser_test_util.hpp"
#include "runner/browser.hpp"

namespace {

namespace fs = std::filesystem;

// The page: for each {name, stage, source} of shaders.json, compile it and its partner, link
// them, and report compile/link status and the info logs.
constexpr const char* kPage = R"(<!doctype html><script type="module">
window.doubletResult = (async () => {
  const shaders = await (await fetch('shaders.json')).json();
  const gl = document.createElement('canvas').getContext('webgl2');
  if (!gl) throw new Error('no WebGL2 context');
  const compile = (type, source) => {
    const s = gl.createShader(type);
    gl.shaderSource(s, source);
    gl.compileShader(s);
    return { shader: s, ok: !!gl.getShaderParameter(s, gl.COMPILE_STATUS), log: gl.getShaderInfoLog(s) || '' };
  };
  // A vertex shader writing every input the fragment shader declares, with the same qualifiers.
  const vertexPartner = (fragment) => {
    let outs = '';
    for (const line of fragment.split('\n')) {
      const m = /^\s*((?:(?:flat|smooth|centroid)\s+)*)in\s+([^;]+);/.exec(line);
      if (m) outs += m[1] + 'out ' + m[2] + ';\n';
    }
    return '#version 300 es\n' + outs + 'void main() { gl_Position = vec4(0.0); }\n';
  };
  const fragmentPartner = '#version 300 es\nprecision highp float;\nout vec4 partner_color;\n' +
                          'void main() { partner_color = vec4(1.0); }\n';
  const results = [];
  for (const { name, stage, source } of shaders) {
    const own = compile(stage === 'vert' ? gl.VERTEX_SHADER : gl.FRAGMENT_SHADER, source);
    const partner = stage === 'vert' ? compile(gl.FRAGMENT_SHADER, fragmentPartner)
                                     : compile(gl.VERTEX_SHADER, vertexPartner(source));
    let linked = false, linkLog = '';
    if (own.ok && partner.ok) {
      const p = gl.createProgram();
      gl.attachShader(p, own.shader);
      gl.attachShader(p, partner.shader);
      gl.linkProgram(p);
      linked = !!gl.getProgramParameter(p, gl.LINK_STATUS);
      linkLog = gl.getProgramInfoLog(p) || '';
    }
    results.push({ name, compiled: own.ok, log: own.log, partner: partner.ok, partnerLog: partner.log, linked, linkLog });
  }
  return { renderer: gl.getParameter(gl.RENDERER), results };
})();
</script>
)";

struct Shader {
  std::string name, stage, source;
};

std::string read(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// <case>.<stage>.<target>.glsl files of tests/golden/expected for `target`.
std::vector<Shader> golden_outputs(const std::string& target) {
  std::vector<Shader> out;
  for (const auto& entry : fs::directory_iterator(fs::path(DOUBLET_GOLDEN_DIR) / "expected")) {
    const std::string file = entry.path().filename().string();
    const std::string suffix = "." + target + ".glsl";
    if (file.size() <= suffix.size() || file.compare(file.size() - suffix.size(), suffix.size(), suffix) != 0)
      continue;
    const std::string stem = file.substr(0, file.size() - suffix.size());  // name.stage
    out.push_back({file, stem.substr(stem.rfind('.') + 1), read(entry.path())});
  }
  std::sort(out.begin(), out.end(), [](const Shader& a, const Shader& b) { return a.name < b.name; });
  return out;
}

nlohmann::json compile_in_browser(const std::vector<Shader>& shaders) {
  const fs::path dir = fs::temp_directory_path() / ("doublet-webgl2-golden-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  nlohmann::json list = nlohmann::json::array();
  for (const auto& s : shaders) list.push_back({{"name", s.name}, {"stage", s.stage}, {"source", s.source}});
  std::ofstream(dir / "shaders.json") << list.dump();
  std::ofstream(dir / "index.html") << kPage;
  doublet::runner::BrowserPageOptions options;
  options.timeout_ms = 300000;
  const auto run = doublet::runner::run_browser_page(dir.string(), options);
  fs::remove_all(dir);
  EXPECT_TRUE(run.ok) << run.error << "\n" << run.log;
  return run.ok ? nlohmann::json::parse(run.result_json) : nlohmann::json();
}

TEST(Webgl2Browser, EveryGoldenOutputCompilesAndLinksInChromiumWebGL2) {
  DOUBLET_REQUIRE_BROWSER_OR_SKIP();
  std::vector<Shader> shaders = golden_outputs("webgl2");
  ASSERT_GE(shaders.size(), 30u) << "the webgl2 goldens are missing";
  const std::size_t webgl2_count = shaders.size();
  // The control: es300 output with struct ternaries, which WebGL must refuse.
  std::vector<Shader> es300 = golden_outputs("es300");
  auto control = std::find_if(es300.begin(), es300.end(),
                              [](const Shader& s) { return s.name == "webgl2_ternaries.frag.es300.glsl"; });
  ASSERT_NE(control, es300.end());
  shaders.push_back(*control);

  const nlohmann::json page = compile_in_browser(shaders);
  ASSERT_TRUE(page.contains("results"));
  const auto& results = page["results"];
  ASSERT_EQ(results.size(), shaders.size());
  std::cout << "renderer: " << page["renderer"].get<std::string>() << "\n";
  for (std::size_t i = 0; i < webgl2_count; ++i) {
    const auto& r = results[i];
    const std::string name = r["name"];
    EXPECT_TRUE(r["compiled"].get<bool>()) << name << " does not compile in WebGL2:\n" << r["log"].get<std::string>();
    EXPECT_TRUE(r["partner"].get<bool>()) << name << ": the partner stage does not compile:\n"
                                          << r["partnerLog"].get<std::string>();
    EXPECT_TRUE(r["linked"].get<bool>()) << name << " does not link in WebGL2:\n" << r["linkLog"].get<std::string>();
    // ANGLE's warnings (Float overflow on a literal above FLT_MAX, ...) count as failures too.
    EXPECT_EQ(r["log"].get<std::string>(), "") << name << ": ANGLE's info log";
  }
  const auto& rejected = results[webgl2_count];
  EXPECT_FALSE(rejected["compiled"].get<bool>()) << "the es300 control with struct ternaries compiled in WebGL2";
  EXPECT_NE(rejected["log"].get<std::string>().find("ternary operator is not allowed for structures"), std::string::npos)
      << rejected["log"].get<std::string>();
  // es300 spells FLT_MAX 3.40282347e38, above FLT_MAX as a real number: ANGLE warns, which the
  // empty-log check above would catch in a webgl2 output.
  EXPECT_NE(rejected["log"].get<std::string>().find("Float overflow"), std::string::npos)
      << rejected["log"].get<std::string>();
}

}  // namespace

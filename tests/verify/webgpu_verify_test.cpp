// `doublet verify --backend webgpu` as users run it: the WGSL lowering in headless Chromium's WebGPU,
// the original in fp64 on lavapipe. add, sub, mul, div, sqrt and a three-stage expression must reach
// 44 bits; drop-lo must fail everywhere; without the guard nothing folds on this stack since TwoProd
// splits by bits (docs/web.md), and df64-int needs no guard. A vertex shader is an input error.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "../runner/browser_test_util.hpp"

namespace {

namespace fs = std::filesystem;

struct CliRun {
  int exit_code = -1;
  std::string out;
  nlohmann::json report;
};

CliRun verify(const std::string& args) {
  CliRun r;
  const fs::path json = fs::temp_directory_path() / ("doublet-webgpu-verify-" + std::to_string(::getpid()) + ".json");
  fs::remove(json);
  const std::string cmd = std::string(DOUBLET_CLI_PATH) + " verify " + args + " --json " + json.string() + " 2>&1";
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return r;
  char buf[4096];
  while (size_t n = fread(buf, 1, sizeof buf, p)) r.out.append(buf, n);
  const int status = pclose(p);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  if (std::ifstream in(json); in) r.report = nlohmann::json::parse(in, nullptr, false);
  fs::remove(json);
  return r;
}

const std::string kOps = std::string(DOUBLET_VERIFY_SHADERS) + "/webgpu/ops.comp";
const std::map<std::string, std::string> kOutputs{{"add", "add_sub[].x"},  {"sub", "add_sub[].y"},
                                                  {"mul", "mul_div[].x"},  {"div", "mul_div[].y"},
                                                  {"sqrt", "sqrt_chain[].x"}, {"3 stages", "sqrt_chain[].y"}};

std::string args(const std::string& extra) {
  return kOps + " --spec " + kOps + ".json --min-bits 44 --backend webgpu " + extra;
}

std::map<std::string, double> bits(const CliRun& r) {
  std::map<std::string, double> out;
  if (!r.report.is_object()) return out;
  for (const auto& run : r.report.at("runs"))
    if (run.at("backend") == "webgpu")
      for (const auto& [op, name] : kOutputs)
        for (const auto& o : run.at("outputs"))
          if (o.at("name") == name) out[op] = o.at("min_bits").get<double>();
  return out;
}

TEST(WebGpuVerify, Keeps44BitsInChromium) {
  DOUBLET_REQUIRE_BROWSER_OR_SKIP();
  const CliRun r = verify(args(""));
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const auto& run = r.report.at("runs").at(0);
  EXPECT_NE(run.at("driver").get<std::string>().find("WebGPU"), std::string::npos) << run.at("driver");
  const auto measured = bits(r);
  ASSERT_EQ(measured.size(), kOutputs.size()) << r.out;
  for (const auto& [op, b] : measured) EXPECT_GE(b, 44) << op << "\n" << r.out;
}

TEST(WebGpuVerify, DropLoFailsInChromium) {
  DOUBLET_REQUIRE_BROWSER_OR_SKIP();
  const CliRun r = verify(args("--sabotage drop-lo"));
  ASSERT_EQ(r.exit_code, 1) << r.out;
  const auto measured = bits(r);
  ASSERT_EQ(measured.size(), kOutputs.size()) << r.out;
  for (const auto& [op, b] : measured) EXPECT_LT(b, 30) << op << "\n" << r.out;
}

// Dawn/SwiftShader folded the products, quotients and roots through Veltkamp's split without the
// guard; the split by bits leaves it nothing to fold, so df64 keeps its bits there, as df64-int
// (which has no guard) does. A browser that starts folding sums fails this: update docs/web.md.
TEST(WebGpuVerify, DropGuardKeepsItsBitsAndDf64IntNeedsNoGuard) {
  DOUBLET_REQUIRE_BROWSER_OR_SKIP();
  for (const std::string mode : {"df64", "df64-int"}) {
    const CliRun unguarded = verify(args("--sabotage drop-guard --mode " + mode));
    ASSERT_EQ(unguarded.exit_code, 0) << mode << "\n" << unguarded.out;
    const auto kept = bits(unguarded);
    ASSERT_EQ(kept.size(), kOutputs.size()) << unguarded.out;
    for (const auto& [op, b] : kept) EXPECT_GE(b, 44) << mode << " " << op << "\n" << unguarded.out;
  }
}

// Mode exact in WGSL: binary64 in u32 arithmetic in Chromium's WebGPU, bit-identical to native fp64
// on lavapipe (ties included); rounding ties away from zero must differ there too.
TEST(WebGpuVerify, ExactIsBitIdenticalInChromiumAndTiesAwayFails) {
  DOUBLET_REQUIRE_BROWSER_OR_SKIP();
  CliRun r = verify(kOps + " --spec " + kOps + ".json --backend webgpu --mode exact");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("identical bits required: 0 of"), std::string::npos) << r.out;
  const std::string ties = std::string(DOUBLET_VERIFY_SHADERS) + "/exact_words.comp --spec " +
                           std::string(DOUBLET_VERIFY_SHADERS) + "/exact_ties.json --backend webgpu --mode exact";
  r = verify(ties);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_EQ(r.out.find("FAIL"), std::string::npos) << r.out;
  r = verify(ties + " --sabotage ties-away");
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_NE(r.out.find("FAIL"), std::string::npos) << r.out;
}

// std140 storage arrays of doubles and floats: WGSL's own stride (8, 4) is not std140's (16), which
// the host writes; doublet pads the elements. Before, the shader was refused; printed without the
// padding, every value is misread (0 bits). drop-lo shows the check can fail.
TEST(WebGpuVerify, Std140ArraysAreReadAtStd140Strides) {
  DOUBLET_REQUIRE_BROWSER_OR_SKIP();
  const std::string shader = std::string(DOUBLET_VERIFY_SHADERS) + "/webgpu/std140.comp";
  const std::string common = shader + " --spec " + shader + ".json --min-bits 44 --backend webgpu";
  auto min_bits = [](const CliRun& r) {
    for (const auto& o : r.report.at("runs").at(0).at("outputs"))
      if (o.at("name") == "o[]") return o.at("min_bits").get<double>();
    return -1.0;
  };
  const CliRun kept = verify(common);
  ASSERT_EQ(kept.exit_code, 0) << kept.out;
  EXPECT_GE(min_bits(kept), 44) << kept.out;
  const CliRun dropped = verify(common + " --sabotage drop-lo");
  ASSERT_EQ(dropped.exit_code, 1) << dropped.out;
  EXPECT_LT(min_bits(dropped), 30) << dropped.out;
}

// Buffer elements passed to out/inout parameters, inside an expression and as a statement, and to
// the generated helpers' (w[i].x = ..., w[i][1] = ...) and modf's whole part, two calls in one
// statement (hoisted in their order): WGSL's pointers point to function memory only, so they go through temporaries
// (wgsl-out-arguments, then hoist-commas). Before, the expression form, and then two calls in one
// statement, were refused. drop-lo shows the check can fail.
TEST(WebGpuVerify, BufferElementsAsOutArgumentsKeep44Bits) {
  DOUBLET_REQUIRE_BROWSER_OR_SKIP();
  const std::string shader = std::string(DOUBLET_VERIFY_SHADERS) + "/webgpu/out_arguments.comp";
  const CliRun kept = verify(shader + " --min-bits 44 --backend webgpu");
  ASSERT_EQ(kept.exit_code, 0) << kept.out;
  int outputs = 0;
  for (const auto& o : kept.report.at("runs").at(0).at("outputs")) {
    EXPECT_GE(o.at("min_bits").get<double>(), 44) << o.at("name") << "\n" << kept.out;
    ++outputs;
  }
  EXPECT_EQ(outputs, 7) << kept.out;
  const CliRun dropped = verify(shader + " --min-bits 44 --backend webgpu --sabotage drop-lo");
  EXPECT_EQ(dropped.exit_code, 1) << dropped.out;
  EXPECT_NE(dropped.out.find("w[].y"), std::string::npos) << dropped.out;
  EXPECT_NE(dropped.out.find("FAIL (< 44.0)"), std::string::npos) << dropped.out;
}

// Increments and assignments inside expressions (`tmp[n++] = ...`, `tmp[m++] - tmp[m++]`,
// `(acc = v * 3) + acc`), under ?: and && and in a loop condition: refused for WGSL before; now
// temporaries hoisted in GLSL's order, if/else for what is evaluated only sometimes. Both operand
// orders matter to r[].w (3v - 6v, not 6v - 3v); u[] is 18 v or 30 v only if each branch and
// test ran as in GLSL. drop-lo shows the check can fail.
TEST(WebGpuVerify, IncrementsAndAssignmentsInsideExpressionsKeep44Bits) {
  DOUBLET_REQUIRE_BROWSER_OR_SKIP();
  // Both signs of v: both branches of each ?: and loop test.
  const std::string shader = std::string(DOUBLET_VERIFY_SHADERS) + "/webgpu/expression_effects.comp --range v=-4:4";
  const CliRun kept = verify(shader + " --min-bits 44 --backend webgpu");
  ASSERT_EQ(kept.exit_code, 0) << kept.out;
  int outputs = 0;
  for (const auto& o : kept.report.at("runs").at(0).at("outputs")) {
    EXPECT_GE(o.at("min_bits").get<double>(), 44) << o.at("name") << "\n" << kept.out;
    ++outputs;
  }
  EXPECT_EQ(outputs, 7) << kept.out;
  const CliRun dropped = verify(shader + " --min-bits 44 --backend webgpu --sabotage drop-lo");
  EXPECT_EQ(dropped.exit_code, 1) << dropped.out;
  EXPECT_NE(dropped.out.find("FAIL (< 44.0)"), std::string::npos) << dropped.out;
}

TEST(WebGpuVerify, VertexShaderAndManyDispatchesAreInputErrors) {
  const CliRun vertex = verify(std::string(DOUBLET_VERIFY_SHADERS) + "/pairs.vert --backend webgpu");
  EXPECT_EQ(vertex.exit_code, 2) << vertex.out;
  EXPECT_NE(vertex.out.find("verifies compute shaders"), std::string::npos) << vertex.out;
  // uniform_pairs.comp takes its operands from uniforms: a dispatch per sample.
  const std::string uniforms = std::string(DOUBLET_VERIFY_SHADERS) + "/uniform_pairs.comp";
  const CliRun many = verify(uniforms + " --spec " + std::string(DOUBLET_VERIFY_SHADERS) +
                             "/uniform_pairs.json --backend webgpu --samples 64");
  EXPECT_EQ(many.exit_code, 2) << many.out;
  EXPECT_NE(many.out.find("one browser page per dispatch"), std::string::npos) << many.out;
}

}  // namespace

// `doublet verify --backend webgl2` as users run it: the lowered shader in headless Chromium's
// WebGL2, the original in fp64 on lavapipe. Held-out-style accuracy (add, sub, mul, div, sqrt, a
// cancelling sum, a three-stage expression) must reach 44 bits in a fragment and a vertex shader,
// and drop-lo (doubles demoted to float) must turn the same check red in the browser everywhere.
// drop-guard (no optimizer guard) keeps every bit on this stack since TwoProd splits by bits: the
// browser's compiler folded only Veltkamp's split (docs/web.md). A shader WebGL rejects is a driver failure
// carrying the browser's log; a compute shader or a target WebGL2 cannot compile is an input error.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
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
  std::string out;  // stdout and stderr
  nlohmann::json report;  // --json, when the run wrote one
};

const std::string kShaders = DOUBLET_VERIFY_SHADERS;

CliRun verify(const std::string& args, const std::string& env = "") {
  CliRun r;
  const fs::path json = fs::temp_directory_path() / ("doublet-webgl2-verify-" + std::to_string(::getpid()) + ".json");
  fs::remove(json);
  const std::string cmd = env + " " + std::string(DOUBLET_CLI_PATH) + " verify " + args + " --json " + json.string() + " 2>&1";
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

// Which output component holds which operation, per shader (tests/verify/shaders/webgl2/ops.*).
struct Ops {
  std::string file;
  std::map<std::string, std::string> outputs;  // operation -> output name in the report
};
const Ops kFragment{"ops.frag",
                    {{"add", "add_sub.xy"}, {"sub", "add_sub.zw"}, {"mul", "mul_div.xy"}, {"div", "mul_div.zw"},
                     {"sqrt", "sqrt_cancel.xy"}, {"cancellation", "sqrt_cancel.zw"}, {"3 stages", "chain.xy"}}};
const Ops kVertex{"ops.vert",
                  {{"add", "add_sub_mul_div.x"}, {"sub", "add_sub_mul_div.y"}, {"mul", "add_sub_mul_div.z"},
                   {"div", "add_sub_mul_div.w"}, {"sqrt", "sqrt_cancel.x"}, {"cancellation", "sqrt_cancel.y"},
                   {"3 stages", "chain"}}};

std::string args(const Ops& ops, const std::string& backend, const std::string& sabotage = "none") {
  const std::string dir = kShaders + "/webgl2/";
  return dir + ops.file + " --spec " + dir + ops.file + ".json --samples 4096 --min-bits 44 --backend " + backend +
         " --sabotage " + sabotage;
}

// Min bits per operation in the report's run on `backend`.
std::map<std::string, double> bits(const CliRun& r, const Ops& ops, const std::string& backend) {
  std::map<std::string, double> out;
  for (const auto& run : r.report.at("runs"))
    if (run.at("backend") == backend)
      for (const auto& [op, name] : ops.outputs)
        for (const auto& o : run.at("outputs"))
          if (o.at("name") == name) out[op] = o.at("min_bits").get<double>();
  return out;
}

class WebGl2Verify : public ::testing::TestWithParam<Ops> {};

TEST_P(WebGl2Verify, Keeps44BitsInChromium) {
  DOUBLET_REQUIRE_BROWSER_OR_SKIP();
  // The vertex case runs every backend (--backend all); the fragment case WebGL2 alone.
  const bool all = GetParam().file == "ops.vert";
  const CliRun r = verify(args(GetParam(), all ? "all" : "webgl2"));
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const auto& runs = r.report.at("runs");
  ASSERT_EQ(runs.size(), all ? 3u : 1u) << r.out;
  const auto& webgl2 = runs.back();
  EXPECT_EQ(webgl2.at("backend"), "webgl2");
  EXPECT_TRUE(webgl2.at("error").is_null());
  EXPECT_TRUE(webgl2.at("probe").at("error").is_null()) << webgl2.at("probe");
  // The driver is the browser's unmasked renderer, not the Mesa device of the native run.
  EXPECT_FALSE(webgl2.at("driver").get<std::string>().empty());
  EXPECT_NE(webgl2.at("driver"), webgl2.at("reference_driver"));
  for (const std::string backend : all ? std::vector<std::string>{"vulkan", "gles", "webgl2"} : std::vector<std::string>{"webgl2"}) {
    const auto measured = bits(r, GetParam(), backend);
    ASSERT_EQ(measured.size(), GetParam().outputs.size()) << r.out;
    for (const auto& [op, b] : measured) EXPECT_GE(b, 44) << backend << " " << op << "\n" << r.out;
  }
}

TEST_P(WebGl2Verify, DropLoFailsInChromium) {
  DOUBLET_REQUIRE_BROWSER_OR_SKIP();
  const CliRun r = verify(args(GetParam(), "webgl2", "drop-lo"));
  ASSERT_EQ(r.exit_code, 1) << r.out;
  const auto measured = bits(r, GetParam(), "webgl2");
  ASSERT_EQ(measured.size(), GetParam().outputs.size()) << r.out;
  for (const auto& [op, b] : measured) EXPECT_LT(b, 30) << op << " kept its bits with doubles demoted\n" << r.out;
}

// Without the guard nothing folds here: ANGLE/SwiftShader folded the products, quotients and roots
// through Veltkamp's split (a*4097 - ...), which the split by bits (rules/core.glsl) does not have.
// If a browser update starts folding sums, this fails: re-measure and update docs/web.md.
TEST_P(WebGl2Verify, DropGuardKeepsItsBitsInChromium) {
  DOUBLET_REQUIRE_BROWSER_OR_SKIP();
  const CliRun r = verify(args(GetParam(), "webgl2", "drop-guard"));
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const auto measured = bits(r, GetParam(), "webgl2");
  ASSERT_EQ(measured.size(), GetParam().outputs.size()) << r.out;
  for (const auto& [op, b] : measured) EXPECT_GE(b, 44) << op << " lost its bits without the guard\n" << r.out;
}

// df64-int with the guard removed (it has none to begin with) keeps every bit the guarded df64
// keeps: issue 14's "df64-int holds >= 44 bits with the guard removed" in WebGL2.
TEST_P(WebGl2Verify, Df64IntNeedsNoGuardInChromium) {
  DOUBLET_REQUIRE_BROWSER_OR_SKIP();
  const CliRun r = verify(args(GetParam(), "webgl2", "drop-guard") + " --mode df64-int");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const auto measured = bits(r, GetParam(), "webgl2");
  ASSERT_EQ(measured.size(), GetParam().outputs.size()) << r.out;
  for (const auto& [op, b] : measured) EXPECT_GE(b, 44) << op << "\n" << r.out;
}

INSTANTIATE_TEST_SUITE_P(Stages, WebGl2Verify, ::testing::Values(kFragment, kVertex),
                         [](const auto& info) { return info.param.file == "ops.frag" ? "fragment" : "vertex"; });

TEST(WebGl2VerifyErrors, ShaderWebGlRejectsIsADriverFailureWithTheBrowsersLog) {
  DOUBLET_REQUIRE_BROWSER_OR_SKIP();
  // es300 lowers the double ternary to a ternary on structs: ES 3.00 allows it, WebGL does not.
  const CliRun r = verify(kShaders + "/webgl2/ternary.frag --backend webgl2 --target es300 --min-bits 44");
  EXPECT_EQ(r.exit_code, 3) << r.out;
  EXPECT_NE(r.out.find("ternary operator is not allowed for structures"), std::string::npos) << r.out;
  EXPECT_NE(r.report.at("runs").at(0).at("error").get<std::string>().find("GLSL compile failed"), std::string::npos);
  // The log's line number is the lowered text's (the wrapper's own lines are not counted).
  const fs::path lowered = fs::temp_directory_path() / ("doublet-webgl2-ternary-" + std::to_string(::getpid()) + ".frag");
  ASSERT_EQ(std::system((std::string(DOUBLET_CLI_PATH) + " lower " + kShaders + "/webgl2/ternary.frag --target es300 -o " +
                         lowered.string()).c_str()), 0);
  std::ifstream in(lowered);
  int line_number = 0, ternary_line = 0;
  for (std::string line; std::getline(in, line);)
    if (++line_number && line.find("df_double r = ") != std::string::npos && line.find(" ? ") != std::string::npos)
      ternary_line = line_number;
  fs::remove(lowered);
  ASSERT_GT(ternary_line, 0);
  EXPECT_NE(r.out.find("0:" + std::to_string(ternary_line) + ": '?:'"), std::string::npos) << "line " << ternary_line << "\n" << r.out;
}

// Decided before anything runs: no browser needed.
TEST(WebGl2VerifyErrors, ComputeShaderIsAnInputErrorThatNamesWebGpu) {
  const CliRun r = verify(kShaders + "/arith_pairs.comp --spec " + kShaders + "/arith_pairs.json --backend webgl2");
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_NE(r.out.find("WebGL2 has no compute shaders"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("webgpu"), std::string::npos) << r.out;
}

TEST(WebGl2VerifyErrors, TargetWebGl2CannotCompileIsAnInputError) {
  const CliRun r = verify(kShaders + "/webgl2/ops.frag --backend webgl2 --target es310");
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_NE(r.out.find("--target es300"), std::string::npos) << r.out;
}

TEST(WebGl2VerifyErrors, SweepOnWebGl2IsAnInputError) {
  const CliRun r = verify("--sweep add --backend webgl2");
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_NE(r.out.find("WebGL2 lacks"), std::string::npos) << r.out;
}

// With --backend all a compute shader still runs on the drivers that have compute; WebGL2 is skipped with a note.
TEST(WebGl2VerifyErrors, AllSkipsWebGl2ForComputeWithANote) {
  const CliRun r = verify(kShaders + "/arith_pairs.comp --spec " + kShaders + "/arith_pairs.json --samples 256 --backend all");
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("WebGL2 backend skipped"), std::string::npos) << r.out;
  EXPECT_EQ(r.report.at("runs").size(), 2u);
}

// No browser here: the WebGL2 run fails as a driver failure that says what is missing.
TEST(WebGl2VerifyErrors, NoBrowserIsADriverFailureThatSaysWhy) {
  const CliRun r = verify(kShaders + "/webgl2/ops.frag --backend webgl2", "CHROMIUM=/nonexistent/chromium");
  EXPECT_EQ(r.exit_code, 3) << r.out;
  EXPECT_NE(r.out.find("no browser"), std::string::npos) << r.out;
}

}  // namespace

// `doublet lower --mode MODE --mode-for NAME=MODE` and `doublet verify --mode`: what reaches the
// output, and the exit codes of bad values (docs/modes.md). Bad flag values are usage errors
// (exit 1, like an unknown --target); a name the shader does not declare, an unknown mode in a
// pragma and native on ES are compiler diagnostics (exit 2).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "test_support.hpp"

namespace doublet::cli_test {
namespace {
namespace fs = std::filesystem;

const char* const kShader = R"(#version 300 es
in dvec3 position;
uniform dvec3 eye;
void main() {
  gl_Position = vec4(vec3(position - eye), 1.0);
}
)";

class ModeFlags : public ::testing::Test {
 protected:
  void SetUp() override { write_file(dir / "m.vert", kShader); }
  ProcessResult lower(std::vector<std::string> extra, const std::string& input = "m.vert") {
    std::vector<std::string> args{"lower", input, "-o", "out.vert"};
    args.insert(args.end(), extra.begin(), extra.end());
    return run_process(DOUBLET_CLI_PATH, args, dir.path());
  }
  static bool has(const std::string& text, const std::string& s) { return text.find(s) != std::string::npos; }
  ScratchDir dir;
};

TEST_F(ModeFlags, Fp32DemotesTheInterfaceAndTheManifestSaysSo) {
  ProcessResult r = lower({"--mode", "fp32", "--manifest", "m.json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string out = read_file(dir / "out.vert");
  EXPECT_TRUE(has(out, "in vec3 position;")) << out;
  EXPECT_FALSE(has(out, "position_hi")) << out;
  const std::string manifest = read_file(dir / "m.json");
  EXPECT_TRUE(has(manifest, R"("mode": "fp32")")) << manifest;
  EXPECT_TRUE(has(manifest, R"("split": false)")) << manifest;
}

TEST_F(ModeFlags, ModeForNamesOneDeclaration) {
  ProcessResult r = lower({"--mode", "fp32", "--mode-for", "eye=df64"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string out = read_file(dir / "out.vert");
  EXPECT_TRUE(has(out, "in vec3 position;")) << out;
  EXPECT_TRUE(has(out, "uniform vec3 eye_hi;")) << out;
}

// -O0 (--no-optimize) turns the whole-shader optimizer off: a square keeps the general product.
TEST_F(ModeFlags, NoOptimizeKeepsTheGeneralRules) {
  write_file(dir / "sq.comp", R"(#version 450
layout(local_size_x = 1) in;
layout(std430, binding = 0) buffer B { double x; double y; };
void main() { y = x * x; }
)");
  const std::vector<std::string> base{"lower", "sq.comp", "--target", "es310", "-o"};
  auto with = [&](std::vector<std::string> args, std::vector<std::string> extra) {
    args.insert(args.end(), extra.begin(), extra.end());
    return args;
  };
  ProcessResult r = run_process(DOUBLET_CLI_PATH, with(base, {"opt.comp"}), dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* flag : {"-O0", "--no-optimize"}) {
    SCOPED_TRACE(flag);
    r = run_process(DOUBLET_CLI_PATH, with(base, {"o0.comp", flag}), dir.path());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::string optimized = read_file(dir / "opt.comp"), plain = read_file(dir / "o0.comp");
    EXPECT_TRUE(has(optimized, "df_double df_sqr(")) << optimized;
    EXPECT_FALSE(has(optimized, "df_double df_mul(")) << optimized;
    EXPECT_TRUE(has(plain, "df_double df_mul(")) << plain;
    EXPECT_FALSE(has(plain, "df_double df_sqr(")) << plain;
  }
}

// Mode exact shares one call site per operation in a run of statements (a loop over the run);
// --inline-exact-calls leaves every call where it is (docs/performance.md).
TEST_F(ModeFlags, InlineExactCallsKeepsEveryCallInPlace) {
  write_file(dir / "chain.comp", R"(#version 450
layout(local_size_x = 1) in;
layout(std430, binding = 0) buffer B { double x; double y; };
void main() { y = x * y * x * y; }
)");
  ProcessResult r = run_process(DOUBLET_CLI_PATH, {"lower", "chain.comp", "--mode", "exact", "--target", "es310", "-o", "shared.comp"},
                                dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_process(DOUBLET_CLI_PATH,
                  {"lower", "chain.comp", "--mode", "exact", "--target", "es310", "--inline-exact-calls", "-o", "inline.comp"},
                  dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string shared = read_file(dir / "shared.comp"), inlined = read_file(dir / "inline.comp");
  EXPECT_TRUE(has(shared, "for (int ex_pc1 = 0; ex_pc1 < 3; ++ex_pc1)")) << shared;  // three products, one site
  EXPECT_FALSE(has(inlined, "ex_pc1")) << inlined;
  EXPECT_TRUE(has(inlined, "ex_mul(ex_mul(ex_mul(")) << inlined;
}

TEST_F(ModeFlags, BadValuesAreUsageErrors) {
  ProcessResult r = lower({"--mode", "double"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_TRUE(has(r.err, "--mode: unknown mode 'double' (expected fp32, rte, df64-fast, df64, df64-int, native, exact or rte-exact)")) << r.err;
  r = lower({"--mode-for", "eye"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_TRUE(has(r.err, "--mode-for: expected NAME=MODE")) << r.err;
  r = lower({"--mode-for", "eye=fast"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_TRUE(has(r.err, "unknown mode 'fast'")) << r.err;
  EXPECT_FALSE(fs::exists(dir / "out.vert"));
}

TEST_F(ModeFlags, UnknownNamesAndNativeOnEsAreDiagnostics) {
  ProcessResult r = lower({"--mode-for", "nothere=fp32"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(has(r.err, "m.vert: error: --mode-for nothere=fp32: the shader declares no global variable or function 'nothere'"))
      << r.err;
  r = lower({"--mode", "native"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(has(r.err, "use --target glsl450")) << r.err;
  r = lower({"--mode", "native", "--target", "glsl450"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(has(read_file(dir / "out.vert"), "in dvec3 position;"));
}

TEST_F(ModeFlags, UnknownPragmaModeIsAFileLineColumnError) {
  std::string text = kShader;
  text.replace(text.find("uniform dvec3 eye;"), 0, "#pragma doublet mode(fp64)\n");
  write_file(dir / "p.vert", text);
  ProcessResult r = lower({}, "p.vert");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(has(r.err, "p.vert:3:22: error: unknown mode 'fp64'")) << r.err;
}

TEST_F(ModeFlags, VerifyRejectsAnUnknownMode) {
  ProcessResult r = run_process(DOUBLET_CLI_PATH, {"verify", "m.vert", "--mode", "df32"}, dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(has(r.err, "unknown mode 'df32'")) << r.err;
}

}  // namespace
}  // namespace doublet::cli_test

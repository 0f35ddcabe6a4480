// Precision modes (docs/modes.md): which declaration a pragma or --mode-for entry reaches,
// what each mode does to storage and arithmetic, and the errors for bad names and modes.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <regex>
#include <string>

#include "doublet/doublet.hpp"

namespace {

using doublet::Mode;

doublet::Options options(Mode mode = Mode::Df64, doublet::Target target = doublet::Target::Es300) {
  doublet::Options o;
  o.stage = doublet::Stage::Fragment;
  o.target = target;
  o.file_name = "modes.frag";
  o.mode = mode;
  return o;
}

std::string messages(const doublet::Result& r) {
  std::string s;
  for (const auto& d : r.diagnostics) s += doublet::format_diagnostic(d) + "\n";
  return s;
}

const doublet::InterfaceVariable* variable(const doublet::Result& r, const std::string& name) {
  for (const auto& v : r.manifest.variables)
    if (v.name == name) return &v;
  return nullptr;
}

bool contains(const std::string& text, const std::string& pattern) {
  return std::regex_search(text, std::regex(pattern));
}

// Two double uniforms, a helper function with a local, and main.
const char* kShader = R"(#version 300 es
precision highp float;
uniform double a;
uniform double b;
out vec4 color;
double helper(double x) {
  double y = x * a;
  return y - b;
}
void main() {
  double p = a * b;
  color = vec4(float(helper(p)), 0.0, 0.0, 1.0);
}
)";

TEST(Modes, Fp32DemotesEveryDoubleAndEmitsNoRuntime) {
  auto r = doublet::lower(kShader, options(Mode::Fp32));
  ASSERT_TRUE(r.ok) << messages(r);
  EXPECT_FALSE(contains(r.output, R"(\bdf_)")) << r.output;
  EXPECT_FALSE(contains(r.output, R"(_hi\b)")) << r.output;
  EXPECT_TRUE(contains(r.output, R"(uniform float a;)")) << r.output;
  EXPECT_TRUE(contains(r.output, R"(float helper\(float x\))")) << r.output;
  const auto* a = variable(r, "a");
  ASSERT_NE(a, nullptr);
  EXPECT_FALSE(a->split);
  EXPECT_EQ(a->type, "double");
  EXPECT_EQ(a->lowered_type, "float");
  EXPECT_EQ(a->lowered_names, std::vector<std::string>{"a"});
  EXPECT_EQ(nlohmann::json::parse(r.manifest.to_json())["mode"], "fp32");
}

TEST(Modes, RteKeepsHiLoStorageAndOnlyTheDifferenceOfTwoDoublesIsFloatFloat) {
  auto r = doublet::lower(kShader, options(Mode::Rte));
  ASSERT_TRUE(r.ok) << messages(r);
  EXPECT_TRUE(variable(r, "a")->split);
  // y - b: both hi/lo, so the exact df_sub, then one rounding to float.
  EXPECT_TRUE(contains(r.output, R"(df_to_float\(df_sub\(y, b\)\))")) << r.output;
  // x * a and a * b are float products; their results are widened into the hi/lo locals.
  EXPECT_FALSE(contains(r.output, R"(df_mul\w*\()")) << r.output;
  EXPECT_TRUE(contains(r.output, R"(df_double y = df_from_float\()")) << r.output;
}

// A double's 64-bit pattern does not exist where doubles are floats: fp32 and rte refuse the bit
// casts at their position (rte read a float's type as a float-float one before: clang's UBSan,
// scripts/check-sanitizers); the float-float modes lower them (golden int64_bit_casts.comp).
TEST(Modes, BitCastsOfDoublesAreRefusedWhereDoublesAreFloats) {
  const std::string src = R"(#version 450
#extension GL_ARB_gpu_shader_int64 : require
uniform double a;
out vec4 color;
void main() {
  uint64_t bits = doubleBitsToUint64(a);
  color = vec4(float(bits & 1ul), 0.0, 0.0, 1.0);
}
)";
  for (Mode mode : {Mode::Fp32, Mode::Rte}) {
    auto r = doublet::lower(src, options(mode, doublet::Target::Glsl450));
    EXPECT_FALSE(r.ok) << doublet::to_string(mode);
    EXPECT_TRUE(contains(messages(r), R"(modes\.frag:6:\d+: error: doubleBitsToUint64 has no meaning when doubles are demoted to float \(--mode )" +
                                          std::string(doublet::to_string(mode)) + R"(\))"))
        << messages(r);
  }
  EXPECT_TRUE(doublet::lower(src, options(Mode::Df64, doublet::Target::Glsl450)).ok);
}

TEST(Modes, Df64FastCallsTheFastRules) {
  auto r = doublet::lower(kShader, options(Mode::Df64Fast));
  ASSERT_TRUE(r.ok) << messages(r);
  EXPECT_TRUE(contains(r.output, R"(df_sub_fast\(y, b\))")) << r.output;
  EXPECT_TRUE(contains(r.output, R"(df_mul_fast\()")) << r.output;
  EXPECT_FALSE(contains(r.output, R"(df_sub\()")) << r.output;
}

TEST(Modes, Df64NamedExplicitlyChangesNothing) {
  auto plain = doublet::lower(kShader, options());
  auto o = options(Mode::Df64);
  o.mode_for = {{"a", Mode::Df64}, {"helper", Mode::Df64}, {"helper.y", Mode::Df64}};
  auto named = doublet::lower(kShader, o);
  ASSERT_TRUE(plain.ok && named.ok) << messages(named);
  EXPECT_EQ(plain.output, named.output);
}

TEST(Modes, PragmaBeforeAGlobalDemotesOnlyIt) {
  std::string src = kShader;
  src.replace(src.find("uniform double a;"), 0, "#pragma doublet mode(fp32)\n");
  auto r = doublet::lower(src, options());
  ASSERT_TRUE(r.ok) << messages(r);
  EXPECT_FALSE(variable(r, "a")->split);
  EXPECT_TRUE(variable(r, "b")->split);
  // df64 arithmetic reads the float 'a' widened.
  EXPECT_TRUE(contains(r.output, R"(uniform float a;)")) << r.output;
  EXPECT_TRUE(contains(r.output, R"(uniform float b_hi;)")) << r.output;
}

TEST(Modes, PragmaBeforeAFunctionSetsItsArithmeticAndItsLocals) {
  std::string src = kShader;
  src.replace(src.find("double helper("), 0, "#pragma doublet mode(fp32)\n");
  auto r = doublet::lower(src, options());
  ASSERT_TRUE(r.ok) << messages(r);
  EXPECT_TRUE(contains(r.output, R"(float helper\(float x\))")) << r.output;
  EXPECT_TRUE(contains(r.output, R"(float y = x \* df_to_float\(a\);)")) << r.output;
  EXPECT_TRUE(contains(r.output, R"(df_double p = df_mul\(a, b\);)")) << r.output;  // main stays df64
}

TEST(Modes, PragmaBeforeALocalSetsItsStorage) {
  std::string src = kShader;
  src.replace(src.find("  double p = a * b;"), 0, "  #pragma doublet mode(fp32)\n");
  auto r = doublet::lower(src, options());
  ASSERT_TRUE(r.ok) << messages(r);
  // df64 product, demoted once into the float local.
  EXPECT_TRUE(contains(r.output, R"(float p = df_to_float\(df_mul\(a, b\)\);)")) << r.output;
}

TEST(Modes, UnknownPragmaModeIsAnErrorAtItsColumn) {
  std::string src = kShader;
  src.replace(src.find("uniform double a;"), 0, "#pragma doublet mode(fast)\n");
  auto r = doublet::lower(src, options());
  ASSERT_FALSE(r.ok);
  ASSERT_FALSE(r.diagnostics.empty());
  EXPECT_EQ(r.diagnostics[0].line, 3);
  EXPECT_EQ(r.diagnostics[0].column, 22);
  EXPECT_TRUE(contains(messages(r), R"(modes\.frag:3:22: error: unknown mode 'fast')")) << messages(r);
}

TEST(Modes, MalformedDoubletPragmaIsAnError) {
  std::string src = kShader;
  src.replace(src.find("uniform double a;"), 0, "#pragma doublet precision(fp32)\n");
  auto r = doublet::lower(src, options());
  ASSERT_FALSE(r.ok);
  EXPECT_TRUE(contains(messages(r), R"(modes\.frag:3:1: error: malformed '#pragma doublet')")) << messages(r);
}

TEST(Modes, OtherPragmasAndCommentedOutOnesAreIgnored) {
  std::string src = kShader;
  src.replace(src.find("uniform double a;"), 0, "#pragma optimize(on)\n/*\n#pragma doublet mode(fp32)\n*/\n");
  auto r = doublet::lower(src, options());
  ASSERT_TRUE(r.ok) << messages(r);
  EXPECT_TRUE(variable(r, "a")->split);
}

TEST(Modes, PragmaWithoutADeclarationIsAWarning) {
  std::string src = kShader;
  src += "#pragma doublet mode(rte)\n";
  auto r = doublet::lower(src, options());
  ASSERT_TRUE(r.ok) << messages(r);
  EXPECT_TRUE(contains(messages(r), R"(modes\.frag:14:1: warning: '#pragma doublet mode\(rte\)' is not followed by a declaration)"))
      << messages(r);
}

TEST(Modes, ModeForReachesGlobalsFunctionsAndLocals) {
  auto o = options();
  o.mode_for = {{"b", Mode::Fp32}, {"helper", Mode::Rte}, {"main.p", Mode::Fp32}};
  auto r = doublet::lower(kShader, o);
  ASSERT_TRUE(r.ok) << messages(r);
  EXPECT_FALSE(variable(r, "b")->split);
  EXPECT_TRUE(variable(r, "a")->split);
  EXPECT_TRUE(contains(r.output, R"(float p = )")) << r.output;
  // helper is rte; b is float now, so y - b is a float subtraction: no df_sub at all.
  EXPECT_FALSE(contains(r.output, R"(df_sub\()")) << r.output;
}

TEST(Modes, LaterModeForEntryWinsAndBeatsThePragma) {
  std::string src = kShader;
  src.replace(src.find("uniform double a;"), 0, "#pragma doublet mode(fp32)\n");
  auto o = options();
  o.mode_for = {{"a", Mode::Fp32}, {"a", Mode::Df64}};
  auto r = doublet::lower(src, o);
  ASSERT_TRUE(r.ok) << messages(r);
  EXPECT_TRUE(variable(r, "a")->split);
}

TEST(Modes, UnknownModeForNamesAreErrors) {
  for (const char* name : {"nothere", "helper.z", "nofunction.y"}) {
    auto o = options();
    o.mode_for = {{name, Mode::Fp32}};
    auto r = doublet::lower(kShader, o);
    EXPECT_FALSE(r.ok) << name;
    EXPECT_TRUE(contains(messages(r), std::string("modes\\.frag: error: --mode-for ") + name)) << messages(r);
  }
}

TEST(Modes, NativeIsWholeShaderOnlyAndDesktopOnly) {
  auto o = options(Mode::Native);
  auto es = doublet::lower(kShader, o);
  EXPECT_FALSE(es.ok);
  EXPECT_TRUE(contains(messages(es), "--target glsl450")) << messages(es);

  o.target = doublet::Target::Glsl450;
  auto desktop = doublet::lower(kShader, o);
  ASSERT_TRUE(desktop.ok) << messages(desktop);
  EXPECT_TRUE(contains(desktop.output, R"(uniform double a;)")) << desktop.output;
  EXPECT_TRUE(contains(desktop.output, R"(double p = a \* b;)")) << desktop.output;
  EXPECT_FALSE(contains(desktop.output, R"(\bdf_)")) << desktop.output;

  o.mode_for = {{"a", Mode::Fp32}};
  EXPECT_FALSE(doublet::lower(kShader, o).ok);

  auto per_name = options();
  per_name.mode_for = {{"a", Mode::Native}};
  auto r = doublet::lower(kShader, per_name);
  EXPECT_FALSE(r.ok);
  EXPECT_TRUE(contains(messages(r), "whole shader only")) << messages(r);

  std::string src = kShader;
  src.replace(src.find("uniform double a;"), 0, "#pragma doublet mode(native)\n");
  r = doublet::lower(src, options());
  EXPECT_FALSE(r.ok);
  EXPECT_TRUE(contains(messages(r), R"(modes\.frag:3:1: error: mode native applies to the whole shader only)"))
      << messages(r);
}

TEST(Modes, OutArgumentOfAnotherPrecisionIsAnErrorNotACrash) {
  const char* src = R"(#version 300 es
precision highp float;
uniform double a;
out vec4 color;
void twice(inout double x) { x = x * 2.0lf; }
void main() {
  double v = a;
  twice(v);
  color = vec4(float(v));
}
)";
  auto o = options();
  o.mode_for = {{"main.v", Mode::Fp32}};
  auto r = doublet::lower(src, o);
  EXPECT_FALSE(r.ok);
  EXPECT_TRUE(contains(messages(r), R"(modes\.frag:8:\d+: error: argument 1 of 'twice' is an out/inout)")) << messages(r);
}

TEST(Modes, Fp32ConstantOutsideFloatRangeIsAnError) {
  const char* src = R"(#version 300 es
precision highp float;
out vec4 color;
void main() {
  double big = 1e300lf;
  color = vec4(float(big));
}
)";
  auto r = doublet::lower(src, options(Mode::Fp32));
  EXPECT_FALSE(r.ok);
  EXPECT_TRUE(contains(messages(r), R"(modes\.frag:5:\d+: error: the double constant 1.*e\+300 is outside float range)"))
      << messages(r);
}

TEST(Modes, Fp32OverloadThatCollidesWithAFloatOneIsAnError) {
  const char* src = R"(#version 300 es
precision highp float;
uniform double a;
out vec4 color;
float f(float x) { return x; }
double f(double x) { return x * 2.0lf; }
void main() { color = vec4(float(f(a)) + f(1.0)); }
)";
  EXPECT_TRUE(doublet::lower(src, options()).ok);
  auto r = doublet::lower(src, options(Mode::Fp32));
  EXPECT_FALSE(r.ok);
  EXPECT_TRUE(contains(messages(r), R"(modes\.frag:6:\d+: error: with its mode, this overload of 'f' has the same )"
                                    R"(parameter types as the one on line 5)"))
      << messages(r);
}

TEST(Modes, ParseAndSpellEveryMode) {
  for (Mode m : {Mode::Fp32, Mode::Rte, Mode::Df64Fast, Mode::Df64, Mode::Native, Mode::Df64Int})
    EXPECT_EQ(doublet::parse_mode(doublet::to_string(m)), m);
  EXPECT_EQ(doublet::to_string(Mode::Df64Int), "df64-int");
  EXPECT_EQ(doublet::parse_mode("df64fast"), std::nullopt);
}

}  // namespace

// --target webgl2 (issue 14): what WebGL 2.0 forbids on top of GLSL ES 3.00 is rewritten
// (struct ternaries, FLT_MAX spelling) or refused with a positioned diagnostic (reserved names,
// `precise`, compute, a ternary on arrays where no statement can hold the selection); the printed
// text is checked by emit::webgl_violations, tested here on text that breaks each rule.
#include <gtest/gtest.h>

#include <cfloat>
#include <cstdlib>
#include <string>

#include "doublet/doublet.hpp"
#include "emit/webgl_rules.hpp"

namespace {

doublet::Result lower_webgl2(const std::string& source, doublet::Stage stage = doublet::Stage::Fragment,
                             doublet::GuardKind guard = doublet::GuardKind::Auto) {
  doublet::Options o;
  o.stage = stage;
  o.target = doublet::Target::Webgl2;
  o.guard = guard;
  o.file_name = "user.frag";
  return doublet::lower(source, o);
}

std::string diagnostics(const doublet::Result& r) {
  std::string s;
  for (const auto& d : r.diagnostics) s += doublet::format_diagnostic(d) + "\n";
  return s;
}

TEST(Webgl2Target, SpelledWebgl2AndPrintedAsEs300) {
  ASSERT_EQ(doublet::parse_target("webgl2"), doublet::Target::Webgl2);
  EXPECT_EQ(doublet::to_string(doublet::Target::Webgl2), "webgl2");
  EXPECT_TRUE(doublet::target_is_es(doublet::Target::Webgl2));
  EXPECT_EQ(doublet::target_version(doublet::Target::Webgl2), 300);
  auto r = lower_webgl2("#version 450\nuniform double a;\nout vec4 c;\nvoid main() { c = vec4(float(a * a)); }\n");
  ASSERT_TRUE(r.ok) << diagnostics(r);
  EXPECT_EQ(r.output.rfind("#version 300 es\n", 0), 0u);
  EXPECT_EQ(r.manifest.target, "webgl2");
  EXPECT_EQ(r.manifest.guard.kind, "uniform");  // no `precise` in WebGL: the uniform guard
  EXPECT_EQ(r.output.find("precise"), std::string::npos);
}

TEST(Webgl2Target, StructTernariesAreRewrittenAndArrayOnesOutsideAStatementRefused) {
  auto r = lower_webgl2("#version 450\nuniform double a;\nuniform int n;\nout vec4 c;\n"
                        "void main() { double x = n > 0 ? a : -a; c = vec4(float(x)); }\n");
  ASSERT_TRUE(r.ok) << diagnostics(r);
  EXPECT_NE(r.output.find("df_select1 = a, true"), std::string::npos) << r.output;
  auto arrays = lower_webgl2("#version 450\nuniform double a;\nuniform int n;\nout vec4 c;\n"
                             "void main() {\n  double x = (n > 0 ? double[2](a, a) : double[2](-a, a))[1];\n"
                             "  c = vec4(float(x));\n}\n");
  EXPECT_FALSE(arrays.ok);
  EXPECT_NE(diagnostics(arrays).find("user.frag:6:"), std::string::npos) << diagnostics(arrays);
  EXPECT_NE(diagnostics(arrays).find("error: webgl2: WebGL allows neither the ternary operator nor the sequence "
                                     "operator on arrays"),
            std::string::npos)
      << diagnostics(arrays);
}

TEST(Webgl2Target, WebglRulesAreDiagnosedAtTheUserCode) {
  auto reserved = lower_webgl2("#version 450\nuniform double a;\nout vec4 c;\n"
                               "void main() {\n  double webgl_x = a;\n  c = vec4(float(webgl_x));\n}\n");
  EXPECT_FALSE(reserved.ok);
  EXPECT_NE(diagnostics(reserved).find("user.frag:5:"), std::string::npos) << diagnostics(reserved);
  EXPECT_NE(diagnostics(reserved).find("WebGL reserves identifiers beginning with webgl_"), std::string::npos);

  // glslang itself refuses names over 1024 characters; a 1023-character double uniform is split
  // into NAME_hi / NAME_lo, 1026 characters, which WebGL 2.0 would refuse.
  const std::string long_name(1023, 'v');
  auto too_long = lower_webgl2("#version 450\nuniform double " + long_name + ";\nout vec4 c;\nvoid main() {\n"
                               "  c = vec4(float(" + long_name + "));\n}\n");
  EXPECT_FALSE(too_long.ok);
  EXPECT_NE(diagnostics(too_long).find("user.frag:2:"), std::string::npos) << diagnostics(too_long);
  EXPECT_NE(diagnostics(too_long).find("has 1026 characters: WebGL 2.0 allows identifiers of at most 1024"),
            std::string::npos)
      << diagnostics(too_long);

  auto precise = lower_webgl2("#version 450\nuniform double a;\nout vec4 c;\nvoid main() { c = vec4(float(a)); }\n",
                              doublet::Stage::Fragment, doublet::GuardKind::Precise);
  EXPECT_FALSE(precise.ok);
  EXPECT_NE(diagnostics(precise).find("target webgl2 has no 'precise' qualifier"), std::string::npos);

  auto compute = lower_webgl2("#version 450\nlayout(local_size_x = 1) in;\nvoid main() {}\n", doublet::Stage::Compute);
  EXPECT_FALSE(compute.ok);
  EXPECT_NE(diagnostics(compute).find("target webgl2 has no compute shaders"), std::string::npos);
}

TEST(Webgl2Target, PrintedTextChecksFindEachBrokenRule) {
  EXPECT_TRUE(doublet::emit::webgl_violations("#version 300 es\nprecision highp float;\n// precise webgl_x 3.5e38\n"
                                              "float f(float x) { return x <= 3.4028234663852886e38 ? x : 0.0; }\n")
                  .empty());
  const auto broken = doublet::emit::webgl_violations(
      "#version 300 es\n#extension GL_EXT_gpu_shader5 : require\nprecise float a;\nfloat webgl_b;\n"
      "float c = 3.40282347e38;\nfloat " + std::string(1025, 'd') + ";\n");
  ASSERT_EQ(broken.size(), 5u);
  EXPECT_EQ(broken[0].line, 2);  // #extension
  EXPECT_EQ(broken[1].line, 3);  // precise
  EXPECT_EQ(broken[2].line, 4);  // webgl_ prefix
  EXPECT_EQ(broken[3].line, 5);  // Float overflow
  EXPECT_EQ(broken[4].line, 6);  // identifier length
}

TEST(Webgl2Target, FloatMaxSpellingDenotesTheSameFloatAndNoLongerExceedsIt) {
  const std::string spelled = doublet::emit::spell_float_max_for_webgl("x <= 3.40282347e38");
  ASSERT_EQ(spelled, "x <= 3.4028234663852886e38");
  EXPECT_EQ(std::strtof("3.40282347e38", nullptr), FLT_MAX);
  EXPECT_EQ(std::strtof("3.4028234663852886e38", nullptr), FLT_MAX);  // bit-identical float
  EXPECT_GT(std::strtod("3.40282347e38", nullptr), static_cast<double>(FLT_MAX));   // why ANGLE warns
  EXPECT_EQ(std::strtod("3.4028234663852886e38", nullptr), static_cast<double>(FLT_MAX));  // exact
}

}  // namespace

// The lints (src/lower/lints.cpp, docs/robustness.md "Lints"): each fires at the right
// line:col with its message, stays quiet on the look-alikes that are fine, and can be
// silenced or promoted through Options.
#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "doublet/doublet.hpp"

namespace {

using doublet::Severity;

doublet::Options options(doublet::Stage stage = doublet::Stage::Compute) {
  doublet::Options o;
  o.stage = stage;
  o.target = doublet::Target::Es310;
  o.file_name = "l.comp";
  return o;
}

std::string all(const doublet::Result& r) {
  std::string s;
  for (const auto& d : r.diagnostics) s += doublet::format_diagnostic(d) + "\n";
  return s;
}

// The diagnostics whose message ends in [-WNAME].
std::vector<doublet::Diagnostic> lint(const doublet::Result& r, const std::string& name) {
  std::vector<doublet::Diagnostic> out;
  const std::string tag = " [-W" + name + "]";
  for (const auto& d : r.diagnostics)
    if (d.message.size() > tag.size() && d.message.compare(d.message.size() - tag.size(), tag.size(), tag) == 0)
      out.push_back(d);
  return out;
}

// A compute shader whose main() body is `body` (lines start at 5).
std::string compute(const std::string& body, const std::string& globals = "") {
  return "#version 310 es\n"
         "layout(local_size_x = 1) in;\n"
         "layout(std430, binding = 0) buffer B { double o[4]; double din; float fin; vec3 vin; int iin; };\n" +
         (globals.empty() ? std::string("// no globals\n") : globals) + "void main() {\n" + body + "}\n";
}

// ---- float-literal ------------------------------------------------------------
// 0.1f is 0x3DCCCCCD = 13421773 * 2^-27 = 0.100000001490116119384765625 exactly;
// 0.2f = 13421773 * 2^-26 = 0.20000000298023223876953125; 0.7f = 11744051 * 2^-24 =
// 0.699999988079071044921875. The messages print 15 significant digits of those.

TEST(FloatLiteralLint, FiresAtTheLiteralWithTheFix) {
  auto r = doublet::lower(compute("  double x = 0.1;\n  o[0] = x * din;\n"), options());
  ASSERT_TRUE(r.ok) << all(r);
  auto found = lint(r, "float-literal");
  ASSERT_EQ(found.size(), 1u) << all(r);
  EXPECT_EQ(doublet::format_diagnostic(found[0]),
            "l.comp:6:14: warning: float literal 0.1 becomes 0.100000001490116 as a double; write 0.1lf "
            "(doublet and glslang read it as 0.1lf, GL drivers as the float) [-Wfloat-literal]");
}

TEST(FloatLiteralLint, EveryWayALiteralMeetsADouble) {
  const std::string body =
      "  dvec2 v = dvec2(0.1, 0.25);\n"       // 8: constructor, folded; 0.25 is a float
      "  o[0] = din * 0.2 + v.x;\n"           // 9: operand
      "  o[1] = f(0.7);\n"                    // 10: function argument
      "  o[2] = -0.1 * din + double(0.2f);\n"  // 11: negated; f-suffixed in a conversion
      "  o[3] = din * K + din * M;\n";        // 12: a const and a macro: reported at their definitions
  const std::string globals =
      "double f(double a) { return a * a; }\n"  // 4
      "const double K = 0.7;\n"                 // 5
      "#define M 0.1\n";                        // 6; main() is line 7
  auto r = doublet::lower(compute(body, globals), options());
  ASSERT_TRUE(r.ok) << all(r);
  std::vector<std::string> got;
  for (const auto& d : lint(r, "float-literal"))
    got.push_back(std::to_string(d.line) + ":" + std::to_string(d.column) + " " +
                  d.message.substr(0, d.message.find(';')));
  std::vector<std::string> want{
      "5:18 float literal 0.7 becomes 0.699999988079071 as a double",
      "6:11 float literal 0.1 becomes 0.100000001490116 as a double",
      "8:19 float literal 0.1 becomes 0.100000001490116 as a double",
      "9:16 float literal 0.2 becomes 0.200000002980232 as a double",
      "10:12 float literal 0.7 becomes 0.699999988079071 as a double",
      "11:11 float literal 0.1 becomes 0.100000001490116 as a double",
      "11:30 float literal 0.2f becomes 0.200000002980232 as a double",
  };
  EXPECT_EQ(got, want) << all(r);
  for (const auto& d : lint(r, "float-literal")) EXPECT_EQ(d.severity, Severity::Warning);
}

TEST(FloatLiteralLint, QuietWhenTheLiteralIsAFloatOrNotADouble) {
  const std::string body =
      "  double a = 0.5 + 2.0 * din + 1e3;\n"  // exact floats
      "  dvec3 b = dvec3(0.125, -4.0, 1e-3lf);\n"
      "  o[0] = a + b.x + 0.1lf + 0.1LF;\n"    // double literals
      "  float c = 0.1 * fin;\n"               // float context
      "  o[1] = double(c) + double(3);\n"      // an int literal is exact
      "  o[2] = din * Q;\n";                   // an unused double constant is never reported
  auto r = doublet::lower(compute(body, "const double UNUSED = 0.3;\nconst double Q = 0.25;\n"), options());
  ASSERT_TRUE(r.ok) << all(r);
  EXPECT_TRUE(lint(r, "float-literal").empty()) << all(r);
}

// Float arithmetic on exact float literals, folded by glslang in double: GLSL computes 1.0 / 3.0
// in float (0.333333343267441 widened), glslang and doublet keep the double 1/3.
TEST(FloatLiteralLint, FloatExpressionFoldedInDouble) {
  const std::string body =
      "  double t = 1.0 / 3.0;\n"                                  // 6
      "  o[0] = t * din + din * double(2.0 / 3.0) + din * THIRD;\n"  // 7
      "  o[1] = din * (1.0 / 4.0) + din * (1.0lf / 3.0) + din * (2.0 * 3.0);\n"  // 8: quiet
      "  o[2] = din * -(1.0 / 3.0);\n";                                          // 9: the text's value
  auto r = doublet::lower(compute(body, "const double THIRD = (1.0 + 0.0) / 3.0;\n"), options());
  ASSERT_TRUE(r.ok) << all(r);
  std::vector<std::string> got;
  for (const auto& d : lint(r, "float-literal")) got.push_back(doublet::format_diagnostic(d));
  const std::string tail =
      " (doublet and glslang keep that), but under the GLSL rules it is float arithmetic, which GL drivers widen; "
      "write its literals with lf [-Wfloat-literal]";
  std::vector<std::string> want{
      "l.comp:4:22: warning: float expression '(1.0 + 0.0) / 3.0' is folded in double to 0.333333333333333" + tail,
      "l.comp:6:14: warning: float expression '1.0 / 3.0' is folded in double to 0.333333333333333" + tail,
      "l.comp:7:33: warning: float expression '2.0 / 3.0' is folded in double to 0.666666666666667" + tail,
      "l.comp:9:18: warning: float expression '1.0 / 3.0' is folded in double to 0.333333333333333" + tail,
  };
  EXPECT_EQ(got, want) << all(r);
}

// A constant from an #include'd file carries that file's line and column; the main file may
// have a float literal at the same place, which must not be blamed.
TEST(FloatLiteralLint, IncludedConstantsDoNotBlameTheMainFile) {
  struct OneFile : doublet::Includer {
    std::optional<doublet::IncludeResult> include(std::string_view, std::string_view) override {
      // 0.7 at line 4, column 38 of inc.glsl
      return doublet::IncludeResult{"inc.glsl", "// 1\n// 2\n// 3\ndouble scaled(double d) { return d * 0.7; }\n"};
    }
  } includer;
  doublet::Options o = options();
  o.includer = &includer;
  auto r = doublet::lower("#version 310 es\n"
                          "#include \"inc.glsl\"\n"
                          "layout(local_size_x = 1) in;\n"
                          "float padding_to_reach_col38 = 1.0 + 0.1;\n"  // 0.1 at column 38 (float context)
                          "layout(std430, binding = 0) buffer B { double o; float fo; };\n"
                          "void main() { o = scaled(o); fo = padding_to_reach_col38; }\n",
                          o);
  ASSERT_TRUE(r.ok) << all(r);
  EXPECT_TRUE(lint(r, "float-literal").empty()) << all(r);
}

// The lowering keeps glslang's reading (docs/robustness.md): `0.1` that meets a double is
// the double nearest 0.1, the same code as `0.1lf`, not 0.1f widened.
TEST(FloatLiteralLint, TheLoweringReadsTheLiteralAsADoubleLiteral) {
  doublet::Options o = options();
  o.disabled_lints = {"all"};
  auto unsuffixed = doublet::lower(compute("  o[0] = din * 0.1;\n"), o);
  auto suffixed = doublet::lower(compute("  o[0] = din * 0.1lf;\n"), o);
  ASSERT_TRUE(unsuffixed.ok && suffixed.ok) << all(unsuffixed) << all(suffixed);
  EXPECT_EQ(unsuffixed.output, suffixed.output);
  EXPECT_TRUE(unsuffixed.diagnostics.empty()) << all(unsuffixed);
}

// ---- wasted-double --------------------------------------------------------------
TEST(WastedDoubleLint, ConversionStraightBack) {
  auto r = doublet::lower(compute("  float a = float(double(fin));\n"
                                  "  vec3 b = vec3(dvec3(vin));\n"
                                  "  o[0] = double(a + b.x);\n"),
                          options());
  ASSERT_TRUE(r.ok) << all(r);
  auto found = lint(r, "wasted-double");
  ASSERT_EQ(found.size(), 2u) << all(r);
  EXPECT_EQ(doublet::format_diagnostic(found[0]),
            "l.comp:6:13: warning: float(double(...)) converts to double and straight back with no double "
            "operation between: the result is the same without the double conversion, which only costs "
            "float-float work; drop it [-Wwasted-double]");
  EXPECT_EQ(found[1].line, 7);
  EXPECT_EQ(found[1].column, 12);
  EXPECT_NE(found[1].message.find("vec3(dvec3(...))"), std::string::npos) << found[1].message;
}

TEST(WastedDoubleLint, VariableThatOnlyHoldsAWidenedFloat) {
  auto r = doublet::lower(compute("  double w = double(fin);\n"
                                  "  if (iin > 0) w = double(fin * 2.0);\n"
                                  "  float back = float(w);\n"
                                  "  o[0] = double(back);\n"),
                          options());
  ASSERT_TRUE(r.ok) << all(r);
  auto found = lint(r, "wasted-double");
  ASSERT_EQ(found.size(), 1u) << all(r);
  EXPECT_EQ(doublet::format_diagnostic(found[0]),
            "l.comp:6:10: warning: 'w' only ever holds a widened float and is only read back as float (line 8): "
            "no double operation uses it, so its float-float storage and conversions are wasted work; declare it "
            "float [-Wwasted-double]");
}

TEST(WastedDoubleLint, QuietWhenADoubleOperationHappens) {
  const std::string body =
      "  float a = float(double(fin) * din);\n"  // a double multiply between
      "  double u = double(fin);\n"
      "  o[0] = u + din;\n"                      // u takes part in double arithmetic
      "  double k = din;\n"
      "  float c = float(k);\n"                  // k holds a real double
      "  dvec2 s = dvec2(vin.xy);\n"
      "  float e = float(s.x);\n"                // read through a swizzle: not followed
      "  o[1] = double(a + c + e);\n"
      "  float g = float(din);\n"                // demoting a double from memory is the point
      "  o[2] = double(g);\n";
  auto r = doublet::lower(compute(body), options());
  ASSERT_TRUE(r.ok) << all(r);
  EXPECT_TRUE(lint(r, "wasted-double").empty()) << all(r);
}

// ---- smooth-double-varying --------------------------------------------------------
const char* const kVertex =
    "#version 300 es\n"
    "in vec3 p;\n"
    "out dvec3 v_pos;\n"
    "flat out double v_flat;\n"
    "out vec3 v_float;\n"
    "void main() { v_pos = dvec3(p) * 2.0lf; v_flat = 1.0lf; v_float = p; gl_Position = vec4(p, 1.0); }\n";

TEST(SmoothDoubleVaryingLint, DoubleVertexOutputWithoutFlat) {
  doublet::Options o = options(doublet::Stage::Vertex);
  o.target = doublet::Target::Es300;
  auto r = doublet::lower(kVertex, o);
  ASSERT_TRUE(r.ok) << all(r);
  auto found = lint(r, "smooth-double-varying");
  ASSERT_EQ(found.size(), 1u) << all(r);
  EXPECT_EQ(found[0].line, 3);
  EXPECT_EQ(found[0].column, 11);
  EXPECT_NE(found[0].message.find("'v_pos' is a double vertex output without 'flat'"), std::string::npos);
  EXPECT_NE(found[0].message.find("declare it flat, or pass the value as a uniform"), std::string::npos);
}

// The flat a shader asks for cannot be printed on ES 1.00: say so instead of dropping it silently.
TEST(SmoothDoubleVaryingLint, FlatIsLostOnEs100) {
  doublet::Options o = options(doublet::Stage::Vertex);
  o.target = doublet::Target::Es100;
  auto r = doublet::lower(kVertex, o);
  ASSERT_TRUE(r.ok) << all(r);
  auto found = lint(r, "smooth-double-varying");
  ASSERT_EQ(found.size(), 2u) << all(r);
  EXPECT_EQ(found[1].line, 4);
  EXPECT_NE(found[1].message.find("'v_flat' is a flat double vertex output, but ES 1.00 has no 'flat'"),
            std::string::npos)
      << found[1].message;
}

TEST(SmoothDoubleVaryingLint, Es100HasNoFlatSoTheAdviceIsAUniform) {
  doublet::Options o = options(doublet::Stage::Vertex);
  o.target = doublet::Target::Es100;
  auto r = doublet::lower("#version 100\nattribute vec3 p;\nvarying dvec3 v_pos;\n"
                          "void main() { v_pos = dvec3(p) * 2.0lf; gl_Position = vec4(p, 1.0); }\n", o);
  ASSERT_TRUE(r.ok) << all(r);
  auto found = lint(r, "smooth-double-varying");
  ASSERT_EQ(found.size(), 1u) << all(r);
  EXPECT_EQ(found[0].line, 3);
  EXPECT_EQ(found[0].column, 15);
  EXPECT_NE(found[0].message.find("ES 1.00 has no 'flat', so pass the value as a uniform"), std::string::npos)
      << found[0].message;
}

// A smooth double fragment input never reaches the lint: GLSL forbids it and glslang says so.
TEST(SmoothDoubleVaryingLint, SmoothDoubleFragmentInputIsAnError) {
  doublet::Options o = options(doublet::Stage::Fragment);
  o.target = doublet::Target::Es300;
  auto smooth = doublet::lower("#version 300 es\nprecision highp float;\nin dvec3 v;\nout vec4 c;\n"
                               "void main() { c = vec4(vec3(v), 1.0); }\n", o);
  EXPECT_FALSE(smooth.ok);
  ASSERT_FALSE(smooth.diagnostics.empty());
  EXPECT_EQ(smooth.diagnostics[0].line, 3);
  EXPECT_NE(smooth.diagnostics[0].message.find("flat"), std::string::npos) << all(smooth);
  auto flat = doublet::lower("#version 300 es\nprecision highp float;\nflat in dvec3 v;\nout vec4 c;\n"
                             "void main() { c = vec4(vec3(v), 1.0); }\n", o);
  EXPECT_TRUE(flat.ok) << all(flat);
  EXPECT_TRUE(flat.diagnostics.empty()) << all(flat);
}

// ---- silencing and promotion --------------------------------------------------------
const std::string kEveryLint = compute("  double x = 0.1 * din;\n  float a = float(double(fin));\n  o[0] = x + double(a);\n");

TEST(LintOptions, EachLintCanBeSilencedAlone) {
  auto loud = doublet::lower(kEveryLint, options());
  ASSERT_EQ(lint(loud, "float-literal").size(), 1u) << all(loud);
  ASSERT_EQ(lint(loud, "wasted-double").size(), 1u) << all(loud);
  for (std::string_view view : doublet::lint_names()) {
    std::string name(view);
    doublet::Options o = options();
    o.disabled_lints = {name};
    auto r = doublet::lower(kEveryLint, o);
    ASSERT_TRUE(r.ok) << all(r);
    EXPECT_TRUE(lint(r, name).empty()) << name << "\n" << all(r);
    EXPECT_EQ(r.output, loud.output) << "silencing a lint changes no code";
  }
  doublet::Options o = options();
  o.disabled_lints = {"float-literal"};
  EXPECT_EQ(lint(doublet::lower(kEveryLint, o), "wasted-double").size(), 1u) << "the others still run";
  o.disabled_lints = {"all"};
  EXPECT_TRUE(doublet::lower(kEveryLint, o).diagnostics.empty());
}

TEST(LintOptions, LintErrorsFailTheLowering) {
  doublet::Options o = options();
  o.lint_errors = true;
  auto r = doublet::lower(kEveryLint, o);
  EXPECT_FALSE(r.ok);
  EXPECT_TRUE(r.output.empty());
  ASSERT_EQ(lint(r, "float-literal").size(), 1u) << all(r);
  EXPECT_EQ(lint(r, "float-literal")[0].severity, Severity::Error);
  o.disabled_lints = {"float-literal", "wasted-double"};
  EXPECT_TRUE(doublet::lower(kEveryLint, o).ok) << "silenced lints are not errors either";
}

TEST(LintOptions, UnknownLintNameIsAnError) {
  doublet::Options o = options();
  o.disabled_lints = {"float-literals"};
  auto r = doublet::lower(kEveryLint, o);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(all(r).find("error: unknown lint 'float-literals' (known: float-literal, wasted-double, "
                        "smooth-double-varying, all)"),
            std::string::npos)
      << all(r);
}

TEST(LintOptions, NamesAreListed) {
  std::vector<std::string> names;
  for (std::string_view n : doublet::lint_names()) names.emplace_back(n);
  EXPECT_EQ(names, (std::vector<std::string>{"float-literal", "wasted-double", "smooth-double-varying"}));
}

}  // namespace

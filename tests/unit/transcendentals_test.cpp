// The transcendental extension in the front end and the lowering (frontend/transcendentals.hpp):
// calls on doubles are accepted and lowered to rules/transcendental.glsl, shaders without them
// parse exactly as before, and misuse gets a file:line:col diagnostic. The accuracy is checked on
// the drivers in tests/numeric/transcendental_test.cpp.
#include <gtest/gtest.h>

#include <string>

#include "doublet/doublet.hpp"

namespace {

doublet::Result lower(const std::string& body, doublet::Target target = doublet::Target::Es310) {
  doublet::Options o;
  o.stage = doublet::Stage::Compute;
  o.target = target;
  o.file_name = "t.comp";
  return doublet::lower("#version 450\nlayout(local_size_x = 1) in;\n"
                        "layout(std430, binding = 0) buffer B { double d[]; };\n" + body,
                        o);
}

std::string messages(const doublet::Result& r) {
  std::string s;
  for (const auto& d : r.diagnostics) s += doublet::format_diagnostic(d) + "\n";
  return s;
}

TEST(Transcendentals, EveryFunctionOnEveryWidthLowersToItsRule) {
  const char* names[] = {"exp", "exp2", "log", "log2", "sin", "cos", "tan", "asin", "acos", "atan", "sinh", "cosh", "tanh"};
  for (const char* type : {"double", "dvec2", "dvec3", "dvec4"}) {
    for (const char* n : names) {
      const std::string t = type;
      auto r = lower("void main() { " + t + " x = " + t + "(d[0]); " + t + " y = " + n + "(x); d[1] = y" +
                     (t == "double" ? "" : ".x") + "; }\n");
      ASSERT_TRUE(r.ok) << n << " " << type << "\n" << messages(r);
      EXPECT_NE(r.output.find(std::string("df_") + n + "("), std::string::npos) << n << " " << type;
    }
    const std::string t = type;
    auto r = lower("void main() { " + t + " x = " + t + "(d[0]); " + t + " y = pow(x, x) + atan(x, x); d[1] = y" +
                   (t == "double" ? "" : ".x") + "; }\n");
    ASSERT_TRUE(r.ok) << type << "\n" << messages(r);
    EXPECT_NE(r.output.find("df_pow("), std::string::npos) << type;
    EXPECT_NE(r.output.find("df_atan2("), std::string::npos) << type;
  }
}

TEST(Transcendentals, FloatCallsKeepTheirMeaning) {
  // No double call: the shader parses without the prototypes, so exp(1) stays the float built-in.
  auto r = lower("void main() { float f = exp(1) + sin(float(d[0])); d[1] = double(f); }\n");
  ASSERT_TRUE(r.ok) << messages(r);
  EXPECT_EQ(r.output.find("df_exp"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("df_sin"), std::string::npos) << r.output;
  // With a double call beside it, a float argument still picks the float built-in.
  r = lower("void main() { float f = sin(float(d[0])); d[1] = exp(d[0]) + double(f); }\n");
  ASSERT_TRUE(r.ok) << messages(r);
  EXPECT_NE(r.output.find("df_exp("), std::string::npos);
  EXPECT_EQ(r.output.find("df_sin("), std::string::npos) << r.output;
}

// (Desktop target: GLSL ES forbids user functions named like built-ins, a limit of doublet's
// printer for every such name, transcendental or not.)
// A shader whose only errors are elsewhere is not re-parsed: its diagnostics are the same as
// without the extension (no "double" errors from exp(1) resolving to a prototype).
TEST(Transcendentals, OtherErrorsAreReportedAsBefore) {
  auto r = lower("void main() { float f = exp(1); d[1] = double(f) + undeclared; }\n");
  ASSERT_FALSE(r.ok);
  EXPECT_NE(messages(r).find("t.comp:4:52: error: undeclared identifier 'undeclared'"), std::string::npos)
      << messages(r);
  EXPECT_EQ(messages(r).find("double"), std::string::npos) << messages(r);
}

TEST(Transcendentals, UserDefinitionsWin) {
  auto r = lower("double exp(double x) { return x + 1.0lf; }\nvoid main() { d[1] = exp(d[0]); }\n",
                 doublet::Target::Glsl450);
  ASSERT_TRUE(r.ok) << messages(r);
  EXPECT_EQ(r.output.find("df_exp("), std::string::npos) << r.output;
}

TEST(Transcendentals, MisuseIsDiagnosedWithAPosition) {
  auto r = lower("void main() {\n  d[1] = exp(d[0], d[0]);\n}\n");
  ASSERT_FALSE(r.ok);
  EXPECT_NE(messages(r).find("t.comp:5:10: error: no matching overloaded function found 'exp'"), std::string::npos)
      << messages(r);
  // ES 1.00 has no intBitsToFloat for the 2^k scaling: named with the target.
  doublet::Options o;
  o.stage = doublet::Stage::Vertex;
  o.target = doublet::Target::Es100;
  o.file_name = "v.vert";
  auto v = doublet::lower("#version 450\nin double a;\nvoid main() { gl_Position = vec4(float(exp(a))); }\n", o);
  ASSERT_FALSE(v.ok);
  EXPECT_NE(messages(v).find("v.vert:3:45: error: df_exp2i is not available on ES 1.00 (it needs ES 3.00 or later), "
                            "needed by df_exp"),
            std::string::npos)
      << messages(v);
  EXPECT_EQ(messages(v).find("internal error"), std::string::npos);
  // atan needs no ES 3.00 feature: it lowers for ES 1.00.
  v = doublet::lower("#version 450\nin double a;\nvoid main() { gl_Position = vec4(float(atan(a) + asin(a))); }\n", o);
  EXPECT_TRUE(v.ok) << messages(v);
}

}  // namespace

// Issue 13: generated names never contain "__", and the lowering forms that were refused or
// crashed (double loop index, compound assignment through computed indices, swizzle of a swizzle
// written) lower, or are refused with a position and advice where they cannot be.
#include <gtest/gtest.h>

#include <regex>
#include <sstream>

#include "doublet/doublet.hpp"

namespace {

doublet::Options options(doublet::Stage stage, doublet::Target target) {
  doublet::Options o;
  o.stage = stage;
  o.target = target;
  o.file_name = "forms.glsl";
  return o;
}

std::string messages(const doublet::Result& r) {
  std::string s;
  for (const auto& d : r.diagnostics) s += doublet::format_diagnostic(d) + "\n";
  return s;
}

// Identifiers with "__" in the code (comments dropped).
std::string reserved_identifiers(const std::string& glsl) {
  std::istringstream in(glsl);
  std::string line, found;
  static const std::regex identifier(R"([A-Za-z_][A-Za-z_0-9]*)");
  while (std::getline(in, line)) {
    line = line.substr(0, line.find("//"));
    for (std::sregex_iterator it(line.begin(), line.end(), identifier), end; it != end; ++it)
      if (it->str().find("__") != std::string::npos) found += it->str() + " ";
  }
  return found;
}

constexpr doublet::Target kAllTargets[] = {doublet::Target::Es100, doublet::Target::Es300, doublet::Target::Es310,
                                           doublet::Target::Es320, doublet::Target::Glsl330, doublet::Target::Glsl450,
                                           doublet::Target::Webgl2};

TEST(GeneratedNames, NamesEndingInUnderscoreNeverMakeDoubleUnderscores) {
  const char* src = R"(#version 100
precision highp float;
uniform double scale_;
uniform dmat2 basis_;
attribute vec2 position_;
varying float shade_;
void main() {
  double s_ = scale_ * double(position_.x);
  { double s_ = basis_[1][0] * 3.0lf; shade_ = float(s_); }
  shade_ += float(s_);
  gl_Position = vec4(position_, 0.0, 1.0);
}
)";
  for (doublet::Target target : kAllTargets) {
    auto r = doublet::lower(src, options(doublet::Stage::Vertex, target));
    ASSERT_TRUE(r.ok) << doublet::to_string(target) << "\n" << messages(r);
    EXPECT_EQ(reserved_identifiers(r.output), "") << doublet::to_string(target);
    EXPECT_NE(r.output.find("uniform float scale_hi;"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("s_1"), std::string::npos) << r.output;  // the inner s_, renamed
    ASSERT_EQ(r.manifest.variables.front().name, "scale_");
    EXPECT_EQ(r.manifest.variables.front().lowered_names, (std::vector<std::string>{"scale_hi", "scale_lo"}));
  }
}

TEST(GeneratedNames, SuffixWithDoubleUnderscoreIsDiagnosedWithPosition) {
  auto o = options(doublet::Stage::Fragment, doublet::Target::Es300);
  o.hi_suffix = "__h";
  auto r = doublet::lower("#version 300 es\nprecision highp float;\nuniform double g;\nout vec4 c;\n"
                          "void main() { c = vec4(float(g)); }\n",
                          o);
  EXPECT_FALSE(r.ok);
  EXPECT_TRUE(r.output.empty());
  ASSERT_FALSE(r.diagnostics.empty());
  EXPECT_GT(r.diagnostics[0].line, 0);
  EXPECT_NE(messages(r).find("'g__h'"), std::string::npos) << messages(r);
  EXPECT_NE(messages(r).find("--hi-suffix"), std::string::npos) << messages(r);
}

TEST(GeneratedNames, UserNameWithDoubleUnderscoreIsDiagnosedOnce) {
  auto r = doublet::lower("#version 300 es\nprecision highp float;\nuniform double a__b;\nout vec4 c;\n"
                          "void main() { c = vec4(float(a__b)); }\n",
                          options(doublet::Stage::Fragment, doublet::Target::Es300));
  EXPECT_FALSE(r.ok);
  int errors = 0;
  for (const auto& d : r.diagnostics) errors += d.severity == doublet::Severity::Error;
  EXPECT_EQ(errors, 1) << messages(r);
  EXPECT_NE(messages(r).find("'a__b' contains '__', which GLSL reserves"), std::string::npos) << messages(r);
  EXPECT_NE(messages(r).find("rename it"), std::string::npos) << messages(r);
}

TEST(LoweringForms, DoubleLoopIndexLowersOnEveryTarget) {
  const char* src = R"(#version 300 es
precision highp float;
uniform double e;
out vec4 c;
void main() {
  double s = 0.0lf;
  for (double t = 0.0lf; t < e; t += 0.25lf) s += t;
  c = vec4(float(s));
}
)";
  for (doublet::Target target : kAllTargets) {
    auto r = doublet::lower(src, options(doublet::Stage::Fragment, target));
    ASSERT_TRUE(r.ok) << doublet::to_string(target) << "\n" << messages(r);
    // The constant reads the guard where the guard is a uniform (guard-constants): `0.0 + df_guard`.
    EXPECT_TRUE(std::regex_search(r.output, std::regex(R"(for \(df_double t = df_double\(0\.0[^;]*, 0\.0[^;]*\); df_lt\(t, e\);)")))
        << r.output;
    // ES 1.00 Appendix A guarantees only int and float loop indices: said, with the loop's position.
    const bool warned = messages(r).find("forms.glsl:7:3: warning: a double loop index") != std::string::npos;
    EXPECT_EQ(warned, target == doublet::Target::Es100) << messages(r);
  }
}

doublet::Result lower_compute(const std::string& body) {
  return doublet::lower("#version 450\nlayout(local_size_x = 1) in;\n"
                        "layout(std430, binding = 0) buffer B { int k; double r[]; };\n"
                        "int next(inout int c) { c += 1; return c; }\n"
                        "void main() {\n" + body + "}\n",
                        options(doublet::Stage::Compute, doublet::Target::Glsl450));
}

TEST(LoweringForms, CompoundAssignmentEvaluatesASideEffectIndexOnce) {
  auto r = lower_compute("  double x[4] = double[4](1.0lf, 2.0lf, 3.0lf, 4.0lf);\n  int i = k;\n"
                         "  x[i + 1] += 0.5lf;\n  x[i++] *= r[0];\n  r[1] = x[1] + double(i);\n");
  ASSERT_TRUE(r.ok) << messages(r);
  EXPECT_NE(r.output.find("x[i + 1] = df_add_f(x[i + 1], 0.5);"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("df_mul_assign_double_double(x[i++], r[0]);"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("i++"), r.output.rfind("i++")) << "i++ must appear once:\n" << r.output;
}

TEST(LoweringForms, CompoundOnAComponentThroughSideEffectsIsRefusedWithAdvice) {
  auto r = lower_compute("  dvec3 y[2] = dvec3[2](dvec3(1.0lf), dvec3(2.0lf));\n  int c = k;\n"
                         "  y[next(c)].z -= 0.25lf;\n  r[0] = y[1].z;\n");
  EXPECT_FALSE(r.ok);
  EXPECT_NE(messages(r).find("forms.glsl:8:16: error: compound assignment to a component of a double vector"),
            std::string::npos)
      << messages(r);
  EXPECT_NE(messages(r).find("temporary"), std::string::npos);
}

TEST(LoweringForms, SwizzleOfASwizzleWrittenComposes) {
  auto r = lower_compute("  dvec4 v = dvec4(r[0], r[1], r[2], r[3]);\n  v.xz.y = 7.0lf;\n  v.wzyx.yx += dvec2(1.0lf);\n"
                         "  r[4] = v.z + v.w;\n");
  ASSERT_TRUE(r.ok) << messages(r);
  EXPECT_NE(r.output.find("df_assign_dvec4_z(v, df_double(7.0, 0.0));"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("df_assign_dvec4_zw(v, "), std::string::npos) << r.output;
}

TEST(LoweringForms, DynamicIndexIntoAWrittenSwizzleIsRefusedWithAdvice) {
  auto r = lower_compute("  dvec4 v = dvec4(r[0]);\n  v.xz[k] = 7.0lf;\n  r[4] = v.x;\n");
  EXPECT_FALSE(r.ok);
  EXPECT_NE(messages(r).find("forms.glsl:7:11: error: writing a swizzle of a double vector through a variable index"),
            std::string::npos)
      << messages(r);
}

}  // namespace

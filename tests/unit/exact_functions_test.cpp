// Mode exact for one function of a float-float shader (src/lower/exact_functions.cpp,
// docs/modes.md "Exact functions"): what lowers, how the two representations meet, and each
// refusal by name. Numeric checks on the drivers: golden.verify_exact_functions*.
#include <gtest/gtest.h>

#include <string>

#include "doublet/doublet.hpp"

namespace {

std::string messages(const doublet::Result& r) {
  std::string s;
  for (const auto& d : r.diagnostics) s += doublet::format_diagnostic(d) + "\n";
  return s;
}

doublet::Result lower(const std::string& source, doublet::Target target = doublet::Target::Es310,
                      doublet::Mode mode = doublet::Mode::Df64, std::vector<std::pair<std::string, doublet::Mode>> mode_for = {}) {
  doublet::Options o;
  o.stage = doublet::Stage::Compute;
  o.target = target;
  o.mode = mode;
  o.mode_for = std::move(mode_for);
  o.file_name = "shader.comp";
  return doublet::lower(source, o);
}

void expect_error(const doublet::Result& r, std::initializer_list<const char*> fragments) {
  ASSERT_FALSE(r.ok) << "expected an error";
  const std::string all = messages(r);
  for (const char* f : fragments) EXPECT_NE(all.find(f), std::string::npos) << "missing '" << f << "' in\n" << all;
  EXPECT_EQ(all.find("internal error"), std::string::npos) << all;
}

const std::string kHead = "#version 450\nlayout(local_size_x = 1) in;\nlayout(std430, binding = 0) buffer B { double v[]; };\n";
const std::string kSum = "double sum(dvec2 a, int n) { double s = a.x; for (int k = 0; k < n; ++k) s += a.y; return s; }\n";
const std::string kMain = "void main() { v[0] = sum(dvec2(v[1], v[2]), 3) * v[3]; }\n";

TEST(ExactFunctions, ThePragmaAndModeForGiveTheSameLoweringInEveryFloatFloatMode) {
  const doublet::Result by_pragma = lower(kHead + "#pragma doublet mode(exact)\n" + kSum + kMain);
  ASSERT_TRUE(by_pragma.ok) << messages(by_pragma);
  const std::string& out = by_pragma.output;
  // The exact part under its own names, the shader's in df64, one conversion each way at the call.
  EXPECT_NE(out.find("struct ex_double { uint hi; uint lo; };"), std::string::npos) << out;
  EXPECT_NE(out.find("struct df_double { float hi; float lo; };"), std::string::npos) << out;
  EXPECT_NE(out.find("ex_double sum(ex_dvec2 a, int n)"), std::string::npos) << out;
  EXPECT_NE(out.find("s = ex_add(s, ex_double(a.hi.y, a.lo.y));"), std::string::npos) << out;
  EXPECT_NE(out.find("df_mul(df_from_exact(sum(df_to_exact("), std::string::npos) << out;
  EXPECT_EQ(out.find("df_double sum("), std::string::npos) << out;
  const doublet::Result by_option = lower(kHead + kSum + kMain, doublet::Target::Es310, doublet::Mode::Df64,
                                          {{"sum", doublet::Mode::Exact}});
  ASSERT_TRUE(by_option.ok) << messages(by_option);
  EXPECT_EQ(by_option.output, out);
  for (doublet::Mode m : {doublet::Mode::Df64Fast, doublet::Mode::Df64Int})
    for (doublet::Target t : {doublet::Target::Es300, doublet::Target::Glsl330, doublet::Target::Glsl450}) {
      doublet::Options o;
      const std::string vertex = "#version 450\nin dvec2 p;\nout vec4 c;\n#pragma doublet mode(exact)\n" + kSum +
                                 "void main() { double s = sum(p, 2); c = vec4(float(s)); gl_Position = c; }\n";
      o.stage = doublet::Stage::Vertex, o.target = t, o.mode = m;
      const doublet::Result r = doublet::lower(vertex, o);
      ASSERT_TRUE(r.ok) << messages(r);
      EXPECT_NE(r.output.find("df_from_exact(sum(df_to_exact(p), 2))"), std::string::npos) << r.output;
    }
}

TEST(ExactFunctions, AFunctionWithoutDoublesNeedsNoConversion) {
  const doublet::Result r = lower("#version 450\nlayout(local_size_x = 1) in;\nlayout(std430, binding = 0) buffer B { float f[]; };\n"
                                  "#pragma doublet mode(exact)\nfloat twice(float x) { return x * 2.0; }\n"
                                  "void main() { f[0] = twice(f[1]); }\n");
  ASSERT_TRUE(r.ok) << messages(r);
  EXPECT_EQ(r.output.find("df_to_exact"), std::string::npos) << r.output;
}

TEST(ExactFunctions, WhatCannotBeExactIsRefusedByName) {
  const std::string pragma = "#pragma doublet mode(exact)\n";
  expect_error(lower(kHead + "double g;\n" + pragma + "double f(double a) { return a + g; }\nvoid main() { v[0] = f(v[1]); }\n"),
               {"exact function 'f'", "double global 'g'", "pass it as a parameter"});
  expect_error(lower(kHead + "double h(double a) { return a; }\n" + pragma +
                     "double f(double a) { return h(a); }\nvoid main() { v[0] = f(v[1]); }\n"),
               {"exact function 'f'", "calls 'h'", "make it exact too"});
  expect_error(lower(kHead + pragma + "void f(double a, out double b) { b = a; }\nvoid main() { double b; f(v[1], b); v[0] = b; }\n"),
               {"parameter 'b' is out/inout"});
  expect_error(lower(kHead + pragma + "double f(dmat2 m) { return m[0][0]; }\nvoid main() { v[0] = f(dmat2(v[1])); }\n"),
               {"parameter 'm' is a dmat2"});
  expect_error(lower(kHead + pragma + "void main() { v[0] = v[1]; }\n"), {"main cannot be exact alone", "--mode exact"});
  expect_error(lower(kHead + pragma + "double f(double a) { return a; }\nfloat f(float a) { return a; }\n"
                     "void main() { v[0] = f(v[1]); }\n"),
               {"overloaded function cannot be exact"});
  expect_error(lower(kHead + "void main() {\n#pragma doublet mode(exact)\n  double x = v[1];\n  v[0] = x;\n}\n"),
               {"mode exact applies to a whole shader (--mode exact) or to functions"});
  expect_error(lower(kHead + "void main() { double x = v[1]; v[0] = x; }\n", doublet::Target::Es310, doublet::Mode::Df64,
                     {{"main.x", doublet::Mode::Exact}}),
               {"--mode-for main.x=exact", "or to functions"});
  expect_error(lower(kHead + kSum + kMain, doublet::Target::Es310, doublet::Mode::Fp32, {{"sum", doublet::Mode::Exact}}),
               {"needs the shader in a float-float mode", "not --mode fp32"});
  expect_error(lower(kHead + pragma + kSum + kMain, doublet::Target::Wgsl), {"not lowered for wgsl yet"});
  doublet::Options es100;
  es100.stage = doublet::Stage::Vertex, es100.target = doublet::Target::Es100, es100.file_name = "shader.vert";
  expect_error(doublet::lower("#version 450\nin dvec2 p;\n" + pragma + kSum +
                                  "void main() { gl_Position = vec4(float(sum(p, 2))); }\n", es100),
               {"mode exact needs 32-bit integers", "es300"});
}

}  // namespace

// Bugs found by lowering glslang's own test shaders (glslang_suite_test.cpp), each reduced to a few
// lines that need no fetched corpus.
#include <gtest/gtest.h>

#include <string>

#include "doublet/doublet.hpp"

namespace {

using namespace doublet;

Options options(Stage stage, Target target, Mode mode = Mode::Df64) {
  Options o;
  o.stage = stage;
  o.target = target;
  o.mode = mode;
  o.file_name = "peer.glsl";
  o.disabled_lints = {"all"};
  return o;
}

std::string messages(const Result& r) {
  std::string s;
  for (const auto& d : r.diagnostics) s += format_diagnostic(d) + "\n";
  return s;
}

// stringToDouble.vert: `double e12 = 1e+309;` is infinity, which mode native printed as `inf.0lf`
// (internal error: 'inf' : undeclared identifier).
TEST(PeerRegressions, NativeInfinityAndNanConstantsArePrintable) {
  const char* shader = R"(#version 450
layout(location = 0) out vec4 color;
uniform double u;
void main() {
  double big = 1e+309;
  double low = -1e+309lf;
  double nan = u < 0.0lf ? big + low : u;
  color = vec4(float(big), float(low), float(nan), 1.0);
}
)";
  Result r = lower(shader, options(Stage::Fragment, Target::Glsl450, Mode::Native));
  ASSERT_TRUE(r.ok) << messages(r);
  EXPECT_NE(r.output.find("(1.0lf / 0.0lf)"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("(-1.0lf / 0.0lf)"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("inf"), std::string::npos) << r.output;
}

}  // namespace

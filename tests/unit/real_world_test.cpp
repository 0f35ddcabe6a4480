// Constructs of real-world shaders (issue 12): every shader glslang accepts is lowered or
// refused with a diagnostic that names the construct, the target and what to do instead —
// never an internal error. Golden cases (tests/golden/cases) show the lowered text; these
// tests check the diagnostics.
#include <gtest/gtest.h>

#include <string>

#include "doublet/doublet.hpp"

namespace {

using doublet::Severity;
using doublet::Stage;
using doublet::Target;

doublet::Result lower(const std::string& source, Stage stage, Target target) {
  doublet::Options o;
  o.stage = stage;
  o.target = target;
  o.file_name = "real.glsl";
  return doublet::lower(source, o);
}

std::string messages(const doublet::Result& r) {
  std::string s;
  for (const auto& d : r.diagnostics) s += doublet::format_diagnostic(d) + "\n";
  return s;
}

// The diagnostic of `severity` whose message contains `fragment`, or null.
const doublet::Diagnostic* find(const doublet::Result& r, Severity severity, const std::string& fragment) {
  for (const auto& d : r.diagnostics)
    if (d.severity == severity && d.message.find(fragment) != std::string::npos) return &d;
  return nullptr;
}

void expect_no_internal_error(const doublet::Result& r) {
  EXPECT_EQ(messages(r).find("internal error"), std::string::npos) << messages(r);
}

const char* kPrecise = R"(#version 450
uniform double u;
out vec4 color;
void main() {
  precise double a = u * 3.0lf;
  color = vec4(float(a));
}
)";

TEST(RealWorld, UserPreciseIsDroppedWithAWarningWhereTheTargetLacksIt) {
  for (Target t : {Target::Es100, Target::Es300, Target::Es310, Target::Glsl330}) {
    auto r = lower(kPrecise, Stage::Fragment, t);
    EXPECT_TRUE(r.ok) << messages(r);
    const auto* w = find(r, Severity::Warning, "'precise' on 'a' is dropped: target " + std::string(to_string(t)));
    ASSERT_NE(w, nullptr) << messages(r);
    EXPECT_EQ(w->line, 5);
    EXPECT_EQ(r.output.find("precise df_double"), std::string::npos);
  }
  for (Target t : {Target::Es320, Target::Glsl450}) {
    auto r = lower(kPrecise, Stage::Fragment, t);
    EXPECT_TRUE(r.ok) << messages(r);
    EXPECT_EQ(find(r, Severity::Warning, "'precise'"), nullptr) << messages(r);
    EXPECT_NE(r.output.find("precise df_double a"), std::string::npos);
  }
}

}  // namespace

// verify() for vertex and fragment stages on real drivers (lavapipe and GLES): the lowered shaders
// keep their bits in the stage where they run, the report carries the stage's FTZ probe, and each
// sabotage turns the check red (drop-lo, the fp32 demotion: <= 24 bits).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "verify/report.hpp"
#include "verify/verify.hpp"

namespace doublet::verify {
namespace {

std::string read(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

struct Case {
  const char* dir;
  const char* file;       // shader file in dir; its spec is tests/verify/shaders/<file>.json
  Target target;
  double expected_bits;   // every output, both backends, without sabotage
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.file; }

VerifyReport run(const Case& c, Sabotage sabotage) {
  VerifyOptions o;
  o.lower.file_name = c.file;
  o.lower.stage = stage_from_path(c.file);
  o.lower.target = c.target;
  o.samples = 512;
  o.sabotage = sabotage;
  EXPECT_EQ(parse_spec(read(std::string(DOUBLET_VERIFY_SHADERS) + "/" + c.file + ".json"), &o.spec), "");
  o.min_bits = 44;  // outputs the spec does not override (float gl_Position: 24 in its spec)
  return verify(read(std::string(c.dir) + "/" + c.file), o);
}

double worst_bits(const VerifyReport& r) {
  double worst = kMaxBits;
  for (const BackendRun& run : r.runs)
    for (const OutputStats& o : run.outputs) worst = std::min(worst, o.min_bits);
  return worst;
}

void expect_ran_on_both_backends(const VerifyReport& r) {
  ASSERT_EQ(r.input_error, "") << format_table(r);
  ASSERT_EQ(r.runs.size(), 2u) << format_table(r);
  for (const BackendRun& run : r.runs) {
    EXPECT_EQ(run.error, "") << format_table(r);
    EXPECT_EQ(run.probe.error, "");
    EXPECT_EQ(run.probe.stage, r.stage);
    EXPECT_FALSE(run.outputs.empty());
    for (const OutputStats& o : run.outputs) EXPECT_EQ(o.class_mismatches, 0u) << o.name;
  }
}

class VerifyStage : public ::testing::TestWithParam<Case> {};

TEST_P(VerifyStage, KeepsItsBitsOnBothBackendsWithTheFtzCaveat) {
  const VerifyReport r = run(GetParam(), Sabotage::None);
  expect_ran_on_both_backends(r);
  std::printf("%s", format_table(r).c_str());
  EXPECT_TRUE(r.passed()) << format_table(r);
  EXPECT_GE(worst_bits(r), GetParam().expected_bits);
  // docs/numerics.md#measured-driver-facts: vertex and fragment stages flush denormals; the report
  // must say so.
  for (const BackendRun& run : r.runs) EXPECT_TRUE(run.probe.denormals_flushed);
  EXPECT_NE(format_table(r).find("caveat: this stage flushes denormals"), std::string::npos);
}

TEST_P(VerifyStage, DropGuardSabotageFails) {
  const VerifyReport r = run(GetParam(), Sabotage::DropGuard);
  expect_ran_on_both_backends(r);
  EXPECT_FALSE(r.passed()) << "sabotage did not turn the check red:\n" << format_table(r);
}

TEST_P(VerifyStage, DropLoSabotageIsFloatPrecision) {
  const VerifyReport r = run(GetParam(), Sabotage::DropLo);
  expect_ran_on_both_backends(r);
  EXPECT_FALSE(r.passed());
  EXPECT_LE(worst_bits(r), 24.0) << format_table(r);
}

// The foundation's relative-to-eye shader (positions and eye in [1e6, 1e7], identity viewProj):
// its float gl_Position matches native fp64 bit for bit (60 = exact; one float ulp would be ~23).
INSTANTIATE_TEST_SUITE_P(Shaders, VerifyStage,
                         ::testing::Values(Case{DOUBLET_GOLDEN_CASES, "rte_position.vert", Target::Es300, 60},
                                           Case{DOUBLET_VERIFY_SHADERS, "pairs.vert", Target::Es310, 44},
                                           Case{DOUBLET_VERIFY_SHADERS, "pairs.frag", Target::Es300, 44},
                                           Case{DOUBLET_VERIFY_SHADERS, "pairs.frag", Target::Es320, 44}),
                         [](const auto& info) {
                           std::string name = info.param.file;
                           for (char& c : name)
                             if (c == '.') c = '_';
                           return name + "_" + std::string(to_string(info.param.target));
                         });

// ES 1.00 text (attribute/varying) runs as ES 3.10 in the capture, on both drivers.
TEST(VerifyStageInputs, Es100VertexShaderRunsOnBothBackends) {
  const Case es100{DOUBLET_GOLDEN_CASES, "rte_position.vert", Target::Es100, 44};
  const VerifyReport r = run(es100, Sabotage::None);
  expect_ran_on_both_backends(r);
  EXPECT_GE(worst_bits(r), 20) << format_table(r);  // gl_Position is float (its spec: 24)
  EXPECT_TRUE(r.passed()) << format_table(r);
}

}  // namespace
}  // namespace doublet::verify

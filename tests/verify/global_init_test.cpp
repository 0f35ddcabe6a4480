// Global initialisers that read a double uniform run after the uniform's hi/lo join (issue 12):
// tests/verify/shaders/global_init.comp on real drivers, for an ES target (where they must move
// into main) and glsl450 (where, printed at global scope, they silently read zero: inf and 0).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "verify/report.hpp"
#include "verify/verify.hpp"

namespace doublet::verify {
namespace {

std::string read_shader_file(const std::string& name) {
  std::ifstream in(std::string(DOUBLET_VERIFY_SHADERS) + "/" + name);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

class GlobalInitialisers : public ::testing::TestWithParam<Target> {};

TEST_P(GlobalInitialisers, SeeTheUniformsValue) {
  VerifyOptions o;
  o.lower.stage = Stage::Compute;
  o.lower.target = GetParam();
  o.lower.file_name = "global_init.comp";
  o.samples = 32;
  o.min_bits = 44;
  ASSERT_EQ(parse_spec(read_shader_file("global_init.json"), &o.spec), "");
  const VerifyReport r = verify(read_shader_file("global_init.comp"), o);
  ASSERT_EQ(r.input_error, "") << format_table(r);
  ASSERT_FALSE(r.runs.empty());
  for (const BackendRun& run : r.runs) EXPECT_EQ(run.error, "") << format_table(r);
  EXPECT_TRUE(r.passed()) << format_table(r);
}

INSTANTIATE_TEST_SUITE_P(Targets, GlobalInitialisers, ::testing::Values(Target::Es310, Target::Glsl450),
                         [](const ::testing::TestParamInfo<Target>& info) { return std::string(to_string(info.param)); });

}  // namespace
}  // namespace doublet::verify

// The optimizer's rules (rules/opt.glsl, substituted by src/lower/optimize_df.cpp) on a real
// driver: each per-op kernel is lowered with and without the optimizer, run on Mesa GLES, and its
// worst error over 4096 inputs compared with a long double host reference. The optimized form
// must keep at least 44 bits, lose nothing against the general rules, and the measurement must
// catch a broken rule (a sabotaged copy of the emitted text loses the lo word's contribution).
#include <gtest/gtest.h>

#include <doublet/doublet.hpp>

#include "bench/handwritten.hpp"

namespace {
using namespace doublet;

std::string lowered(const std::string& op, Target target, bool optimize) {
  Options o;
  o.stage = Stage::Compute;
  o.target = target;
  o.optimize = optimize;
  o.file_name = op + ".comp";
  Result r = lower(bench::double_kernel(op, 8), o);
  EXPECT_TRUE(r.ok) << op;
  return r.output;
}

double bits(const std::string& op, const std::string& glsl) {
  std::string error;
  const double b = bench::kernel_bits(op, glsl, 4096, &error);
  EXPECT_GE(b, 0) << op << ": " << error;
  return b;
}

struct Case {
  const char* op;
  const char* rule;      // what the optimizer must have substituted
  const char* intact;    // text of the rule's lo-word step in the emitted GLSL...
  const char* broken;    // ...and its sabotaged replacement
};

class OptAccuracy : public ::testing::TestWithParam<std::tuple<Case, Target>> {};

TEST_P(OptAccuracy, OptimizedFormKeeps44BitsAndSabotageIsCaught) {
  const auto& [c, target] = GetParam();
  SCOPED_TRACE(std::string(c.op) + " " + std::string(to_string(target)));
  const std::string opt = lowered(c.op, target, true);
  const std::string plain = lowered(c.op, target, false);
  ASSERT_NE(opt.find(std::string(c.rule) + "("), std::string::npos) << "the optimizer did not use " << c.rule;
  ASSERT_EQ(plain.find(std::string(c.rule) + "("), std::string::npos);
  const double b_opt = bits(c.op, opt), b_plain = bits(c.op, plain);
  EXPECT_GE(b_opt, 44.0);
  EXPECT_GE(b_opt, b_plain - 0.5) << "optimized " << b_opt << " bits, general rules " << b_plain;

  std::string sabotaged = opt;
  const size_t at = sabotaged.find(c.intact);
  ASSERT_NE(at, std::string::npos) << "sabotage point '" << c.intact << "' not in the emitted text";
  sabotaged.replace(at, std::string(c.intact).size(), c.broken);
  EXPECT_LT(bits(c.op, sabotaged), 40.0) << "the accuracy check does not see a broken " << c.rule;
}

const Case kCases[] = {
    {"sqr", "df_sqr", "c + c", "c * 0.0"},                  // drop the cross term 2·hi·lo
    {"pow2", "df_mul_pow2", "a.lo * p", "a.lo * 0.0"},       // drop the scaled lo word
    {"mulf", "df_mul_f2", "a.lo * b", "a.lo * 0.0"},         // drop lo·b
    {"addf", "df_add_f", "a.lo + s.lo", "s.lo + 0.0"},       // drop a.lo
};

INSTANTIATE_TEST_SUITE_P(Rules, OptAccuracy,
                         ::testing::Combine(::testing::ValuesIn(kCases), ::testing::Values(Target::Es310, Target::Es320)),
                         [](const auto& info) {
                           return std::string(std::get<0>(info.param).op) + "_" +
                                  std::string(to_string(std::get<1>(info.param)));
                         });

}  // namespace

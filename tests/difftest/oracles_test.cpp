// The differential tester's oracles on lavapipe and Mesa GLES (src/difftest/oracles.hpp): they hold
// on generated programs, and each one reports a finding when a bug is put back on purpose — the
// lowering's low words dropped (verify's drop-lo sabotage on the exact and df64-int runs), or a pass
// left out of the pipeline.
#include <gtest/gtest.h>

#include <string>

#include "difftest/generator.hpp"
#include "difftest/oracles.hpp"

namespace doublet::difftest {
namespace {

bool has_finding(const CheckResult& r, const std::string& oracle) {
  for (const Finding& f : r.findings)
    if (f.oracle == oracle) return true;
  return false;
}

std::string describe(const CheckResult& r) {
  std::string s = r.invalid;
  for (const Finding& f : r.findings) s += "\n[" + f.oracle + "] " + f.detail;
  return s;
}

// The first program (from seed 1) that has `feature` and none of the built-ins native rounds badly.
Program first_with(const std::string& feature) {
  for (uint64_t seed = 1;; ++seed) {
    Program p = generate(seed);
    if (p.features.count(feature) && !uses_native_non_ieee(p)) return p;
  }
}

CheckOptions quick() {
  CheckOptions o;
  o.samples = 64;
  return o;
}

TEST(DiffOracles, HoldOnAGeneratedProgram) {
  const Program p = first_with("stmt:for");
  const CheckResult r = check(p.glsl, p.spec_json, p.stage, quick());
  EXPECT_TRUE(r.invalid.empty()) << r.invalid;
  EXPECT_TRUE(r.findings.empty()) << "seed " << p.seed << describe(r);
  EXPECT_EQ(r.checked, (std::vector<std::string>{"exact", "int", "targets"}));
}

TEST(DiffOracles, DroppedLowWordsAreFoundByTheExactAndIntOracles) {
  const Program p = first_with("op:*");
  CheckOptions o = quick();
  o.sabotage = "drop-lo";
  const CheckResult r = check(p.glsl, p.spec_json, p.stage, o);
  EXPECT_TRUE(has_finding(r, "exact")) << "seed " << p.seed << describe(r);
  EXPECT_TRUE(has_finding(r, "int")) << "seed " << p.seed << describe(r);
}

TEST(DiffOracles, APassLeftOutIsFound) {
  // f(v.y) for an out parameter: without out-argument-temporaries the lowering cannot pass a
  // component of a split vector.
  const Program p = first_with("call:component-out-argument");
  CheckOptions o = quick();
  o.oracles = {"int"};
  EXPECT_TRUE(check(p.glsl, p.spec_json, p.stage, o).findings.empty()) << "seed " << p.seed;
  o.skip_passes = {"out-argument-temporaries"};
  const CheckResult r = check(p.glsl, p.spec_json, p.stage, o);
  EXPECT_FALSE(r.findings.empty()) << "seed " << p.seed << "\n" << p.glsl;
}

}  // namespace
}  // namespace doublet::difftest

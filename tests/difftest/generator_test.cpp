// The differential tester's generator (src/difftest/generator.hpp), without drivers: a seed names one
// program; every program compiles as GLSL 4.50 with doubles and lowers in the modes and targets the
// oracles run; together the programs reach the operators, built-ins and statements it lists.
#include <gtest/gtest.h>

#include <regex>
#include <set>
#include <string>

#include "difftest/generator.hpp"
#include "difftest/oracles.hpp"
#include "difftest/reduce.hpp"
#include "doublet/doublet.hpp"

namespace doublet::difftest {
namespace {

constexpr uint64_t kSeeds = 120;

TEST(DiffGenerator, ASeedNamesOneProgram) {
  for (uint64_t seed : {1u, 2u, 77u}) EXPECT_EQ(generate(seed).glsl, generate(seed).glsl);
  EXPECT_NE(generate(1).glsl, generate(2).glsl);
}

TEST(DiffGenerator, ProgramsCompileNativelyAndLowerInEveryOraclesMode) {
  const std::pair<Mode, Target> lowerings[] = {{Mode::Exact, Target::Es310}, {Mode::Df64, Target::Es310},
                                               {Mode::Df64Int, Target::Es310}, {Mode::Df64, Target::Es320},
                                               {Mode::Df64, Target::Glsl450}};
  for (uint64_t seed = 1; seed <= kSeeds; ++seed) {
    const Program p = generate(seed);
    std::string error;
    ASSERT_TRUE(compiles_natively(p.glsl, p.stage, &error)) << "seed " << seed << "\n" << error << "\n" << p.glsl;
    const Stage stage = parse_stage(p.stage).value_or(Stage::Compute);
    for (const auto& [mode, target] : lowerings) {
      Options o;
      o.stage = stage;
      o.mode = mode;
      o.target = target;
      o.check_ir = true;
      const Result r = lower(p.glsl, o);
      std::string diagnostics;
      for (const Diagnostic& d : r.diagnostics) diagnostics += d.message + "\n";
      EXPECT_TRUE(r.ok) << "seed " << seed << ", " << to_string(mode) << " " << to_string(target) << ":\n"
                        << diagnostics << p.glsl;
    }
  }
}

TEST(DiffGenerator, ProgramsReachNearlyEveryFeature) {
  std::set<std::string> covered;
  for (uint64_t seed = 1; seed <= kSeeds; ++seed) {
    const Program p = generate(seed);
    covered.insert(p.features.begin(), p.features.end());
  }
  std::string missing;
  for (const std::string& f : all_features())
    if (!covered.count(f)) missing += " " + f;
  for (const std::string& f : covered)
    EXPECT_NE(std::find(all_features().begin(), all_features().end(), f), all_features().end()) << "unlisted feature " << f;
  EXPECT_GE(covered.size() * 100, all_features().size() * 95) << "not reached:" << missing;
}

}  // namespace
}  // namespace doublet::difftest

namespace doublet::difftest {
namespace {

// The arguments of every call of `fn` in `glsl`, split at top-level commas.
std::vector<std::vector<std::string>> calls_of(const std::string& glsl, const std::string& fn) {
  std::vector<std::vector<std::string>> calls;
  for (size_t at = glsl.find(fn + "("); at != std::string::npos; at = glsl.find(fn + "(", at + 1)) {
    if (at > 0 && (std::isalnum(static_cast<unsigned char>(glsl[at - 1])) || glsl[at - 1] == '_')) continue;
    std::vector<std::string> args(1);
    int depth = 0;
    for (size_t i = at + fn.size() + 1; i < glsl.size(); ++i) {
      const char c = glsl[i];
      if (depth == 0 && c == ')') break;
      if (depth == 0 && c == ',') {
        args.emplace_back();
        continue;
      }
      depth += c == '(' ? 1 : c == ')' ? -1 : 0;
      args.back() += c;
    }
    calls.push_back(args);
  }
  return calls;
}

TEST(DiffGenerator, ReadsAVariableTellsConstantsFromVariables) {
  for (const std::string constant : {"dvec3(2.0lf)", "(dvec3(2.76lf, -1.37lf, 2.89lf) + 1.0lf)", "1e-3lf", "-0.5lf",
                                     "double(true)"})
    EXPECT_FALSE(reads_a_variable(constant)) << constant;
  for (const std::string variable : {"x1.xyx", "in0[gid]", "(dvec3(1.0lf) + x0.yxy)", "abs(s_1)"})
    EXPECT_TRUE(reads_a_variable(variable)) << variable;
}

// Seeds 70089 and 70272 (a 2-hour run, 2026-11-28): mode exact one ulp from native for a mix of two
// constant ends and for reflect with a constant normal, where lavapipe folded the constants into its
// expansion of the built-in. The generator avoided both forms until verify's native reference made
// built-ins NoContraction (tests/difftest/cases hold the forms, each failing before); it writes them
// again, and the exact oracle checks them.
TEST(DiffGenerator, WritesMixesOfConstantsAndReflectsOnConstantNormals) {
  int constant_mixes = 0, constant_normals = 0;
  for (uint64_t seed = 1; seed <= 3 * kSeeds; ++seed) {
    const Program p = generate(seed);
    for (const auto& args : calls_of(p.glsl, "mix"))
      if (args.size() == 3 && !reads_a_variable(args[0]) && !reads_a_variable(args[1])) ++constant_mixes;
    for (const auto& args : calls_of(p.glsl, "reflect"))
      if (args.size() == 2 && !reads_a_variable(args[1])) ++constant_normals;
  }
  EXPECT_GT(constant_mixes, 0);
  EXPECT_GT(constant_normals, 0);
}

// The reducer keeps only candidates whose while/do-while counters are still incremented: seed
// 70349's reduction dropped `w12++;` and gave a program that never ends (docs/robustness.md).
TEST(DiffReducer, KeepsTheStepsOfTheGeneratorsLoops) {
  const std::regex step(R"(\n *(w\d+)\+\+;)");  // a while or do-while counter's increment
  int loops = 0;
  for (uint64_t seed = 1; seed <= kSeeds; ++seed) {
    const std::string glsl = generate(seed).glsl;
    EXPECT_TRUE(keeps_loop_steps(glsl)) << "seed " << seed;
    std::smatch m;
    if (!std::regex_search(glsl, m, step)) continue;
    ++loops;
    const std::string without = m.prefix().str() + "\n" + m.suffix().str();
    EXPECT_FALSE(keeps_loop_steps(without)) << "seed " << seed << ": without " << m[1] << "++\n" << without;
  }
  EXPECT_GT(loops, 5);
}

// Seed 70571 (the long run): mode exact 1-3 ulps from native, reduced by hand to reflect(x.xx, x):
// with aliased operands lavapipe's reflect differed from its own written I - 2 dot(N, I) N. The
// exact oracle skipped programs with reflect until native's built-ins were NoContraction too
// (tests/difftest/cases/reflect_constant_and_aliased.frag); now it checks them.
TEST(DiffGenerator, TheExactOracleChecksReflect) {
  const Program p = generate(70571);
  ASSERT_TRUE(p.features.count("fn:reflect"));
  EXPECT_FALSE(uses_native_non_ieee(p));
}

}  // namespace
}  // namespace doublet::difftest

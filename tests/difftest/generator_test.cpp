// The differential tester's generator (src/difftest/generator.hpp), without drivers: a seed names one
// program; every program compiles as GLSL 4.50 with doubles and lowers in the modes and targets the
// oracles run; together the programs reach the operators, built-ins and statements it lists.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "difftest/generator.hpp"
#include "difftest/oracles.hpp"
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

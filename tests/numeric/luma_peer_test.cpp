// doublet's transcendentals next to luma.gl's fp64 module (the npm package, tools/peers; see
// docs/transcendentals.md) on the same inputs, lavapipe and Mesa GLES: doublet must keep >= 44
// bits and at least luma.gl's bits on every function and domain. The sabotage (doublet's optimizer
// guard removed) must fall below both marks, so the comparison can fail. Skipped, with the reason,
// where node or the package is missing, unless DOUBLET_REQUIRE_BROWSER=1 (.ci/run sets it: npm ci
// runs there).
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "bench/luma_peer.hpp"
#include "bench/transcendental_bench.hpp"

namespace {

using doublet::bench::Domain;
using doublet::bench::TranscendentalVariant;
using doublet::runner::Backend;

constexpr int kSamples = 1024;

struct Case {
  Backend backend;
  doublet::Target target;
};

class LumaPeer : public ::testing::TestWithParam<Case> {
 protected:
  void SetUp() override {
    const doublet::bench::LumaLibrary& lib = doublet::bench::luma_fp64_library();
    if (lib.ok) return;
    const char* required = std::getenv("DOUBLET_REQUIRE_BROWSER");
    if (lib.unavailable && !(required && std::string(required) == "1")) GTEST_SKIP() << "no luma.gl: " << lib.error;
    FAIL() << "luma.gl: " << lib.error;
  }
};

std::vector<Domain> domains(const std::string& function) {
  if (doublet::bench::is_trig(function)) return {Domain::Main, Domain::Wide};
  return {Domain::Main};
}

TEST_P(LumaPeer, DoubletKeeps44BitsAndAtLeastLumasOnTheSameInputs) {
  const auto [backend, target] = GetParam();
  for (const std::string& f : doublet::bench::transcendental_functions())
    for (Domain d : domains(f)) {
      const auto luma = doublet::bench::transcendental_accuracy(f, TranscendentalVariant::Luma, backend, target, d, kSamples);
      const auto df64 = doublet::bench::transcendental_accuracy(f, TranscendentalVariant::Df64, backend, target, d, kSamples);
      ASSERT_TRUE(luma.ok) << f << ": " << luma.error;
      ASSERT_TRUE(df64.ok) << f << ": " << df64.error;
      std::printf("  %-4s %-22s doublet %6.2f bits, luma.gl %6.2f bits\n", f.c_str(), doublet::bench::domain_name(f, d),
                  df64.min_bits, luma.min_bits);
      EXPECT_GE(df64.min_bits, 44.0) << f << " " << doublet::bench::domain_name(f, d) << ": " << df64.worst;
      EXPECT_GE(df64.min_bits, luma.min_bits) << f << " " << doublet::bench::domain_name(f, d) << ": " << df64.worst;
    }
}

// The same comparison with doublet's optimizer guard removed: Mesa folds the error terms away and
// doublet's results drop below 44 bits and below luma.gl's (which keeps its own `ONE` guard).
TEST_P(LumaPeer, WithoutTheGuardDoubletFallsBelowBothMarks) {
  const auto [backend, target] = GetParam();
  int below = 0;
  for (const std::string& f : doublet::bench::transcendental_functions()) {
    const auto luma = doublet::bench::transcendental_accuracy(f, TranscendentalVariant::Luma, backend, target,
                                                              Domain::Main, kSamples);
    const auto df64 = doublet::bench::transcendental_accuracy(f, TranscendentalVariant::Df64, backend, target,
                                                              Domain::Main, kSamples, doublet::GuardKind::None);
    ASSERT_TRUE(luma.ok && df64.ok) << f << ": " << luma.error << df64.error;
    std::printf("  %-4s guard removed: doublet %6.2f bits, luma.gl %6.2f bits\n", f.c_str(), df64.min_bits, luma.min_bits);
    below += df64.min_bits < 44.0 && df64.min_bits < luma.min_bits;
  }
  EXPECT_EQ(below, 5) << "some function kept its bits without the guard: the comparison could not fail there";
}

INSTANTIATE_TEST_SUITE_P(Drivers, LumaPeer,
                         ::testing::Values(Case{Backend::Vulkan, doublet::Target::Es310},
                                           Case{Backend::Vulkan, doublet::Target::Glsl450},
                                           Case{Backend::Gles, doublet::Target::Es310},
                                           Case{Backend::Gles, doublet::Target::Es320}),
                         [](const auto& info) {
                           return std::string(doublet::runner::backend_name(info.param.backend)) + "_" +
                                  std::string(doublet::to_string(info.param.target));
                         });

}  // namespace

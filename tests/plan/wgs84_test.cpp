// The WGS84 example (docs/examples-wgs84.md) on lavapipe and Mesa GLES: `doublet plan` chooses a
// mode per value for examples/scenes/wgs84_ecef.vert, and the shader lowered with that plan keeps
// the scene's promise (positions relative to the eye within 1 mm) against MPFR, where fp32 does
// not. Downgrading any step the plan kept in df64, or removing the optimizer guard, breaks it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "cli_run.hpp"
#include "wgs84_harness.hpp"

namespace {

using doublet::runner::Backend;
using namespace plan_test;

constexpr double kRelPromise = 1e-3;  // wgs84.scene.json: v_rel within 1 mm
constexpr double kUpPromise = 1e-2;   // v_up within 0.01

const std::vector<wgs84::View>& views() {
  static const std::vector<wgs84::View> v = wgs84::make_globe_views(64, 64, 20261124);
  return v;
}

std::string plan_file() {
  static const std::string path = [] {
    const std::string out = (std::filesystem::temp_directory_path() / "doublet_wgs84.plan.json").string();
    const CliRun r = run_doublet("plan " + kScenes + "/wgs84_ecef.vert --scene " + kScenes + "/wgs84.scene.json -o " + out);
    EXPECT_EQ(r.exit_code, 0) << r.out;
    return out;
  }();
  return path;
}

doublet::Options planned(const std::vector<std::pair<std::string, doublet::Mode>>& downgrades = {}) {
  doublet::Options o;
  o.target = doublet::Target::Es300;
  std::string error;
  EXPECT_TRUE(wgs84::apply_plan_file(plan_file(), &o, &error)) << error;
  for (const auto& d : downgrades) o.mode_for.push_back(d);
  return o;
}

wgs84::Errors measure(Backend backend, const doublet::Options& options) {
  const doublet::Result lowered = wgs84::lower_example("wgs84_ecef.vert", options);
  wgs84::Errors e;
  if (!lowered.ok) {
    for (const auto& d : lowered.diagnostics) e.error += doublet::format_diagnostic(d) + "\n";
    return e;
  }
  e = wgs84::measure_vertex(backend, lowered.output, views());
  std::printf("  %zu points: v_rel max %.3g m, v_up max %.3g, not finite %d; worst %s\n", e.samples, e.rel_max,
              e.up_max, e.not_finite, e.worst.c_str());
  return e;
}

// The reference itself, at points whose ECEF coordinates are published: the equator on the prime
// meridian is (a, 0, 0); the pole is at the semi-minor axis b = 6356752.314245 m (NIMA TR8350.2).
TEST(Wgs84Reference, KnownPoints) {
  const wgs84::Vec3 equator = wgs84::reference_rel({0, 0, 0}, {0, 0, 0});
  EXPECT_EQ(equator[0], 6378137.0);
  EXPECT_EQ(equator[1], 0.0);
  EXPECT_EQ(equator[2], 0.0);
  const wgs84::Vec3 pole = wgs84::reference_rel({1.5707963267948966, 0, 100}, {0, 0, 6356752.0});
  EXPECT_NEAR(pole[2], 100 + 0.314245, 1e-6);
  EXPECT_LT(std::fabs(pole[0]), 1e-9);  // cos of the double nearest pi/2 is 6e-17
}

TEST(Wgs84Plan, ChoosesDf64ForTheGeodesyAndFloatForTheRest) {
  const std::string plan = read_file(plan_file());
  // The trigonometry and N stay df64 (no entry: the plan's default), the normal is computed in
  // float, and the eye-relative offset is stored as float after the df64 subtraction.
  EXPECT_NE(plan.find("\"mode\": \"df64\""), std::string::npos) << plan;
  EXPECT_NE(plan.find("\"up_vector\": \"fp32\""), std::string::npos) << plan;
  EXPECT_NE(plan.find("\"main.rel\": \"fp32\""), std::string::npos) << plan;
  EXPECT_EQ(plan.find("geodetic_to_ecef"), std::string::npos) << plan;
  EXPECT_EQ(plan.find("main.p"), std::string::npos) << plan;
}

class Wgs84 : public ::testing::TestWithParam<Backend> {};

TEST_P(Wgs84, PlanKeepsOneMillimetreAndFp32DoesNot) {
  ASSERT_EQ(doublet::runner::backend_unavailable_reason(GetParam()), "");
  const wgs84::Errors plan = measure(GetParam(), planned());
  ASSERT_EQ(plan.error, "");
  EXPECT_EQ(plan.not_finite, 0);
  EXPECT_LE(plan.rel_max, kRelPromise) << plan.worst;
  EXPECT_LE(plan.up_max, kUpPromise);

  doublet::Options fp32;
  fp32.target = doublet::Target::Es300;
  fp32.mode = doublet::Mode::Fp32;
  const wgs84::Errors f = measure(GetParam(), fp32);
  ASSERT_EQ(f.error, "");
  EXPECT_GT(f.rel_max, kRelPromise) << "fp32 kept the promise: the scene does not need doublet";
}

// Each value the plan keeps in df64, demoted on top of the plan: the promise breaks.
TEST_P(Wgs84, DowngradingTheTrigonometryOrTheEcefPositionBreaksThePromise) {
  using doublet::Mode;
  const std::vector<std::pair<std::string, Mode>> downgrades{
      {"geodetic_to_ecef", Mode::Fp32},     // the whole formula in float
      {"geodetic_to_ecef.s", Mode::Fp32},   // sin(lat) stored as float
      {"geodetic_to_ecef.n", Mode::Fp32},   // N stored as float
      {"main.p", Mode::Fp32},               // the ECEF position stored as float before the subtraction
  };
  for (const auto& d : downgrades) {
    std::printf("%s=%s\n", d.first.c_str(), std::string(doublet::to_string(d.second)).c_str());
    const wgs84::Errors e = measure(GetParam(), planned({d}));
    ASSERT_EQ(e.error, "") << d.first;
    EXPECT_GT(e.rel_max, kRelPromise) << d.first << " downgraded still kept 1 mm";
  }
}

// Sabotage: the plan's float-float code without the optimizer guard (Mesa then deletes the
// error terms, docs/accuracy.md).
TEST_P(Wgs84, WithoutTheGuardThePlanMissesThePromise) {
  doublet::Options o = planned();
  o.guard = doublet::GuardKind::None;
  const wgs84::Errors e = measure(GetParam(), o);
  ASSERT_EQ(e.error, "");
  EXPECT_GT(e.rel_max, kRelPromise);
}

// Mode exact (binary64 in integer arithmetic; its transcendentals bridge through float-float):
// the whole shader, no plan.
TEST_P(Wgs84, ExactKeepsOneMillimetre) {
  doublet::Options o;
  o.target = doublet::Target::Es300;
  o.mode = doublet::Mode::Exact;
  const wgs84::Errors e = measure(GetParam(), o);
  ASSERT_EQ(e.error, "");
  EXPECT_EQ(e.not_finite, 0);
  EXPECT_LE(e.rel_max, kRelPromise) << e.worst;
}

// Sabotage: exact's transcendentals see the angles as float only — the binary64 -> float-float
// bridge keeps the high word and drops the residual correction (mode exact's own sabotages,
// tests/exact/exact_transcendental_test.cpp). Both edits must apply. One driver: compiling the
// edited exact shader takes llvmpipe about 40 s.
TEST(Wgs84Exact, WithoutItsBridgesLowPartsMissesThePromise) {
  doublet::Options o;
  o.target = doublet::Target::Es300;
  o.mode = doublet::Mode::Exact;
  doublet::Result lowered = wgs84::lower_example("wgs84_ecef.vert", o);
  ASSERT_TRUE(lowered.ok);
  const std::pair<std::string, std::string> edits[] = {
      {"return ff_double(uintBitsToFloat(h), uintBitsToFloat(ex_to_float_bits(rest)));",
       "return ff_double(uintBitsToFloat(h), 0.0);"},
      {"  return uintBitsToFloat(ex_to_float_bits(rest));\n}", "  return 0.0;\n}"}};
  for (const auto& [from, to] : edits) {
    const size_t at = lowered.output.find(from);
    ASSERT_NE(at, std::string::npos) << "the sabotage does not apply: " << from;
    lowered.output.replace(at, from.size(), to);
  }
  const wgs84::Errors e = wgs84::measure_vertex(Backend::Gles, lowered.output, views());
  ASSERT_EQ(e.error, "");
  std::printf("  low word and residual dropped: v_rel max %.3g m\n", e.rel_max);
  EXPECT_GT(e.rel_max, kRelPromise);
}

INSTANTIATE_TEST_SUITE_P(Drivers, Wgs84, ::testing::Values(Backend::Vulkan, Backend::Gles),
                         [](const auto& info) { return std::string(doublet::runner::backend_name(info.param)); });

}  // namespace

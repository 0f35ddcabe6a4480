// The plan's model of the transcendental built-ins (src/plan/transcendentals.hpp) and relations on
// computed values. Expected numbers are derived by hand next to each check (where sin and cos
// peak, derivatives, the documented bounds), never taken from a run.
#include <gtest/gtest.h>

#include <cmath>

#include "plan/planner.hpp"
#include "plan/transcendentals.hpp"

namespace {

using namespace doublet;
using namespace doublet::plan;

constexpr double kPi = 3.14159265358979323846;
constexpr double kU2 = 0x1p-48;

PlanOutcome run(const std::string& shader, const std::string& scene_json) {
  Scene scene;
  Diagnostic d;
  EXPECT_TRUE(parse_scene(scene_json, "scene.json", &scene, &d)) << format_diagnostic(d);
  Options o;
  o.stage = Stage::Vertex;
  o.file_name = "test.vert";
  return make_plan(shader, o, scene);
}

std::string mode_for(const PlanOutcome& p, const std::string& name) {
  for (const auto& [n, m] : p.mode_for)
    if (n == name) return std::string(to_string(m));
  return "(none)";
}

TEST(PlanTranscendentals, RangesFollowCrestsPolesAndBranchCuts) {
  // sin on [0.5, 2]: the crest pi/2 lies inside (max 1); the smaller end value is sin 0.5.
  EXPECT_EQ(transcendental_range("sin", 1, {0.5, 2}, {}), (Interval{std::sin(0.5), 1}));
  // cos on [-0.3, 0.2]: crest at 0; the farther end from 0 is -0.3.
  EXPECT_EQ(transcendental_range("cos", 1, {-0.3, 0.2}, {}), (Interval{std::cos(0.3), 1}));
  // Wider than a period: the whole [-1, 1].
  EXPECT_EQ(transcendental_range("sin", 1, {-4, 4}, {}), (Interval{-1, 1}));
  // tan: the pole pi/2 in [1, 2] makes it unbounded; [-1, 1] has none.
  EXPECT_FALSE(transcendental_range("tan", 1, {1, 2}, {}).bounded());
  EXPECT_EQ(transcendental_range("tan", 1, {-1, 1}, {}), (Interval{std::tan(-1.0), std::tan(1.0)}));
  // atan(y, x) over y in [1, 2], x in [-1, 1]: upper half-plane, extremes at the corners (1, 1)
  // -> pi/4 and (-1, 1) -> 3pi/4. Touching the cut (x < 0, y = 0): the whole [-pi, pi].
  const Interval a = transcendental_range("atan", 2, {1, 2}, {-1, 1});
  EXPECT_DOUBLE_EQ(a.lo, kPi / 4);
  EXPECT_DOUBLE_EQ(a.hi, 3 * kPi / 4);
  EXPECT_EQ(transcendental_range("atan", 2, {-1, 1}, {-2, -1}), (Interval{-kPi, kPi}));
  // log reaches -inf at 0; pow(x, y) = exp(y log x) on x in [2, 4], y in [1, 2]: [2, 16].
  EXPECT_EQ(transcendental_range("log", 1, {0, 1}, {}).lo, -kInf);
  const Interval p = transcendental_range("pow", 2, {2, 4}, {1, 2});
  EXPECT_DOUBLE_EQ(p.lo, 2);
  EXPECT_DOUBLE_EQ(p.hi, 16);
}

TEST(PlanTranscendentals, SlopesAreTheLargestDerivative) {
  // d sin = cos, largest |cos| on [0.5, 2] at 0.5 (|cos 2| = 0.42 is smaller).
  EXPECT_DOUBLE_EQ(transcendental_slope("sin", 1, 0, {0.5, 2}, {}), std::cos(0.5));
  EXPECT_DOUBLE_EQ(transcendental_slope("log", 1, 0, {2, 8}, {}), 0.5);                // 1/x at 2
  EXPECT_DOUBLE_EQ(transcendental_slope("exp", 1, 0, {0, 1}, {}), std::exp(1.0));      // e^x at 1
  EXPECT_DOUBLE_EQ(transcendental_slope("asin", 1, 0, {-0.6, 0.6}, {}), 1.25);         // 1/sqrt(1 - 0.36)
  // atan(y, x): both partials <= 1/r, r >= hypot(3, 4) = 5 on y in [3, 4], x in [4, 5].
  EXPECT_DOUBLE_EQ(transcendental_slope("atan", 2, 1, {3, 4}, {4, 5}), 0.2);
  EXPECT_EQ(transcendental_slope("log", 1, 0, {0, 1}, {}), kInf);
}

TEST(PlanTranscendentals, ErrorBoundsPerPrecision) {
  const Interval sin1{-std::sin(1.0), std::sin(1.0)};
  // df64: 20u^2 relative + |x| 2^-96 (docs/transcendentals.md), |x| <= 1.
  EXPECT_DOUBLE_EQ(transcendental_error_df64("sin", 1, {-1, 1}, {}, sin1), 20 * kU2 * std::sin(1.0) + 0x1p-96);
  // exp: 10u^2 on [-70.7, 88.72]; beyond, no bound (float range ends).
  EXPECT_DOUBLE_EQ(transcendental_error_df64("exp", 1, {0, 1}, {}, {1, std::exp(1.0)}), 10 * kU2 * std::exp(1.0));
  EXPECT_EQ(transcendental_error_df64("exp", 1, {0, 100}, {}, {1, std::exp(100.0)}), kInf);
  // Float built-ins: sin 2^-11 absolute on [-pi, pi] only.
  EXPECT_EQ(transcendental_error_float("sin", 1, {-1, 1}, {}, sin1), 0x1p-11);
  EXPECT_EQ(transcendental_error_float("sin", 1, {0, 4}, {}, {-1, 1}), kInf);
  // exp on [0, 2]: (3 + 2*2) ulp of e^2 = 7.39, whose ulp is 2^(2-23).
  EXPECT_EQ(transcendental_error_float("exp", 1, {0, 2}, {}, {1, std::exp(2.0)}), 7 * 0x1p-21);
  // log on [1, 1.5], inside [0.5, 2]: 2^-21 absolute.
  EXPECT_EQ(transcendental_error_float("log", 1, {1, 1.5}, {}, {0, std::log(1.5)}), 0x1p-21);
}

const char* kSine = R"(#version 450
uniform double x;
out double r;
void main() { r = sin(x); }
)";

TEST(PlanTranscendentals, FloatSineWhereTheOutputToleratesItsAllowance) {
  // x in [0, 1]. In float: sin's 2^-11 plus x read as float (half an ulp of 1, 2^-24, times
  // slope cos 0 = 1): 4.8834e-4 <= half of 1e-3, so main runs in fp32.
  PlanOutcome p = run(kSine, R"({"inputs": {"x": {"min": 0, "max": 1}}, "outputs": {"r": {"abs_error": 1e-3}}})");
  ASSERT_TRUE(p.ok);
  EXPECT_TRUE(p.feasible);
  EXPECT_EQ(mode_for(p, "main"), "fp32");
  ASSERT_EQ(p.outputs.size(), 1u);
  EXPECT_NEAR(p.outputs[0].estimate, 0x1p-11 + 0x1p-24, 1e-12);
  // 1e-4 is below the float allowance: the sine keeps float-float arithmetic (df64-fast has the
  // same transcendental rules and nothing to cancel here).
  p = run(kSine, R"({"inputs": {"x": {"min": 0, "max": 1}}, "outputs": {"r": {"abs_error": 1e-4}}})");
  ASSERT_TRUE(p.ok);
  EXPECT_TRUE(p.feasible);
  EXPECT_EQ(mode_for(p, "main"), "df64-fast");
  EXPECT_LT(p.outputs[0].estimate, 1e-12);
}

TEST(PlanTranscendentals, OutsideTheDocumentedRangeNothingCanBePromised) {
  const PlanOutcome p = run(R"(#version 450
uniform double x;
out double r;
void main() { r = exp(x); }
)", R"({"inputs": {"x": {"min": 0, "max": 100}}, "outputs": {"r": {"abs_error": 1e30}}})");
  ASSERT_TRUE(p.ok);
  EXPECT_FALSE(p.feasible);  // exp(100) leaves float-float's range (88.72)
}

const char* kComputed = R"(#version 450
uniform double a;
uniform double b;
out float r;
void main() {
  double p = a * 3.0lf;
  double d = p - b;
  r = float(d);
}
)";

TEST(PlanRelations, AComputedValueMayBeRelatedToAnInput) {
  // a in [1e6, 2e6] -> p in [3e6, 6e6]; b in [3e6, 6e6]: without a relation d is in [-3e6, 3e6].
  const std::string inputs = R"("inputs": {"a": {"min": 1e6, "max": 2e6}, "b": {"min": 3e6, "max": 6e6}})";
  PlanOutcome p = run(kComputed, "{" + inputs + R"(, "outputs": {"r": {"abs_error": 1e-3}}})");
  ASSERT_TRUE(p.ok);
  auto range_of = [](const PlanOutcome& o, const std::string& n) {
    for (const PlanRow& r : o.rows)
      if (r.name == n) return r.range;
    return Interval::top();
  };
  EXPECT_EQ(range_of(p, "main.d"), (Interval{-3e6, 3e6}));
  // The scene says p is within 2 of b: d in [-2, 2].
  p = run(kComputed, "{" + inputs + R"(, "relations": [{"difference": ["main.p", "b"], "abs_max": 2}],
          "outputs": {"r": {"abs_error": 1e-3}}})");
  ASSERT_TRUE(p.ok);
  EXPECT_EQ(range_of(p, "main.d"), (Interval{-2, 2}));
}

TEST(PlanRelations, AComputedValueTheShaderLacksIsAnError) {
  const PlanOutcome p = run(kComputed, R"({"inputs": {"a": {"min": 1, "max": 2}, "b": {"min": 3, "max": 6}},
      "relations": [{"difference": ["main.q", "b"], "abs_max": 2}], "outputs": {"r": {"abs_error": 1e-3}}})");
  EXPECT_FALSE(p.ok);
  ASSERT_FALSE(p.diagnostics.empty());
  EXPECT_NE(p.diagnostics[0].message.find("'main.q'"), std::string::npos) << p.diagnostics[0].message;
  EXPECT_EQ(p.diagnostics[0].line, 2);  // at the relation's difference
}

TEST(PlanRelations, OnlyInputsAndFunctionDotLocalNames) {
  Scene scene;
  Diagnostic d;
  EXPECT_FALSE(parse_scene(R"({"inputs": {"b": {"abs_max": 1}}, "relations": [{"difference": ["a.b.c", "b"], "abs_max": 1}],
      "outputs": {"r": {"abs_error": 1}}})", "s.json", &scene, &d));
  EXPECT_NE(d.message.find("'a.b.c' is not among the scene's inputs"), std::string::npos) << d.message;
  EXPECT_TRUE(parse_scene(R"({"inputs": {"b": {"abs_max": 1}}, "relations": [{"difference": ["main.p", "b"], "abs_max": 1}],
      "outputs": {"r": {"abs_error": 1}}})", "s.json", &scene, &d)) << d.message;
}

}  // namespace

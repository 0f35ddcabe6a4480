// The range and error analysis on small shaders. Every expected number is derived by hand in the
// comment next to it (interval arithmetic, derivatives, float spacing), never taken from a run.
#include <gtest/gtest.h>

#include <cmath>

#include "plan/planner.hpp"

namespace {

using namespace doublet;
using namespace doublet::plan;

PlanOutcome run(const std::string& shader, const std::string& scene_json, Stage stage = Stage::Vertex) {
  Scene scene;
  Diagnostic d;
  EXPECT_TRUE(parse_scene(scene_json, "scene.json", &scene, &d)) << format_diagnostic(d);
  Options o;
  o.stage = stage;
  o.file_name = "test.vert";
  return make_plan(shader, o, scene);
}

const PlanRow& row(const PlanOutcome& p, const std::string& name) {
  for (const PlanRow& r : p.rows)
    if (r.name == name) return r;
  ADD_FAILURE() << "no row " << name;
  static PlanRow none;
  return none;
}

std::string mode_for(const PlanOutcome& p, const std::string& name) {
  for (const auto& [n, m] : p.mode_for)
    if (n == name) return std::string(to_string(m));
  return "(none)";
}

TEST(PlanAnalysis, ProductRangeAndBudgets) {
  const PlanOutcome p = run(R"(#version 450
uniform double x;
uniform double y;
out double r;
void main() { double z = x * y; r = z; }
)", R"({"inputs": {"x": {"min": 1, "max": 2}, "y": {"min": -3, "max": 4}},
        "outputs": {"r": {"abs_error": 1e-3}}})");
  ASSERT_TRUE(p.ok);
  // [1,2] * [-3,4]: endpoint products -3, 4, -6, 8 -> [-6, 8].
  EXPECT_EQ(row(p, "main.z").range.lo, -6);
  EXPECT_EQ(row(p, "main.z").range.hi, 8);
  // r = x*y: dr/dx = y, |y| <= 4 -> budget 1e-3 / 4; dr/dy = x, |x| <= 2 -> 1e-3 / 2.
  EXPECT_DOUBLE_EQ(row(p, "x").budget, 2.5e-4);
  EXPECT_DOUBLE_EQ(row(p, "y").budget, 5e-4);
  // z needs log2(8 / 1e-3) + 1 margin bit = 13.97 bits: float (24) is ample, so main runs in fp32.
  EXPECT_NEAR(row(p, "main.z").bits, std::log2(8 / 1e-3) + 1, 1e-9);
  EXPECT_EQ(mode_for(p, "main"), "fp32");
  EXPECT_TRUE(p.feasible);
}

TEST(PlanAnalysis, QuotientAndSquareRootSensitivities) {
  const PlanOutcome p = run(R"(#version 450
uniform double x;
uniform double y;
out double q;
out double s;
void main() { q = x / y; s = sqrt(y); }
)", R"({"inputs": {"x": {"min": 1, "max": 2}, "y": {"min": 4, "max": 8}},
        "outputs": {"q": {"abs_error": 1e-3}, "s": {"abs_error": 1e-3}}})");
  ASSERT_TRUE(p.ok);
  // [1,2] / [4,8] = [1/8, 1/2]; sqrt([4,8]) = [2, 2.83].
  EXPECT_DOUBLE_EQ(row(p, "q").range.lo, 0.125);
  EXPECT_DOUBLE_EQ(row(p, "q").range.hi, 0.5);
  EXPECT_DOUBLE_EQ(row(p, "s").range.lo, 2);
  EXPECT_DOUBLE_EQ(row(p, "s").range.hi, std::sqrt(8.0));
  // dq/dx = 1/y <= 1/4 -> budget(x) = 4e-3.
  EXPECT_DOUBLE_EQ(row(p, "x").budget, 4e-3);
  // dq/dy = x/y^2 <= 2/16 -> 8e-3; ds/dy = 1/(2 sqrt y) <= 1/4 -> 4e-3; the tighter one wins.
  EXPECT_DOUBLE_EQ(row(p, "y").budget, 4e-3);
}

TEST(PlanAnalysis, RelationBoundsTheDifferenceAndPicksRte) {
  const std::string shader = R"(#version 450
uniform dvec3 a;
uniform dvec3 b;
out dvec3 d;
void main() { dvec3 t = a - b; d = t; }
)";
  const PlanOutcome related = run(shader, R"({"inputs": {"a": {"abs_max": 1e6}, "b": {"abs_max": 1e6}},
      "relations": [{"difference": ["a", "b"], "abs_max": 10}], "outputs": {"d": {"abs_error": 1e-3}}})");
  ASSERT_TRUE(related.ok);
  EXPECT_EQ(row(related, "main.t").range.lo, -10);
  EXPECT_EQ(row(related, "main.t").range.hi, 10);
  // Float reads of a and b round by half an ulp at 1e6 (2^(19-24) = 0.03 m): fp32 fails. rte
  // subtracts the split values exactly and rounds |t| <= 10 once (2^(3-24) = 4.8e-7): it fits.
  EXPECT_EQ(mode_for(related, "main"), "rte");

  const PlanOutcome unrelated = run(shader, R"({"inputs": {"a": {"abs_max": 1e6}, "b": {"abs_max": 1e6}},
      "outputs": {"d": {"abs_error": 1e-3}}})");
  ASSERT_TRUE(unrelated.ok);
  EXPECT_EQ(row(unrelated, "main.t").range.lo, -2e6);  // [-1e6, 1e6] - [-1e6, 1e6]
  EXPECT_EQ(row(unrelated, "main.t").range.hi, 2e6);
  // |t| up to 2e6: float's half ulp there is 2^(20-24) = 0.06 > 1e-3: t stays df64.
  EXPECT_EQ(mode_for(unrelated, "main"), "(none)");
  EXPECT_EQ(mode_for(unrelated, "main.t"), "(none)");
}

TEST(PlanAnalysis, MatrixTimesVector) {
  const PlanOutcome p = run(R"(#version 450
uniform dmat2 m;
uniform dvec2 v;
out dvec2 r;
void main() { r = m * v; }
)", R"({"inputs": {"m": {"abs_max": 1}, "v": {"min": 0, "max": 3}}, "outputs": {"r": {"abs_error": 1e-3}}})");
  ASSERT_TRUE(p.ok);
  // r_i = m_i0 v_0 + m_i1 v_1, each term in [-1,1] * [0,3] = [-3, 3]: r_i in [-6, 6].
  EXPECT_EQ(row(p, "r").range.lo, -6);
  EXPECT_EQ(row(p, "r").range.hi, 6);
  // dr_i/dv_j = m_ij: a v error in every component moves r_i by up to |m_i0| + |m_i1| = 2.
  EXPECT_DOUBLE_EQ(row(p, "v").budget, 5e-4);
}

TEST(PlanAnalysis, CalleeAnalysedWithTheArgumentInterval) {
  const PlanOutcome p = run(R"(#version 450
double sq(double a) { return a * a; }
uniform double x;
out double r;
void main() { r = sq(x); }
)", R"({"inputs": {"x": {"min": -3, "max": 2}}, "outputs": {"r": {"abs_error": 1e-3}}})");
  ASSERT_TRUE(p.ok);
  // Interval product without dependency tracking: [-3,2] * [-3,2] -> products 9, -6, -6, 4.
  EXPECT_EQ(row(p, "r").range.lo, -6);
  EXPECT_EQ(row(p, "r").range.hi, 9);
  EXPECT_EQ(row(p, "sq.a").range.lo, -3);
  EXPECT_EQ(row(p, "sq.a").range.hi, 2);
}

TEST(PlanAnalysis, LoopWidensToInfinityAndKeepsDf64) {
  const PlanOutcome p = run(R"(#version 450
uniform double x;
uniform int n;
out double r;
void main() {
  double s = 0.0lf;
  for (int i = 0; i < n; ++i) s += x;
  r = s;
}
)", R"({"inputs": {"x": {"min": 1, "max": 2}}, "outputs": {"r": {"abs_error": 1e-3}}})");
  ASSERT_TRUE(p.ok);
  // s grows by [1,2] every trip and the trip count is unknown: [0, +inf].
  EXPECT_EQ(row(p, "main.s").range.lo, 0);
  EXPECT_TRUE(std::isinf(row(p, "main.s").range.hi));
  EXPECT_FALSE(p.feasible);  // no bound can be proven
  EXPECT_TRUE(p.mode_for.empty());
  EXPECT_EQ(row(p, "main.s").mode, Mode::Df64);
}

// The acceptance arithmetic (docs/plan.md): float's half spacing at |rel| <= 1e4 is
// 2^(13-24) = 4.9e-4 m, within half of the 1 mm slack; at 1e5 it is 2^(16-24) = 3.9e-3 m, not.
TEST(PlanAnalysis, GlobeDemotesRelOnlyWhenFloatSpacingAllowsIt) {
  const std::string shader = R"(#version 300 es
layout(location = 0) in dvec3 position;
uniform dvec3 eye;
flat out dvec3 v_rel;
void main() { dvec3 rel = position - eye; v_rel = rel; gl_Position = vec4(vec3(rel), 1.0); }
)";
  auto scene = [](const char* within, const char* abs_error) {
    return std::string(R"({"inputs": {"position": {"abs_max": 6.4e6}, "eye": {"abs_max": 6.4e6}},
        "relations": [{"difference": ["position", "eye"], "abs_max": )") + within +
           R"(}], "outputs": {"v_rel": {"abs_error": )" + abs_error + "}}}";
  };
  const PlanOutcome near = run(shader, scene("1e4", "1e-3"));
  ASSERT_TRUE(near.ok);
  EXPECT_EQ(mode_for(near, "main.rel"), "fp32");
  const PlanOutcome far = run(shader, scene("1e5", "1e-3"));
  EXPECT_EQ(mode_for(far, "main.rel"), "(none)");
  EXPECT_EQ(row(far, "main.rel").mode, Mode::Df64);
  const PlanOutcome far_cm = run(shader, scene("1e5", "1e-2"));  // 3.9e-3 <= 1e-2 / 2
  EXPECT_NE(mode_for(far_cm, "main.rel"), "(none)");
}

TEST(PlanAnalysis, UnknownSceneNamesAreErrorsAtTheirPlace) {
  const PlanOutcome p = run(R"(#version 450
uniform double x;
out double r;
void main() { r = x; }
)", "{\"inputs\": {\"x\": {\"abs_max\": 1}, \"nope\": {\"abs_max\": 1}},\n \"outputs\": {\"r\": {\"abs_error\": 1}}}");
  EXPECT_FALSE(p.ok);
  ASSERT_FALSE(p.diagnostics.empty());
  EXPECT_EQ(p.diagnostics[0].line, 1);
  EXPECT_EQ(p.diagnostics[0].column, 42);  // the value of "nope"
  EXPECT_NE(p.diagnostics[0].message.find("'nope'"), std::string::npos);
}

// The same overflow inside a function that main calls: df64 with that function exact
// (docs/modes.md, "Exact functions") keeps the promise, so the plan stays df64 elsewhere; the
// function's result comes back as its nearest float-float pair, which the estimate counts.
TEST(PlanAnalysis, AFunctionBeyondFloatRangeAloneBecomesExact) {
  const std::string shader = R"(#version 450
uniform double a;
uniform double b;
out double r;
double scaled(double x, double y) { double p = x * y; return p * 1e-40; }
void main() { r = scaled(a, b) + 1.0lf; }
)";
  const std::string scene = R"({"inputs": {"a": {"min": 1e20, "max": 1e25}, "b": {"min": 1e20, "max": 1e25}},
        "outputs": {"r": {"abs_error": 1e-3}}})";
  const PlanOutcome p = run(shader, scene);
  ASSERT_TRUE(p.ok);
  EXPECT_TRUE(std::isinf(p.outputs[0].estimate_df64));
  EXPECT_TRUE(p.feasible);
  EXPECT_EQ(p.mode, Mode::Df64);
  ASSERT_EQ(p.mode_for.size(), 1u);
  EXPECT_EQ(p.mode_for[0].first, "scaled");
  EXPECT_EQ(p.mode_for[0].second, Mode::Exact);
  // r <= 1e10 + 1 comes back as a float-float pair: its representation error, 2^-48 relative, is
  // in the estimate (about 3.6e-5), above binary64's own roundings (about 2e-6).
  EXPECT_GT(p.outputs[0].estimate, 1e-5);
  EXPECT_LT(p.outputs[0].estimate, 1e-3);
}

// Values beyond float's range (3.4e38): float-float overflows there, so its estimate is infinite
// (before, df64 was estimated at 2^-44 relative and chosen: inf at run time), and the plan is mode
// exact where the target has 32-bit integers.
TEST(PlanAnalysis, ValuesBeyondFloatRangeChooseExact) {
  const std::string shader = R"(#version 450
uniform double a;
uniform double b;
out double r;
void main() { double p = a * b; r = p * 1e-40; }
)";
  const std::string scene = R"({"inputs": {"a": {"min": 1e20, "max": 1e25}, "b": {"min": 1e20, "max": 1e25}},
        "outputs": {"r": {"abs_error": 1e-3}}})";
  const PlanOutcome p = run(shader, scene);
  ASSERT_TRUE(p.ok);
  ASSERT_EQ(p.outputs.size(), 1u);
  EXPECT_TRUE(std::isinf(p.outputs[0].estimate_df64));
  EXPECT_TRUE(std::isinf(p.outputs[0].estimate_fp32));
  // p = a*b <= 1e50 rounds by half an ulp of binary64 there, 2^(166-53), weighted by 1e-40; r <= 1e10
  // rounds by 2^(33-53); 1e-40 is exact in binary64: 1.04e-6 + 9.5e-7.
  EXPECT_NEAR(p.outputs[0].estimate_exact, std::ldexp(1.0, 113) * 1e-40 + std::ldexp(1.0, -20), 1e-9);
  EXPECT_TRUE(p.feasible);
  EXPECT_EQ(p.mode, Mode::Exact);
  EXPECT_TRUE(p.mode_for.empty());
  EXPECT_EQ(row(p, "main.p").mode, Mode::Exact);
  // ES 1.00 has no 32-bit integers: no exact; the plan stays df64 and says why.
  Scene s;
  Diagnostic d;
  ASSERT_TRUE(parse_scene(scene, "scene.json", &s, &d));
  Options o;
  o.stage = Stage::Vertex;
  o.target = Target::Es100;
  const PlanOutcome es100 = make_plan(shader, o, s);
  EXPECT_FALSE(es100.feasible);
  EXPECT_EQ(es100.mode, Mode::Df64);
  bool said = false;
  for (const std::string& n : es100.notes) said |= n.find("es100") != std::string::npos;
  EXPECT_TRUE(said);
}

// glslang spells `v.x` as an index into the vector: the component's own range, not the hull of
// the vector (a buffer's dvec2 of distance and mass kept them apart only after this).
TEST(PlanAnalysis, VectorComponentOfABufferElementKeepsItsRange) {
  const PlanOutcome p = run(R"(#version 450
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer In { dvec2 body[]; };
layout(std430, binding = 1) writeonly buffer Out { double r[]; };
void main() { uint i = gl_GlobalInvocationID.x; double x = body[i].x; double y = body[i].y; r[i] = x + y; }
)", R"({"inputs": {"body": {"min": [1, 100], "max": [2, 200]}}, "outputs": {"r": {"abs_error": 1e-3}}})",
                            Stage::Compute);
  ASSERT_TRUE(p.ok);
  EXPECT_EQ(row(p, "main.x").range.lo, 1);
  EXPECT_EQ(row(p, "main.x").range.hi, 2);
  EXPECT_EQ(row(p, "main.y").range.lo, 100);
  EXPECT_EQ(row(p, "main.y").range.hi, 200);
  EXPECT_EQ(row(p, "r").kind, "output");  // a writeonly block's member: no "no range" note
  for (const PlanRow& r : p.rows) EXPECT_EQ(r.name.find("anon@"), std::string::npos) << r.name;
  for (const std::string& n : p.notes) EXPECT_EQ(n.find("'r' has no range"), std::string::npos) << n;
}

// A buffer of structs ranged member by member, as verify names the members (`sats.pos`): the
// struct's one hull is the join of the members' ranges ([1, 2] and [-5, 3] -> [-5, 3]); a member
// left out, or one the struct lacks, is an error naming it.
TEST(PlanAnalysis, StructMembersRangedOneByOneJoinIntoTheStructsHull) {
  const std::string shader = R"(#version 450
layout(local_size_x = 64) in;
struct Sat { dvec2 pos; double t0; };
layout(std430, binding = 0) readonly buffer In { Sat sats[]; };
layout(std430, binding = 1) writeonly buffer Out { double r[]; };
void main() { uint i = gl_GlobalInvocationID.x; double x = sats[i].pos.x; r[i] = x + sats[i].t0; }
)";
  const PlanOutcome p = run(shader, R"({"inputs": {"sats.pos": {"min": 1, "max": 2}, "sats.t0": {"min": -5, "max": 3}},
      "outputs": {"r": {"abs_error": 1e-3}}})", Stage::Compute);
  ASSERT_TRUE(p.ok);
  EXPECT_EQ(row(p, "main.x").range.lo, -5);
  EXPECT_EQ(row(p, "main.x").range.hi, 3);
  const PlanOutcome missing = run(shader, R"({"inputs": {"sats.pos": {"min": 1, "max": 2}}, "outputs": {"r": {"abs_error": 1e-3}}})",
                                  Stage::Compute);
  EXPECT_FALSE(missing.ok);
  ASSERT_FALSE(missing.diagnostics.empty());
  EXPECT_NE(missing.diagnostics[0].message.find("without sats.t0"), std::string::npos) << missing.diagnostics[0].message;
  const PlanOutcome unknown = run(shader, R"({"inputs": {"sats": {"min": 1, "max": 2}, "sats.vel": {"min": 1, "max": 2}},
      "outputs": {"r": {"abs_error": 1e-3}}})", Stage::Compute);
  EXPECT_FALSE(unknown.ok);
  ASSERT_FALSE(unknown.diagnostics.empty());
  EXPECT_NE(unknown.diagnostics[0].message.find("has no member 'vel'"), std::string::npos) << unknown.diagnostics[0].message;
}

}  // namespace

// The differential tester's oracles on lavapipe and Mesa GLES (src/difftest/oracles.hpp): they hold
// on generated programs, and each one reports a finding when a bug is put back on purpose — the
// lowering's low words dropped (verify's drop-lo sabotage on the exact, df64-int and bound runs), or a pass
// left out of the pipeline.
#include <gtest/gtest.h>

#include <string>

#include "difftest/generator.hpp"
#include "difftest/oracles.hpp"
#include "../runner/browser_test_util.hpp"

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

// The first compute program (from seed 1) that has `feature` and none of the built-ins native
// rounds badly.
Program first_with(const std::string& feature) {
  for (uint64_t seed = 1;; ++seed) {
    Program p = generate(seed);
    if (p.stage == "comp" && p.features.count(feature) && !uses_native_non_ieee(p)) return p;
  }
}

// In a child process, as scripts/fuzz --diff runs it; a program the drivers do not finish is a failure.
CheckResult run(const Program& p, const CheckOptions& o) {
  bool timed_out = false;
  CheckResult r = check_in_child(p.glsl, p.spec_json, p.stage, o, 300, &timed_out);
  EXPECT_FALSE(timed_out) << "seed " << p.seed << ": no result within 300 s";
  return r;
}

CheckOptions quick() {
  CheckOptions o;
  o.samples = 64;
  return o;
}

TEST(DiffOracles, HoldOnAGeneratedProgram) {
  const Program p = first_with("stmt:for");
  const CheckResult r = run(p, quick());
  EXPECT_TRUE(r.invalid.empty()) << r.invalid;
  EXPECT_TRUE(r.findings.empty()) << "seed " << p.seed << describe(r);
  EXPECT_EQ(r.checked, (std::vector<std::string>{"exact", "int", "targets"}));
}

TEST(DiffOracles, DroppedLowWordsAreFoundByTheExactAndIntOracles) {
  // A program in the generator's form, small enough that verify's drop-lo (a text demotion of
  // every double) applies to all of it.
  Program p;
  p.glsl = R"(#version 450
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer In0 { dvec2 in0[]; };
layout(std430, binding = 1) readonly buffer In1 { double in1[]; };
layout(std430, binding = 2) writeonly buffer Out0 { dvec2 r0[]; };
void main() {
  uint gid = gl_GlobalInvocationID.x;
  dvec2 x0 = in0[gid];
  double x1 = in1[gid];
  for (int k0 = 0; k0 < 3; ++k0) {
    x0 = x0 * x1 + dvec2(0.1lf, 0.3lf);
  }
  r0[gid] = x0 / (1.5lf + abs(x0.yx));
}
)";
  p.spec_json = R"({ "inputs": { "in0": { "range": [-3, 3] }, "in1": { "range": [0.25, 4] } } })";
  EXPECT_TRUE(run(p, quick()).findings.empty());
  CheckOptions o = quick();
  o.sabotage = "drop-lo";
  const CheckResult r = run(p, o);
  EXPECT_TRUE(has_finding(r, "exact")) << describe(r);
  EXPECT_TRUE(has_finding(r, "int")) << describe(r);
}

// Tessellation programs in the generator's form (one geometry seed in four each makes a control or
// an evaluation shader): the oracles hold on lavapipe (docs/verify.md), and drop-lo is found.
TEST(DiffOracles, TessellationProgramsHoldAndDroppedLowWordsAreFound) {
  const std::string body = R"(  for (int k0 = 0; k0 < 3; ++k0) {
    x0 = x0 * x1 + dvec2(0.1lf, 0.3lf);
  }
)";
  Program control;
  control.stage = "tesc";
  control.glsl = "#version 450\nlayout(vertices = 1) out;\nin dvec2 in0[];\nin double in1[];\nout dvec2 r0[];\n"
                 "void main() {\n  dvec2 x0 = in0[0];\n  double x1 = in1[0];\n" + body +
                 "  r0[gl_InvocationID] = x0 / (1.5lf + abs(x0.yx));\n}\n";
  control.spec_json = R"({ "inputs": { "in0[0]": { "range": [-3, 3] }, "in1[0]": { "range": [0.25, 4] } } })";
  Program evaluation;
  evaluation.stage = "tese";
  evaluation.glsl = "#version 450\nlayout(triangles, equal_spacing, ccw) in;\nin dvec2 in0[];\nin double in1[];\nout dvec2 r0;\n"
                    "void main() {\n  gl_Position = vec4(0.0, 0.0, 0.0, 1.0);\n  dvec3 tc = dvec3(gl_TessCoord);\n"
                    "  dvec2 x0 = in0[0] * tc.x + in0[1] * tc.y + in0[2] * tc.z;\n"
                    "  double x1 = in1[0] * tc.x + in1[1] * tc.y + in1[2] * tc.z;\n" + body +
                    "  r0 = x0 / (1.5lf + abs(x0.yx));\n}\n";
  evaluation.spec_json = R"({ "inputs": { "in0[0]": { "range": [-3, 3] }, "in0[1]": { "range": [-3, 3] },
    "in0[2]": { "range": [-3, 3] }, "in1[0]": { "range": [0.25, 4] }, "in1[1]": { "range": [0.25, 4] },
    "in1[2]": { "range": [0.25, 4] } } })";
  for (const Program& p : {control, evaluation}) {
    const CheckResult r = run(p, quick());
    EXPECT_TRUE(r.invalid.empty()) << p.stage << ": " << r.invalid;
    EXPECT_TRUE(r.findings.empty()) << p.stage << describe(r);
    EXPECT_EQ(r.checked, (std::vector<std::string>{"exact", "int", "targets"})) << p.stage;
    CheckOptions o = quick();
    o.sabotage = "drop-lo";
    const CheckResult broken = run(p, o);
    EXPECT_TRUE(has_finding(broken, "int")) << p.stage << describe(broken);
  }
}

// Oracle 4 in Chromium's WebGPU: the wgsl lowering agrees with es320 on lavapipe for buffer inputs
// and, with a few samples (one browser page each), for uniform inputs; the wgsl run sabotaged with
// drop-lo is found by it.
TEST(DiffOracles, WebGpuAgreesAndDroppedLowWordsAreFound) {
  DOUBLET_REQUIRE_BROWSER_OR_SKIP();
  Program buffers;
  buffers.glsl = R"(#version 450
layout(local_size_x = 64) in;
layout(std140, binding = 0) readonly buffer In0 { double in0[]; };
layout(std430, binding = 1) writeonly buffer Out0 { double r0[]; };
void main() {
  uint gid = gl_GlobalInvocationID.x;
  r0[gid] = in0[gid] * 1.1lf + in0[gid] / 3.0lf;
}
)";
  buffers.spec_json = R"({ "inputs": { "in0": { "range": [0.25, 4] } } })";
  Program uniforms = buffers;
  uniforms.glsl = R"(#version 450
layout(local_size_x = 64) in;
uniform double u0 = 1.5lf;
layout(std430, binding = 1) writeonly buffer Out0 { double r0[]; };
void main() {
  r0[gl_GlobalInvocationID.x] = u0 * 1.1lf + u0 / 3.0lf;
}
)";
  uniforms.spec_json = R"({ "inputs": { "u0": { "range": [0.25, 4] } } })";
  for (const Program& p : {buffers, uniforms}) {
    CheckOptions o = quick();
    o.webgpu = true;
    o.oracles = {"targets"};
    const CheckResult r = run(p, o);
    EXPECT_TRUE(r.findings.empty()) << p.glsl << describe(r);
    EXPECT_TRUE(r.notes.empty()) << p.glsl << (r.notes.empty() ? "" : r.notes[0]);
    EXPECT_EQ(r.checked, std::vector<std::string>{"targets"}) << p.glsl;
    o.sabotage = "drop-lo";
    const CheckResult broken = run(p, o);
    bool found = false;
    for (const Finding& f : broken.findings) found |= f.oracle == "targets" && f.detail.find("WebGPU") != std::string::npos;
    EXPECT_TRUE(found) << p.glsl << describe(broken);
  }
}

// Seed 70349 (the long run): df64-int and df64 differed in the last bits of 2 and 7 of 16384 results
// near 1e-38, where both modes' error terms underflow each their own way; the int oracle makes no
// claim below 2^-100 (oracles.cpp, outside_int_range). Before, this was a finding.
TEST(DiffOracles, TheIntOracleLeavesResultsBelowFloatFloatsRange) {
  const Program p = generate(70349);
  CheckOptions o;
  o.samples = 16384;
  o.oracles = {"int"};
  const CheckResult r = run(p, o);
  EXPECT_TRUE(r.invalid.empty()) << r.invalid;
  EXPECT_TRUE(r.findings.empty()) << "seed 70349" << describe(r);
  EXPECT_EQ(r.checked, std::vector<std::string>{"int"});
}

// The bound oracle: on a continuous program (one seed in three of the compute and vertex ones),
// every df64 output stays within the planner's bound.
TEST(DiffOracles, ContinuousProgramsKeepThePlannersBound) {
  Program p;
  for (uint64_t seed = 3;; seed += 3)
    if ((p = generate(seed)).stage == "comp") break;
  ASSERT_TRUE(is_continuous(p.glsl)) << p.glsl;
  CheckOptions o = quick();
  o.oracles = {"bound", "guard"};
  const CheckResult r = run(p, o);
  EXPECT_TRUE(r.findings.empty()) << "seed " << p.seed << describe(r);
  EXPECT_EQ(r.checked, (std::vector<std::string>{"guard", "bound"})) << "seed " << p.seed << "\n" << p.glsl;
}

// A continuous compute program of `body` (main's statements after `dvec2 x0 = in0[gid];`, writing
// r0[gid]) on inputs in [0.25, 4]: `oracle` alone checks it and finds nothing; under `sabotage` it
// reports a finding.
void expect_held_then_broken(const std::string& body, const std::string& oracle, const std::string& sabotage) {
  Program p;
  p.glsl = R"(#version 450
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer In0 { dvec2 in0[]; };
layout(std430, binding = 1) writeonly buffer Out0 { dvec2 r0[]; };
void main() {
  uint gid = gl_GlobalInvocationID.x;
  dvec2 x0 = in0[gid];
)" + body + "}\n";
  p.spec_json = R"({ "inputs": { "in0": { "range": [0.25, 4] } } })";
  CheckOptions o = quick();
  o.oracles = {oracle};
  const CheckResult held = run(p, o);
  EXPECT_TRUE(held.findings.empty()) << describe(held);
  EXPECT_EQ(held.checked, (std::vector<std::string>{oracle}));
  o.sabotage = sabotage;
  const CheckResult broken = run(p, o);
  EXPECT_TRUE(has_finding(broken, oracle)) << describe(broken);
}

// In the generator's continuous form: a product, a quotient and a square root.
TEST(DiffOracles, DroppedLowWordsBreakThePlannersBound) {
  expect_held_then_broken("  dvec2 v1 = fma(x0, x0.yx, dvec2(0.1lf, 0.3lf));\n"
                          "  r0[gid] = v1 / (1.5lf + abs(x0.yx)) + sqrt(abs(v1));\n",
                          "bound", "drop-lo");
}

// The guard oracle: the same program lowered with the uniform guard (es310) keeps the bound on both
// drivers; lowered without it (drop-guard), lavapipe deletes the sums' error terms and the bound is
// broken.
TEST(DiffOracles, ADroppedGuardBreaksThePlannersBound) {
  expect_held_then_broken("  r0[gid] = (x0 + dvec2(0.1lf, 0.3lf)) * x0.yx + x0;\n", "guard", "drop-guard");
}

// What the bound oracle leaves out: anything that jumps, where a tiny error can move a result by
// a whole step (docs/plan.md, "Limits").
TEST(DiffOracles, OnlyProgramsWithoutJumpsAreContinuous) {
  const std::string head = "#version 450\nin dvec2 a;\nout double r;\nvoid main() {\n  uint gid = 0u;\n";
  EXPECT_TRUE(is_continuous(head + "  r = fma(a.x, a.y, sqrt(abs(a.x))) / (1.5lf + abs(a.y)); // if (x < y)\n}\n"));
  for (const std::string body : {"r = a.x < a.y ? a.x : a.y;", "r = floor(a.x);", "if (a.x == 0.0lf) r = 1.0lf;",
                                 "r = double(int(a.x));", "for (int k = 0; k < 2; ++k) r += a.x;", "r = step(a.x, a.y);",
                                 "r = mix(a.x, a.y, a.x > 0.0lf);"})
    EXPECT_FALSE(is_continuous(head + "  " + body + "\n}\n")) << body;
}

TEST(DiffOracles, APassLeftOutIsFound) {
  // f(v.y) for an out parameter: without out-argument-temporaries the lowering cannot pass a
  // component of a split vector.
  const Program p = first_with("call:component-out-argument");
  CheckOptions o = quick();
  o.oracles = {"int"};
  EXPECT_TRUE(run(p, o).findings.empty()) << "seed " << p.seed;
  o.skip_passes = {"out-argument-temporaries"};
  const CheckResult r = run(p, o);
  EXPECT_FALSE(r.findings.empty()) << "seed " << p.seed << "\n" << p.glsl;
}

}  // namespace
}  // namespace doublet::difftest

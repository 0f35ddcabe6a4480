// The acceptance cases on real drivers (lavapipe and Mesa GLES): plan -> lower --plan ->
// verify --scene keeps every promise, and plans that are too optimistic are caught.
#include <gtest/gtest.h>

#include <filesystem>

#include "cli_run.hpp"

namespace {

using namespace plan_test;
namespace fs = std::filesystem;

std::string temp(const std::string& name) { return (fs::temp_directory_path() / ("doublet_planv_" + name)).string(); }

std::string make_plan(const std::string& shader, const std::string& scene, const std::string& name) {
  const std::string out = temp(name);
  const CliRun r = run_doublet("plan " + kScenes + "/" + shader + " --scene " + kScenes + "/" + scene + " -o " + out);
  EXPECT_EQ(r.exit_code, 0) << r.out;
  return out;
}

CliRun verify(const std::string& shader, const std::string& scene, const std::string& extra) {
  return run_doublet("verify " + kScenes + "/" + shader + " --target es300 --samples 2048 --scene " + kScenes + "/" +
                 scene + " " + extra);
}

TEST(PlanVerify, GlobePlanDemotesRelAndKeepsItsPromise) {
  const std::string plan = make_plan("globe_rte.vert", "globe.scene.json", "globe.plan.json");
  EXPECT_NE(read_file(plan).find("\"main.rel\": \"fp32\""), std::string::npos);
  const CliRun r = verify("globe_rte.vert", "globe.scene.json", "--plan " + plan);
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("v_rel"), std::string::npos);
  EXPECT_EQ(r.out.find("EXCEEDED"), std::string::npos) << r.out;
}

TEST(PlanVerify, FarEyeKeepsDf64AndADemotedRelFails) {
  const std::string plan = make_plan("globe_rte.vert", "globe_far_eye.scene.json", "far.plan.json");
  CliRun r = verify("globe_rte.vert", "globe_far_eye.scene.json", "--plan " + plan);
  EXPECT_EQ(r.exit_code, 0) << r.out;
  // Too optimistic: rel as float with the eye up to 1e5 m away (float spacing 7.8 mm > 1 mm).
  const std::string optimistic = temp("optimistic.plan.json");
  write_file(optimistic, R"({"version": 1, "mode": "df64", "mode_for": {"main.rel": "fp32"}})");
  r = verify("globe_rte.vert", "globe_far_eye.scene.json", "--plan " + optimistic);
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_NE(r.out.find("EXCEEDED"), std::string::npos) << r.out;
}

// Compute: the scene's range applies to every element of a buffer array, and verify fills the
// lowered buffer's df_dvec3 elements (hi and lo) from the manifest.
TEST(PlanVerify, ComputeBufferArrayKeepsItsPromiseAndFp32DoesNot) {
  const std::string plan = make_plan("globe_rte.comp", "globe_compute.scene.json", "compute.plan.json");
  const std::string base = "verify " + kScenes + "/globe_rte.comp --target es310 --samples 2048 --scene " + kScenes +
                           "/globe_compute.scene.json ";
  CliRun r = run_doublet(base + "--plan " + plan);
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("rel[].z"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("EXCEEDED"), std::string::npos) << r.out;
  r = run_doublet(base + "--mode fp32");
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_NE(r.out.find("EXCEEDED"), std::string::npos) << r.out;
}

TEST(PlanVerify, Fp32EverywhereFailsTheGlobeScene) {
  const CliRun r = verify("globe_rte.vert", "globe.scene.json", "--mode fp32");
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_NE(r.out.find("EXCEEDED"), std::string::npos) << r.out;
}

TEST(PlanVerify, OrbitKeepsDf64AndMeetsOneMicrometre) {
  const std::string plan = make_plan("orbit_step.vert", "orbit.scene.json", "orbit.plan.json");
  CliRun r = verify("orbit_step.vert", "orbit.scene.json", "--plan " + plan);
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_EQ(r.out.find("EXCEEDED"), std::string::npos) << r.out;
  r = verify("orbit_step.vert", "orbit.scene.json", "--mode fp32");
  EXPECT_EQ(r.exit_code, 1) << r.out;
}

// Beyond float's range (G M m reaches 3e47): the plan is mode exact, whose run is bit-identical
// to native; df64 (the default) overflows to inf and is caught by the same scene.
TEST(PlanVerify, GravityInSiUnitsPlansExactAndDf64Overflows) {
  const std::string plan = make_plan("gravity_si.comp", "gravity_si.scene.json", "gravity.plan.json");
  EXPECT_NE(read_file(plan).find("\"mode\": \"exact\""), std::string::npos) << read_file(plan);
  const std::string base = "verify " + kScenes + "/gravity_si.comp --target es310 --samples 1024 --scene " + kScenes +
                           "/gravity_si.scene.json ";
  CliRun r = run_doublet(base + "--plan " + plan);
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("identical bits required: 0 of"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("EXCEEDED"), std::string::npos) << r.out;
  r = run_doublet(base);
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_NE(r.out.find("measured inf"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("EXCEEDED"), std::string::npos) << r.out;
}

// The same physics in functions: only they pass beyond float's range, so the plan makes them exact
// and keeps main float-float (docs/modes.md, "Exact functions"); the run keeps the scene's promise
// within the estimate, and df64 everywhere overflows.
TEST(PlanVerify, GravityInFunctionsPlansExactFunctionsAndKeepsItsPromise) {
  const std::string plan = make_plan("gravity_si_functions.comp", "gravity_si_functions.scene.json", "gravity_fn.plan.json");
  const std::string text = read_file(plan);
  EXPECT_NE(text.find("\"mode\": \"df64\""), std::string::npos) << text;
  EXPECT_NE(text.find("\"force_of\": \"exact\""), std::string::npos) << text;
  EXPECT_NE(text.find("\"energy_of\": \"exact\""), std::string::npos) << text;
  const std::string base = "verify " + kScenes + "/gravity_si_functions.comp --target es310 --samples 1024 --scene " +
                           kScenes + "/gravity_si_functions.scene.json ";
  CliRun r = run_doublet(base + "--plan " + plan);
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_EQ(r.out.find("EXCEEDED"), std::string::npos) << r.out;
  r = run_doublet(base);
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_NE(r.out.find("measured inf"), std::string::npos) << r.out;
}

}  // namespace

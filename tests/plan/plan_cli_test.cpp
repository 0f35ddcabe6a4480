// `doublet plan` and `doublet lower --plan` as users run them (no driver needed).
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "cli_run.hpp"

namespace {

using namespace plan_test;
namespace fs = std::filesystem;

std::string temp(const std::string& name) { return (fs::temp_directory_path() / ("doublet_plan_" + name)).string(); }

TEST(PlanCli, GlobeTableAndPlanFile) {
  const std::string out = temp("globe.plan.json");
  fs::remove(out);
  const CliRun r = run_doublet("plan " + kScenes + "/globe_rte.vert --scene " + kScenes + "/globe.scene.json -o " + out);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  for (const char* column : {"value", "line", "range", "bits", "mode", "flops"})
    EXPECT_NE(r.out.find(column), std::string::npos) << column;
  EXPECT_NE(r.out.find("main.rel"), std::string::npos);
  const nlohmann::json plan = nlohmann::json::parse(read_file(out));
  // Half a float ulp at |rel| <= 1e4 (4.9e-4 m) fits the 1 mm promise: rel is stored as float.
  EXPECT_EQ(plan, nlohmann::json::parse(R"({"version": 1, "mode": "df64", "mode_for": {"main.rel": "fp32"}})"));
}

TEST(PlanCli, FarEyeAndOrbitKeepDf64) {
  const std::string out = temp("far.plan.json");
  CliRun r = run_doublet("plan " + kScenes + "/globe_rte.vert --scene " + kScenes + "/globe_far_eye.scene.json -o " + out);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_EQ(nlohmann::json::parse(read_file(out))["mode_for"], nlohmann::json::object());
  r = run_doublet("plan " + kScenes + "/orbit_step.vert --scene " + kScenes + "/orbit.scene.json -o " + out);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_EQ(nlohmann::json::parse(read_file(out))["mode_for"], nlohmann::json::object());
  EXPECT_EQ(r.out.find(" fp32 "), std::string::npos) << r.out;
}

// wgs84.scene.json relates a computed value (main.p, the ECEF position) to the eye: plan uses it;
// verify, which draws inputs only, refuses it at the relation instead of sampling without it.
TEST(PlanCli, Wgs84PlanAndVerifyRefusingTheComputedRelation) {
  const std::string out = temp("wgs84.plan.json");
  CliRun r = run_doublet("plan " + kScenes + "/wgs84_ecef.vert --scene " + kScenes + "/wgs84.scene.json -o " + out);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("main.rel"), std::string::npos) << r.out;
  EXPECT_EQ(nlohmann::json::parse(read_file(out)),
            nlohmann::json::parse(R"({"version": 1, "mode": "df64", "mode_for": {"up_vector": "fp32", "main.rel": "fp32"}})"));
  r = run_doublet("verify " + kScenes + "/globe_rte.vert --scene " + kScenes + "/wgs84.scene.json");
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_NE(r.out.find("wgs84.scene.json:"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("verify cannot sample a relation on 'main.p'"), std::string::npos) << r.out;
}

TEST(PlanCli, BadScenesExit2WithPosition) {
  const std::string scene = temp("bad.scene.json");
  write_file(scene, "{\n  \"outputs\": {\"v_rel\": {\"abs_error\": \"lots\"}}\n}\n");
  CliRun r = run_doublet("plan " + kScenes + "/globe_rte.vert --scene " + scene);
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_NE(r.out.find(scene + ":2:38: error: abs_error must be a positive number"), std::string::npos) << r.out;

  write_file(scene, "{\"outputs\": {\"nowhere\": {\"abs_error\": 1}}}");
  r = run_doublet("plan " + kScenes + "/globe_rte.vert --scene " + scene);
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_NE(r.out.find(scene + ":1:25: error: the shader has no output"), std::string::npos) << r.out;

  write_file(scene, "not json");
  r = run_doublet("plan " + kScenes + "/globe_rte.vert --scene " + scene);
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_NE(r.out.find(scene + ":1:"), std::string::npos) << r.out;

  r = run_doublet("plan " + kScenes + "/globe_rte.vert --scene " + temp("missing.json"));
  EXPECT_EQ(r.exit_code, 2) << r.out;
  r = run_doublet("plan " + kScenes + "/globe_rte.vert");  // --scene is required: a usage error
  EXPECT_EQ(r.exit_code, 1) << r.out;
}

TEST(PlanCli, InfeasibleSceneExits1) {
  // v_height is a float output of about 1e3 m: its own rounding (2^(9-24) = 3e-5) exceeds 1e-6.
  const std::string scene = temp("tight.scene.json");
  write_file(scene, read_file(kScenes + "/globe.scene.json").replace(
                        read_file(kScenes + "/globe.scene.json").find("\"abs_error\": 1e-4"), 17, "\"abs_error\": 1e-6"));
  const CliRun r = run_doublet("plan " + kScenes + "/globe_rte.vert --scene " + scene);
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_NE(r.out.find("v_height"), std::string::npos);
}

TEST(PlanCli, LowerAppliesThePlanAndRejectsBadPlans) {
  const std::string plan = temp("apply.plan.json");
  write_file(plan, R"({"version": 1, "mode": "df64", "mode_for": {"main.rel": "fp32"}})");
  CliRun r = run_doublet("lower " + kScenes + "/globe_rte.vert --plan " + plan);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("  vec3 rel = "), std::string::npos) << r.out;  // stored as float
  r = run_doublet("lower " + kScenes + "/globe_rte.vert");
  EXPECT_EQ(r.out.find("  vec3 rel = "), std::string::npos);  // without the plan it stays df64

  write_file(plan, "{\"version\": 1, \"mode_for\": {\"main.rel\": 32}}");
  r = run_doublet("lower " + kScenes + "/globe_rte.vert --plan " + plan);
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_NE(r.out.find(plan + ":1:41: error:"), std::string::npos) << r.out;
  r = run_doublet("lower " + kScenes + "/globe_rte.vert --plan " + temp("no_such_plan.json"));
  EXPECT_EQ(r.exit_code, 2) << r.out;
}

// The plan says why it leaves float-float: the value beyond float's range, and each output's
// estimate in binary64 next to df64's infinite one.
TEST(PlanCli, GravityInSiUnitsTableNamesTheValueBeyondFloat) {
  const std::string out = temp("gravity.plan.json");
  const CliRun r = run_doublet("plan " + kScenes + "/gravity_si.comp --scene " + kScenes + "/gravity_si.scene.json -o " + out);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_EQ(nlohmann::json::parse(read_file(out)), nlohmann::json::parse(R"({"version": 1, "mode": "exact", "mode_for": {}})"));
  EXPECT_NE(r.out.find("estimate(exact)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("main.gmm reaches 2.66e+48"), std::string::npos) << r.out;  // 6.6743e-11 * 2.1e30 * 1.9e28
  EXPECT_NE(r.out.find("the plan is mode exact for the whole shader"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("anon@"), std::string::npos) << r.out;
}

}  // namespace

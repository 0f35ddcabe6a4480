// `doublet verify` as users run it: exit codes, the table, and the --json file.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

namespace {

namespace fs = std::filesystem;

struct CliRun {
  int exit_code = -1;
  std::string out;
};

// Runs the CLI with stdout (and stderr) captured.
CliRun doublet(const std::string& args) {
  CliRun r;
  const std::string cmd = std::string(DOUBLET_CLI_PATH) + " verify " + args + " 2>&1";
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return r;
  char buf[4096];
  while (size_t n = fread(buf, 1, sizeof buf, p)) r.out.append(buf, n);
  const int status = pclose(p);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

const std::string kShaders = DOUBLET_VERIFY_SHADERS;
const std::string kArith = kShaders + "/arith_pairs.comp --spec " + kShaders + "/arith_pairs.json --samples 1024";

TEST(VerifyCli, PassesAt44BitsAndPrintsTheProbeFirst) {
  const CliRun r = doublet(kArith + " --min-bits 44");
  EXPECT_EQ(r.exit_code, 0) << r.out;
  const size_t probe = r.out.find("probe: stage comp: unprotected TwoSum");
  ASSERT_NE(probe, std::string::npos) << r.out;
  EXPECT_LT(probe, r.out.find("results[].xy"));
  EXPECT_NE(r.out.find("[vulkan]"), std::string::npos);
  EXPECT_NE(r.out.find("[gles]"), std::string::npos);
  EXPECT_NE(r.out.find("result: PASS"), std::string::npos);
}

// Without any threshold a PASS says only that both versions ran, and verify says so.
TEST(VerifyCli, NoThresholdIsSaidOutLoud) {
  const std::string note = "note: no accuracy threshold";
  const std::string plain = kArith + " --backend gles";
  CliRun r = doublet(plain);
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find(note), std::string::npos) << r.out;
  r = doublet(plain + " --min-bits 40");
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_EQ(r.out.find(note), std::string::npos) << r.out;
}

TEST(VerifyCli, SabotageExitsOne) {
  for (const char* s : {"drop-lo", "drop-guard"}) {
    const CliRun r = doublet(kArith + " --min-bits 44 --backend gles --sabotage " + s);
    EXPECT_EQ(r.exit_code, 1) << s << "\n" << r.out;
    EXPECT_NE(r.out.find("FAIL"), std::string::npos) << r.out;
  }
}

TEST(VerifyCli, InputErrorsExitTwo) {
  EXPECT_EQ(doublet("/nonexistent.comp").exit_code, 2);
  EXPECT_EQ(doublet(kArith + " --range nope=1:2").exit_code, 2);
  EXPECT_EQ(doublet(kArith + " --range operands=2:1").exit_code, 2);
  EXPECT_EQ(doublet(kShaders + "/arith_pairs.comp --spec /nonexistent.json").exit_code, 2);
  const fs::path bad = fs::temp_directory_path() / "doublet_verify_bad.comp";
  std::ofstream(bad) << "#version 310 es\nlayout(local_size_x = 1) in;\nvoid main() { undeclared = 1.0; }\n";
  const CliRun r = doublet(bad.string());
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_NE(r.out.find("undeclared"), std::string::npos) << r.out;
  fs::remove(bad);
}

TEST(VerifyCli, JsonFileFollowsTheSchema) {
  const fs::path json = fs::temp_directory_path() / "doublet_verify_test.json";
  const CliRun r = doublet(kArith + " --backend vulkan --json " + json.string());
  ASSERT_EQ(r.exit_code, 0) << r.out;
  std::ifstream in(json);
  const nlohmann::json j = nlohmann::json::parse(in);
  fs::remove(json);
  EXPECT_EQ(j["schema"], "doublet-verify/1");
  EXPECT_EQ(j["stage"], "comp");
  EXPECT_EQ(j["target"], "es310");
  ASSERT_EQ(j["runs"].size(), 1u);
  EXPECT_EQ(j["runs"][0]["backend"], "vulkan");
  EXPECT_EQ(j["runs"][0]["probe"]["unprotected_two_sum_survives"], false);
  const nlohmann::json& o = j["runs"][0]["outputs"][0];
  EXPECT_EQ(o["name"], "results[].xy");
  EXPECT_EQ(o["samples"], 4096);
  EXPECT_GE(o["min_bits"].get<double>(), 44.0);
  EXPECT_EQ(o["class_mismatches"], 0);
}

// Vertex and fragment stages: same command, same schema; the stage's probe reports the FTZ.
TEST(VerifyCli, FragmentAndVertexStagesReportTheirProbe) {
  const fs::path json = fs::temp_directory_path() / "doublet_verify_frag.json";
  const CliRun r = doublet(kShaders + "/pairs.frag --spec " + kShaders + "/pairs.frag.json --target es300 --samples 256 " +
                           "--min-bits 44 --json " + json.string());
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("probe: stage frag: unprotected TwoSum DELETED"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("fp32 denormals FLUSHED"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("caveat: this stage flushes denormals"), std::string::npos) << r.out;
  std::ifstream in(json);
  const nlohmann::json j = nlohmann::json::parse(in);
  fs::remove(json);
  EXPECT_EQ(j["schema"], "doublet-verify/1");
  EXPECT_EQ(j["stage"], "frag");
  ASSERT_EQ(j["runs"].size(), 2u);
  for (const nlohmann::json& run : j["runs"]) {
    EXPECT_EQ(run["probe"]["stage"], "frag");
    EXPECT_EQ(run["probe"]["denormals_flushed"], true);
    EXPECT_EQ(run["outputs"][0]["name"], "color.xy");
    EXPECT_GE(run["outputs"][0]["min_bits"].get<double>(), 44.0);
  }
  const CliRun vert = doublet(kShaders + "/pairs.vert --spec " + kShaders + "/pairs.vert.json --samples 256 " +
                              "--min-bits 44 --backend vulkan --sabotage drop-lo");
  EXPECT_EQ(vert.exit_code, 1) << vert.out;
  EXPECT_NE(vert.out.find("probe: stage vert"), std::string::npos) << vert.out;
}

}  // namespace

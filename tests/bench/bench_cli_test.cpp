// `doublet bench --json`: a tiny run through the executable writes the documented keys.
#include <gtest/gtest.h>

#include <regex>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <sys/wait.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

namespace {

TEST(BenchCli, JsonHasTheDocumentedKeys) {
  const auto json_path = std::filesystem::temp_directory_path() / ("bench_cli_" + std::to_string(::getpid()) + ".json");
  const std::string cmd = std::string(DOUBLET_CLI_PATH) +
                          " bench --ops add,sqrt --elements 128 --steps 8 --warmup 1 --reps 2 --json " +
                          json_path.string() + " > /dev/null";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  std::ifstream in(json_path);
  const nlohmann::json j = nlohmann::json::parse(in);
  std::filesystem::remove(json_path);
  // The keys docs/performance.md lists, at the top level and per result.
  for (const char* key : {"command", "shader", "target", "elements", "warmup", "repetitions", "devices",
                          "clocks", "native_reference_backend", "results", "notes"})
    EXPECT_TRUE(j.contains(key)) << key;
  ASSERT_EQ(j["results"].size(), 2u * 2u * 6u);  // --modes all: fp32 rte df64-fast df64 df64-int native
  for (const auto& r : j["results"])
    for (const char* key : {"op", "backend", "mode", "ok", "not_applicable", "steps", "note", "seconds", "median_seconds", "min_seconds", "ops_per_second",
                            "time_vs_fp32", "time_vs_native", "finite_output", "spirv_instructions", "glsl_lines",
                            "flops_per_step", "emitted_flops_per_step", "bits"})
      EXPECT_TRUE(r.contains(key)) << key;
  // Bits are measured against native fp64 in the same run: fp32 cannot pass for float-float.
  for (const auto& r : j["results"]) {
    SCOPED_TRACE(r["op"].get<std::string>() + " " + r["mode"].get<std::string>() + " " + r["backend"].get<std::string>());
    if (r["not_applicable"].get<bool>()) continue;
    ASSERT_TRUE(r["bits"].is_number()) << r["note"];
    const double bits = r["bits"].get<double>();
    if (r["mode"] == "native") EXPECT_EQ(bits, 53.0);
    if (r["mode"] == "df64") EXPECT_GE(bits, 43.0);
    if (r["mode"] == "fp32") EXPECT_LE(bits, 24.5);
  }
  // Every documented key appears in docs/performance.md.
  std::ifstream doc(std::string(DOUBLET_DOCS) + "/performance.md");
  std::stringstream ss;
  ss << doc.rdbuf();
  for (const char* key : {"time_vs_fp32", "time_vs_native", "clocks", "spirv_instructions", "median_seconds",
                          "emitted_flops_per_step", "bits"})
    EXPECT_NE(ss.str().find(std::string("`") + key + "`"), std::string::npos) << key;
}

TEST(BenchCli, UserShaderWithIncludesRunsInEveryMode) {
  const auto json_path = std::filesystem::temp_directory_path() / ("bench_shader_" + std::to_string(::getpid()) + ".json");
  const std::string cmd = std::string(DOUBLET_CLI_PATH) + " bench " + DOUBLET_EXAMPLES +
                          "/shaders/orbit_step.comp --elements 256 --warmup 1 --reps 2 --json " + json_path.string() +
                          " > /dev/null";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  std::ifstream in(json_path);
  const nlohmann::json j = nlohmann::json::parse(in);
  std::filesystem::remove(json_path);
  ASSERT_EQ(j["results"].size(), 12u);  // 2 backends x 6 modes
  for (const auto& r : j["results"]) {
    if (r["backend"] == "gles" && r["mode"] == "native") continue;
    EXPECT_TRUE(r["ok"].get<bool>()) << r["mode"] << " " << r["backend"] << ": " << r["note"];
    EXPECT_GT(r["ops_per_second"].get<double>(), 0);
  }
}

std::string run_capture(const std::string& args, int* status) {
  const auto out = std::filesystem::temp_directory_path() / ("bench_out_" + std::to_string(::getpid()) + ".txt");
  const std::string cmd = std::string(DOUBLET_CLI_PATH) + " bench " + args + " > " + out.string() + " 2>&1";
  *status = std::system(cmd.c_str());
  std::ifstream in(out);
  std::stringstream ss;
  ss << in.rdbuf();
  std::filesystem::remove(out);
  return ss.str();
}

// A tiny comparison with the hand-written library: every contender runs, the Mandelbrot row has an
// agreement with native fp64, the per-op rows have bits. No timing thresholds.
TEST(BenchCli, HandwrittenComparisonRunsEveryContender) {
  int status = 0;
  const std::string out = run_capture(
      "--handwritten --ops add,mandelbrot --elements 256 --steps 16 --warmup 1 --reps 1 --mandelbrot-size 16 "
      "--mandelbrot-iterations 50",
      &status);
  ASSERT_EQ(WEXITSTATUS(status), 0) << out;
  for (const char* row : {"| add | handwritten (ONE guard) |", "| add | doublet es310 -O0 |", "| add | doublet es320 |",
                          "| mandelbrot | handwritten (ONE guard) |", "| mandelbrot | doublet es320 |"})
    EXPECT_NE(out.find(row), std::string::npos) << row << "\n" << out;
  EXPECT_NE(out.find("bits |"), std::string::npos) << out;
  EXPECT_NE(out.find("pixels = native"), std::string::npos) << out;
}

TEST(BenchCli, CompilerSpeedPrintsTheRatioToAGlslangParse) {
  int status = 0;
  const std::string out = run_capture("--compiler --lines 300 --reps 1", &status);
  ASSERT_EQ(WEXITSTATUS(status), 0) << out;
  EXPECT_NE(out.find("ratio lower / parse:"), std::string::npos) << out;
  EXPECT_NE(out.find("glslang re-validation of the output"), std::string::npos) << out;
}

TEST(BenchCli, CompilerScalingPrintsARowPerSize) {
  int status = 0;
  const std::string out = run_capture("--compiler --lines 300 --reps 1 --scaling 200,800", &status);
  ASSERT_EQ(WEXITSTATUS(status), 0) << out;
  EXPECT_NE(out.find("| lines | glslang parse ms | doublet::lower ms | lower / parse | parse us/line | lower us/line |"),
            std::string::npos) << out;
  EXPECT_NE(out.find("| import |"), std::string::npos) << out;  // a column per phase
  EXPECT_TRUE(std::regex_search(out, std::regex(R"(\nfrom \d+ to \d+ lines \(x4\.\d\): glslang parse x[0-9.]+, doublet::lower x[0-9.]+\n)"))) << out;
  EXPECT_NE(out.find("command: doublet bench --compiler --lines 300 --reps 1 --target es320 --scaling 200,800"),
            std::string::npos) << out;
}

TEST(BenchCli, CompilerScalingSizesAreChecked) {
  const std::string cmd = std::string(DOUBLET_CLI_PATH) + " bench --compiler --scaling 5 > /dev/null 2>&1";
  EXPECT_EQ(WEXITSTATUS(std::system(cmd.c_str())), 1);
}

TEST(BenchCli, PlotWritesAPng) {
  const auto png = std::filesystem::temp_directory_path() / ("bench_plot_" + std::to_string(::getpid()) + ".png");
  int status = 0;
  const std::string out = run_capture("--ops add --modes fp32,df64,native --elements 128 --steps 8 --warmup 1 --reps 1 --plot " +
                                          png.string(),
                                      &status);
  ASSERT_EQ(WEXITSTATUS(status), 0) << out;
  std::ifstream in(png, std::ios::binary);
  char sig[8] = {};
  in.read(sig, 8);
  EXPECT_EQ(std::string(sig + 1, 3), "PNG");
  EXPECT_NE(out.find("(5 points)"), std::string::npos) << out;  // fp32 x2, df64 x2, native on lavapipe
  std::filesystem::remove(png);
}

// Mode exact has rows on both backends (GLES included), with bits measured against native fp64.
TEST(BenchCli, ExactRowsOnBothBackends) {
  int status = 0;
  const std::string out =
      run_capture("--ops add,sqrt --modes fp32,exact,native --backend both --elements 128 --steps 8 --warmup 1 --reps 1", &status);
  ASSERT_EQ(WEXITSTATUS(status), 0) << out;
  const size_t gles = out.find("### gles");
  ASSERT_NE(gles, std::string::npos) << out;
  for (const char* op : {"add", "sqrt"}) {
    // The emitted-flops column: a count, or "—" where a helper loops (mode exact's shared call sites).
    const std::regex row(std::string(R"(\| )") + op + R"( \| exact \| — \| (?:[0-9.]+|—) \| 53\.00 \| [0-9.]+ \|)");
    EXPECT_TRUE(std::regex_search(out.substr(0, gles), row)) << op << " on vulkan\n" << out;
    EXPECT_TRUE(std::regex_search(out.substr(gles), row)) << op << " on gles\n" << out;
  }
}

// --peer-mesa-fp64 with a file that is missing or is not Mesa's: an input error with the reason,
// never a crash; an op Mesa's path lacks is a usage error.
TEST(BenchCli, PeerMesaFp64BadInputIsDiagnosed) {
  int status = 0;
  std::string out = run_capture("--peer-mesa-fp64 /nonexistent/float64.glsl", &status);
  EXPECT_EQ(WEXITSTATUS(status), 2) << out;
  EXPECT_NE(out.find("cannot read (fetch it with scripts/fetch-mesa-fp64)"), std::string::npos) << out;
  const auto bogus = std::filesystem::temp_directory_path() / ("bogus_fp64_" + std::to_string(::getpid()) + ".glsl");
  std::ofstream(bogus) << "uint __fadd64(uint a) { return a; }\n#if 1\n";
  out = run_capture("--peer-mesa-fp64 " + bogus.string(), &status);
  EXPECT_EQ(WEXITSTATUS(status), 2) << out;
  EXPECT_NE(out.find("#if around definitions is not supported"), std::string::npos) << out;
  std::filesystem::remove(bogus);
  out = run_capture("--peer-mesa-fp64 x.glsl --ops mat4", &status);
  EXPECT_EQ(WEXITSTATUS(status), 1) << out;
}

TEST(BenchCli, TranscendentalsPrintEveryVariantWithRatiosAndBits) {
  int status = 0;
  const std::string out =
      run_capture("--transcendentals --peer-luma --ops exp,sin --elements 64 --steps 8 --warmup 0 --reps 1", &status);
  ASSERT_EQ(WEXITSTATUS(status), 0) << out;
  for (const char* row : {"| exp | vulkan | fp32 | ", "| exp | vulkan | df64 | ", "| exp | vulkan | native | ",
                          "| exp | gles | fp32 | ", "| exp | gles | df64 | ", "| sin | gles | df64 | "})
    EXPECT_NE(out.find(row), std::string::npos) << row << "\n" << out;
  EXPECT_EQ(out.find("| exp | gles | native |"), std::string::npos) << out;  // GLES has no fp64: no row
  // luma.gl runs where tools/peers is installed (CI), and says why not elsewhere.
  EXPECT_TRUE(out.find("| exp | gles | luma.gl | ") != std::string::npos || out.find("luma.gl not run: ") != std::string::npos)
      << out;
  EXPECT_NE(out.find("time / native | time / luma.gl | bits"), std::string::npos) << out;
  EXPECT_NE(out.find("`doublet bench --transcendentals --peer-luma --ops exp,sin"), std::string::npos) << out;
}

TEST(BenchCli, TranscendentalsUnknownFunctionIsAUsageError) {
  const std::string cmd = std::string(DOUBLET_CLI_PATH) + " bench --transcendentals --ops exp,atan > /dev/null 2>&1";
  EXPECT_EQ(WEXITSTATUS(std::system(cmd.c_str())), 1);
}

TEST(BenchCli, UnknownOpIsAUsageError) {
  const std::string cmd = std::string(DOUBLET_CLI_PATH) + " bench --ops nope > /dev/null 2>&1";
  const int status = std::system(cmd.c_str());
  EXPECT_EQ(WEXITSTATUS(status), 1);
}

}  // namespace

namespace {
// A user shader calling the transcendental extension on doubles: every lowered mode runs (the
// interface is reflected with stub bodies for the extension's overloads); native fp64 has no such
// functions, so its row says why it did not run instead of the whole command failing.
TEST(BenchCli, UserShaderWithTranscendentalsRunsAndNativeSaysWhy) {
  const auto dir = std::filesystem::temp_directory_path() / ("bench_trans_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto shader = dir / "waves.comp";
  const auto json_path = dir / "out.json";
  {
    std::ofstream(shader) << "#version 450\nlayout(local_size_x = 64) in;\n"
                             "layout(std430, binding = 0) buffer Data { double v[]; };\nuniform double k;\n"
                             "void main() { uint i = gl_GlobalInvocationID.x; v[i] = sin(k * v[i]) + exp(v[i]); }\n";
  }
  const std::string cmd = std::string(DOUBLET_CLI_PATH) + " bench " + shader.string() +
                          " --modes fp32,df64,native --backend vulkan --elements 256 --warmup 1 --reps 2 --json " +
                          json_path.string() + " > /dev/null";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  std::ifstream in(json_path);
  const nlohmann::json j = nlohmann::json::parse(in);
  std::filesystem::remove_all(dir);
  ASSERT_EQ(j["results"].size(), 3u);
  for (const auto& r : j["results"]) {
    if (r["mode"] == "native") {
      EXPECT_FALSE(r["ok"].get<bool>());
      EXPECT_NE(r["note"].get<std::string>().find("no transcendental functions"), std::string::npos) << r["note"];
    } else {
      EXPECT_TRUE(r["ok"].get<bool>()) << r["mode"] << ": " << r["note"];
    }
  }
}
}  // namespace

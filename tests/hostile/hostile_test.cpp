// Hostile input through the real CLI: every case must exit 2 with a
// `file:line:col: error:` diagnostic within a time limit, create no output and
// leave an existing output byte-for-byte untouched.
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <regex>
#include <sstream>

#include "test_support.hpp"

namespace {

namespace fs = std::filesystem;
using doublet::cli_test::ProcessResult;
using doublet::cli_test::read_file;
using doublet::cli_test::run_process;
using doublet::cli_test::ScratchDir;
using doublet::cli_test::write_file;

constexpr const char* kTimeLimitSeconds = "60";
const std::string kSentinel = "previous output, must survive\n";

struct Outcome {
  ProcessResult process;
  std::string first_error;  // first line of stderr
  double seconds = 0;
};

// Runs `doublet lower NAME -o out.glsl --manifest out.json` in `dir`, where
// both outputs already exist with known contents.
Outcome lower_in(const ScratchDir& dir, const std::string& name) {
  write_file(dir / "out.glsl", kSentinel);
  write_file(dir / "out.json", kSentinel);
  auto start = std::chrono::steady_clock::now();
  Outcome o;
  o.process = run_process("/usr/bin/timeout", {kTimeLimitSeconds, DOUBLET_CLI, "lower", name, "-o", "out.glsl", "--manifest",
                                      "out.json"},
                          dir.path());
  o.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  o.first_error = o.process.err.substr(0, o.process.err.find('\n'));
  return o;
}

void expect_clean_failure(const ScratchDir& dir, const Outcome& o, const std::vector<std::string>& inputs) {
  EXPECT_EQ(o.process.exit_code, 2) << "124 = timed out, -1 = crashed\nstderr: " << o.process.err.substr(0, 2000);
  EXPECT_EQ(read_file(dir / "out.glsl"), kSentinel) << "an existing output was clobbered";
  EXPECT_EQ(read_file(dir / "out.json"), kSentinel) << "an existing manifest was clobbered";
  std::vector<std::string> expected = inputs;
  expected.push_back("out.glsl");
  expected.push_back("out.json");
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(dir.entries(), expected) << "a temporary or partial file was left behind";
}

struct CorpusCase {
  std::string file;
  std::string pattern;
};

std::vector<CorpusCase> corpus() {
  std::ifstream in(std::string(DOUBLET_HOSTILE_DIR) + "/expected.txt");
  std::vector<CorpusCase> cases;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    CorpusCase c;
    fields >> c.file >> std::ws;
    std::getline(fields, c.pattern);
    cases.push_back(c);
  }
  return cases;
}

class Corpus : public ::testing::TestWithParam<CorpusCase> {};

TEST_P(Corpus, DiagnosedWithExit2AndNoOutput) {
  const CorpusCase& c = GetParam();
  ScratchDir dir;
  std::vector<std::string> inputs;
  for (const auto& entry : fs::directory_iterator(std::string(DOUBLET_HOSTILE_DIR) + "/cases")) {
    fs::copy_file(entry.path(), dir / entry.path().filename().string());  // includes need their neighbours
    inputs.push_back(entry.path().filename().string());
  }
  Outcome o = lower_in(dir, c.file);
  expect_clean_failure(dir, o, inputs);
  EXPECT_TRUE(std::regex_search(o.first_error, std::regex(c.pattern))) << "first diagnostic: " << o.first_error;
}

INSTANTIATE_TEST_SUITE_P(Files, Corpus, ::testing::ValuesIn(corpus()), [](const auto& info) {
  std::string name = info.param.file;
  for (char& ch : name)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return name;
});

TEST(Corpus, EveryCaseFileHasAnExpectation) {
  std::set<std::string> listed;
  for (const auto& c : corpus()) listed.insert(c.file);
  for (const auto& entry : fs::directory_iterator(std::string(DOUBLET_HOSTILE_DIR) + "/cases")) {
    std::string name = entry.path().filename().string();
    if (entry.path().extension() == ".glsl") continue;  // include targets, not shaders
    EXPECT_TRUE(listed.count(name)) << name << " has no line in expected.txt";
  }
}

// Generated monsters: too big to commit, cheap to build.
struct Generated {
  const char* name;
  std::string (*make)();
  const char* pattern;
};

std::string deep_parentheses() {
  return "#version 300 es\nvoid main() { float x = " + std::string(10000, '(') + "1.0" + std::string(10000, ')') +
         "; gl_Position = vec4(x); }\n";
}
std::string deep_blocks() {
  std::string s = "#version 300 es\nuniform float u;\nvoid main() { float x = u;\n";
  for (int i = 0; i < 20000; ++i) s += "if (u > 0.0) {";
  return s + "x = 1.0;" + std::string(20000, '}') + " gl_Position = vec4(x); }\n";
}
std::string operator_chain() {
  std::string s = "#version 300 es\nuniform float u;\nvoid main() { float x = u";
  for (int i = 0; i < 300000; ++i) s += "+u";
  return s + "; gl_Position = vec4(x); }\n";
}
std::string macro_bomb() {
  std::string s = "#version 300 es\n#define A0 u\n";
  for (int i = 1; i < 40; ++i) s += "#define A" + std::to_string(i) + " A" + std::to_string(i - 1) + "+A" + std::to_string(i - 1) + "\n";
  return s + "uniform float u;\nvoid main() { gl_Position = vec4(A39); }\n";
}
std::string fifty_megabytes() {
  std::string s = "#version 300 es\nuniform float u;\n";
  for (int i = 0; s.size() < 50u * 1024 * 1024; ++i) s += "// padding line " + std::to_string(i) + " ..........................................\n";
  return s + "void main() { gl_Position = vec4(u) +; }\n";  // error at the very end
}

class Monsters : public ::testing::TestWithParam<Generated> {};

TEST_P(Monsters, DiagnosedWithinTheTimeLimit) {
  const Generated& g = GetParam();
  ScratchDir dir;
  std::string file = std::string(g.name) + ".vert";
  write_file(dir / file, g.make());
  Outcome o = lower_in(dir, file);
  expect_clean_failure(dir, o, {file});
  EXPECT_TRUE(std::regex_search(o.first_error, std::regex(g.pattern))) << "first diagnostic: " << o.first_error;
  std::printf("%s: %.2f s, %s\n", g.name, o.seconds, o.first_error.substr(0, 160).c_str());
}

INSTANTIATE_TEST_SUITE_P(
    Generated, Monsters,
    ::testing::Values(Generated{"deep_parentheses", deep_parentheses, R"(:\d+:\d+: error: .*nests too deeply)"},
                      Generated{"deep_blocks", deep_blocks, R"(:\d+:\d+: error: .*nests too deeply)"},
                      Generated{"operator_chain", operator_chain, R"(:1:1: error: .*nested too deeply)"},
                      Generated{"macro_bomb", macro_bomb, R"(:\d+:\d+: error: macro .A39. expands)"},
                      Generated{"fifty_megabytes", fifty_megabytes, R"(:\d+:\d+: error: syntax error)"}),
    [](const auto& info) { return std::string(info.param.name); });

// Over doublet::kMaxSourceBytes (64 MiB): refused from the file's size, before reading it.
TEST(InputSize, SparseThreeGigabyteInputAndIncludeAreRefused) {
  ScratchDir dir;
  write_file(dir / "sparse.vert", "");
  fs::resize_file(dir / "sparse.vert", std::uintmax_t{3} << 30);
  write_file(dir / "huge.glsl", "");
  fs::resize_file(dir / "huge.glsl", std::uintmax_t{3} << 30);
  write_file(dir / "includes.vert", "#version 300 es\n#include \"huge.glsl\"\nvoid main() {}\n");
  const std::vector<std::string> inputs{"huge.glsl", "includes.vert", "sparse.vert"};

  Outcome o = lower_in(dir, "sparse.vert");
  expect_clean_failure(dir, o, inputs);
  EXPECT_TRUE(std::regex_search(o.first_error, std::regex(R"(^sparse\.vert:1:1: error: input is larger than the 64 MiB limit)")))
      << o.first_error;
  EXPECT_LT(o.seconds, 5.0) << "the file was read";

  o = lower_in(dir, "includes.vert");
  expect_clean_failure(dir, o, inputs);
  EXPECT_TRUE(std::regex_search(o.first_error,
                                std::regex(R"(^includes\.vert:1:1: error: #include "huge\.glsl" is larger than the 64 MiB)")))
      << o.first_error;
}

}  // namespace

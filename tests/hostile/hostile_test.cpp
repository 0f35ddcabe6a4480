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

// Runs `doublet lower NAME -o out.glsl --manifest out.json [extra...]` in `dir`,
// where both outputs already exist with known contents.
Outcome lower_in(const ScratchDir& dir, const std::string& name, const std::vector<std::string>& extra = {}) {
  write_file(dir / "out.glsl", kSentinel);
  write_file(dir / "out.json", kSentinel);
  auto start = std::chrono::steady_clock::now();
  Outcome o;
  std::vector<std::string> args{kTimeLimitSeconds, DOUBLET_CLI, "lower", name, "-o", "out.glsl", "--manifest", "out.json"};
  args.insert(args.end(), extra.begin(), extra.end());
  o.process = run_process("/usr/bin/timeout", args, dir.path());
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
// Six lines whose macros spell a million '+': the operator limit must see the expansion.
std::string macro_operators() {
  std::string s = "#version 300 es\nuniform float u;\n#define A u+u+u+u+u+u+u+u+u+u\n";
  const char* names = "ABCDEF";
  for (int i = 1; i < 6; ++i) {
    s += "#define " + std::string(1, names[i]) + " ";
    for (int k = 0; k < 10; ++k) s += std::string(k ? "+" : "") + names[i - 1];
    s += "\n";
  }
  return s + "void main() { gl_Position = vec4(F); }\n";
}
// A function-like macro that repeats its argument, nested 40 deep: 2^40 copies of u.
std::string function_macro_bomb() {
  std::string s = "#version 300 es\nuniform float u;\n#define D(x) (x+x)\nvoid main() { gl_Position = vec4(";
  for (int i = 0; i < 40; ++i) s += "D(";
  return s + "u" + std::string(40, ')') + "); }\n";
}
// std::regex recursed once per character of a line: these lines overflowed the stack.
std::string long_define_comment() {
  return "#version 300 es\n#define X 1 // " + std::string(4u << 20, 'a') + "\nvoid main() { gl_Position = vec4(X) +; }\n";
}
std::string million_blanks() {
  return "#version 300 es\n" + std::string(4u << 20, ' ') + "\nvoid main() { gl_Position = vec4(1.0) +; }\n";
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
                      Generated{"macro_operators", macro_operators,
                                R"(:1:1: error: a statement with 1000001 operators once its macros and #includes are expanded)"},
                      Generated{"function_macro_bomb", function_macro_bomb, R"(:3:1: error: macro .D. expands)"},
                      Generated{"long_define_comment", long_define_comment, R"(:3:\d+: error: syntax error)"},
                      Generated{"million_blanks", million_blanks, R"(:3:\d+: error: syntax error)"},
                      Generated{"fifty_megabytes", fifty_megabytes, R"(:\d+:\d+: error: syntax error)"}),
    [](const auto& info) { return std::string(info.param.name); });

// The macro budget covers #included files and -D values, not only the shader.
std::string bomb_definitions(const std::string& prefix) {
  std::string s = prefix + "A0 u\n";
  for (int i = 1; i < 40; ++i) s += prefix + "A" + std::to_string(i) + " A" + std::to_string(i - 1) + "+A" + std::to_string(i - 1) + "\n";
  return s;
}
const char* kUsesA39 = "#version 300 es\n#include \"bomb.glsl\"\nuniform float u;\nvoid main() { gl_Position = vec4(A39); }\n";

TEST(MacroBudget, MacroBombInAnIncludedFile) {
  ScratchDir dir;
  write_file(dir / "bomb.glsl", bomb_definitions("#define "));
  write_file(dir / "main.vert", kUsesA39);
  Outcome o = lower_in(dir, "main.vert");
  expect_clean_failure(dir, o, {"bomb.glsl", "main.vert"});
  EXPECT_TRUE(std::regex_search(o.first_error, std::regex(R"(^bomb\.glsl:40:1: error: macro 'A39' expands)")))
      << o.first_error;
}

TEST(MacroBudget, MacroBombInDefineOptions) {
  ScratchDir dir;
  write_file(dir / "main.vert", "#version 300 es\nuniform float u;\nvoid main() { gl_Position = vec4(A39); }\n");
  std::vector<std::string> defines;
  std::istringstream lines(bomb_definitions(""));
  for (std::string name, value; lines >> name >> value;) defines.insert(defines.end(), {"-D", name + "=" + value});
  Outcome o = lower_in(dir, "main.vert", defines);
  expect_clean_failure(dir, o, {"main.vert"});
  EXPECT_TRUE(std::regex_search(o.first_error, std::regex(R"(^main\.vert:1:1: error: macro 'A39' expands)"))) << o.first_error;
}

// 83,000 redefinitions, one error each: columns came from a rescan of the file per
// diagnostic (11 s and more); now a line index, and the report stops at 100.
TEST(ManyDiagnostics, LinearTimeAndCappedReport) {
  ScratchDir dir;
  std::string s = "#version 300 es\n";
  int defines = 0;
  for (; s.size() < (1u << 20); ++defines) s += defines % 2 ? "#define A 1\n" : "#define A 0\n";
  const std::string hidden = std::to_string(defines - 1 - 100);  // every define but the first is an error
  write_file(dir / "redefined.vert", s + "void main() { gl_Position = vec4(1.0); }\n");
  Outcome o = lower_in(dir, "redefined.vert");
  expect_clean_failure(dir, o, {"redefined.vert"});
  EXPECT_EQ(o.first_error, "redefined.vert:3:1: error: Macro redefined; different substitutions: A '#define'");
  EXPECT_LT(o.seconds, 5.0);
  const auto lines = std::count(o.process.err.begin(), o.process.err.end(), '\n');
  EXPECT_EQ(lines, 101) << o.process.err.substr(o.process.err.size() - std::min<size_t>(o.process.err.size(), 500));
  EXPECT_NE(o.process.err.find("redefined.vert: note: " + hidden + " more diagnostics not shown (" + hidden + " errors)"),
            std::string::npos)
      << o.process.err.substr(o.process.err.size() - std::min<size_t>(o.process.err.size(), 500));
}

// Pragmas waiting for the same declaration line each kept a copy of it, and each searched it:
// 20,000 pragmas before a 1 MB line took 20 GB and 30 s.
TEST(ModePragmas, ManyPragmasBeforeALongLine) {
  ScratchDir dir;
  std::string s = "#version 300 es\n";
  for (int i = 0; i < 5000; ++i) s += "#pragma doublet mode(native)\n";  // an error each: native is whole-shader only
  s += "uniform double u; // " + std::string(1u << 20, 'a') + "\nvoid main() { gl_Position = vec4(u); }\n";
  write_file(dir / "pragmas.vert", s);
  Outcome o = lower_in(dir, "pragmas.vert");
  expect_clean_failure(dir, o, {"pragmas.vert"});
  EXPECT_TRUE(std::regex_search(o.first_error, std::regex(R"(^pragmas\.vert:2:1: error: mode native applies to the whole shader only)"))) << o.first_error;
  EXPECT_LT(o.seconds, 3.0);
}


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

// `doublet lower` as a build tool: batch mode (--out-dir, -j), depfiles (-MD -MF -MT),
// coloured diagnostics only on a terminal (NO_COLOR, TERM=dumb, --color) and --help
// examples. Also the pieces behind them: depfile formatting, the -MD spelling.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "depfile.hpp"
#include "gcc_style_args.hpp"
#include "test_support.hpp"

namespace doublet::cli_test {
namespace {
namespace fs = std::filesystem;

const char* const kCompute = R"(#version 310 es
#include "pairs.glsl"
layout(local_size_x = 1) in;
layout(std430, binding = 0) buffer B { vec2 v[]; };
uniform double k;
void main() { v[0] = store_pair(load_pair(v[0]) * k); }
)";
const char* const kPairs = R"(double load_pair(vec2 p) { return double(p.x) + double(p.y); }
vec2 store_pair(double d) { float h = float(d); return vec2(h, float(d - double(h))); }
)";
const char* const kVert = "#version 300 es\nin dvec3 position;\nvoid main() { gl_Position = vec4(vec3(position), 1.0); }\n";
const char* const kBadFrag = "#version 300 es\nprecision highp float;\nout vec4 c;\nvoid main() { c = ; }\n";

class Tool : public ::testing::Test {
 protected:
  void SetUp() override {
    fs::create_directories(dir / "shaders");
    write_file(dir / "shaders/pairs.glsl", kPairs);
    write_file(dir / "shaders/step.comp", kCompute);
    write_file(dir / "shaders/pos.vert", kVert);
    write_file(dir / "shaders/bad.frag", kBadFrag);
  }
  ProcessResult run(const std::vector<std::string>& args) { return run_process(DOUBLET_CLI_PATH, args, dir.path()); }
  // Runs doublet through /usr/bin/env with extra environment assignments.
  ProcessResult run_env(std::vector<std::string> env, const std::vector<std::string>& args) {
    env.push_back(DOUBLET_CLI_PATH);
    env.insert(env.end(), args.begin(), args.end());
    return run_process("/usr/bin/env", env, dir.path());
  }
  // Runs a shell command with stdout/stderr on a pseudo-terminal (script(1)).
  ProcessResult run_on_terminal(const std::string& shell_command) {
    return run_process("/usr/bin/script", {"-qfec", shell_command, "/dev/null"}, dir.path());
  }
  ScratchDir dir;
};

TEST_F(Tool, BatchWritesOutputAndManifestPerInput) {
  ProcessResult r = run({"lower", "shaders/step.comp", "shaders/pos.vert", "--target", "es310", "--out-dir", "out", "-j", "2"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, "");
  for (const char* f : {"out/step.comp", "out/step.comp.json", "out/pos.vert", "out/pos.vert.json"})
    EXPECT_TRUE(fs::is_regular_file(dir / f)) << f;
  EXPECT_NE(read_file(dir / "out/pos.vert.json").find("position_hi"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir / "out/step.comp.d")) << "depfiles only with -MD";
}

TEST_F(Tool, BatchReportsInInputOrderWhateverTheJobCount) {
  std::vector<std::string> args{"lower", "shaders/bad.frag", "shaders/pos.vert", "shaders/bad.frag",
                                "--out-dir", "out", "-S", "frag"};
  // Duplicate names are refused before anything runs.
  EXPECT_EQ(run(args).exit_code, 1);
  write_file(dir / "shaders/bad2.frag", kBadFrag);
  std::vector<std::string> batch{"lower", "shaders/bad.frag", "shaders/step.comp", "shaders/bad2.frag",
                                 "--target", "es310", "--out-dir", "out"};
  std::vector<std::string> one = batch, four = batch;
  one.insert(one.end(), {"-j", "1"});
  four.insert(four.end(), {"-j", "4"});
  ProcessResult serial = run(one), parallel = run(four);
  EXPECT_EQ(serial.exit_code, 2) << "a failing shader fails the batch";
  EXPECT_EQ(parallel.exit_code, 2);
  EXPECT_EQ(serial.err, parallel.err);
  EXPECT_LT(serial.err.find("bad.frag"), serial.err.find("bad2.frag")) << serial.err;
  EXPECT_TRUE(fs::is_regular_file(dir / "out/step.comp")) << "the good shader is still written";
  EXPECT_FALSE(fs::exists(dir / "out/bad.frag"));
}

TEST_F(Tool, BatchUsageErrors) {
  EXPECT_EQ(run({"lower", "shaders/step.comp", "shaders/pos.vert"}).exit_code, 1) << "needs --out-dir";
  EXPECT_EQ(run({"lower", "shaders/step.comp", "shaders/pos.vert", "--out-dir", "o", "-o", "x"}).exit_code, 1);
  EXPECT_EQ(run({"lower", "shaders/step.comp", "shaders/pos.vert", "--out-dir", "o", "-MF", "x.d"}).exit_code, 1);
  EXPECT_EQ(run({"lower", "-", "shaders/pos.vert", "--out-dir", "o", "-S", "vert"}).exit_code, 1);
  EXPECT_EQ(run({"lower", "shaders/pos.vert", "--out-dir", "o", "-j", "0"}).exit_code, 1);
}

TEST_F(Tool, DepfileListsTheInputAndItsIncludes) {
  ProcessResult r = run({"lower", "shaders/step.comp", "--target", "es310", "-o", "out.comp", "-MD", "-MF", "deps/step.d"});
  // -MF into a missing directory fails like any output, and leaves nothing behind.
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_FALSE(fs::exists(dir / "out.comp"));
  fs::create_directories(dir / "deps");
  r = run({"lower", "shaders/step.comp", "--target", "es310", "-o", "out.comp", "-MD", "-MF", "deps/step.d"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(read_file(dir / "deps/step.d"), "out.comp: \\\n  shaders/step.comp \\\n  shaders/pairs.glsl\n");
}

TEST_F(Tool, DepfileSpellings) {
  ASSERT_EQ(run({"lower", "shaders/step.comp", "--target", "es310", "-o", "a.comp", "-MD"}).exit_code, 0);
  EXPECT_TRUE(fs::is_regular_file(dir / "a.comp.d")) << "-MD alone writes OUT.d";
  ASSERT_EQ(run({"lower", "shaders/step.comp", "--target", "es310", "-o", "b.comp", "-MFb.d", "-MT", "my target"}).exit_code, 0);
  EXPECT_EQ(read_file(dir / "b.d").substr(0, 11), "my\\ target:") << "-MF implies -MD; -MT names the target";
  ASSERT_EQ(run({"lower", "shaders/step.comp", "shaders/pos.vert", "--target", "es310", "--out-dir", "o", "-MD"}).exit_code, 0);
  EXPECT_EQ(read_file(dir / "o/pos.vert.d"), "o/pos.vert: \\\n  shaders/pos.vert\n");
  EXPECT_EQ(run({"lower", "shaders/pos.vert", "-MD"}).exit_code, 1) << "stdout output needs -MF and -MT";
  EXPECT_EQ(run({"lower", "shaders/pos.vert", "-MF", "p.d", "-MT", "p"}).exit_code, 0);
}

TEST_F(Tool, NoColourWhenNotATerminal) {
  ProcessResult r = run({"lower", "shaders/bad.frag"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err.find('\033'), std::string::npos) << r.err;
  ProcessResult forced = run({"lower", "shaders/bad.frag", "--color", "always"});
  EXPECT_NE(forced.err.find("\033[1;31merror:\033[0m"), std::string::npos) << forced.err;
  EXPECT_EQ(run({"lower", "shaders/bad.frag", "--color", "sometimes"}).exit_code, 1);
}

TEST_F(Tool, ColourOnATerminalUnlessNoColorOrDumb) {
  if (!fs::exists("/usr/bin/script")) GTEST_SKIP() << "script(1) is needed for a pseudo-terminal";
  const std::string cmd = std::string("'") + DOUBLET_CLI_PATH + "' lower shaders/bad.frag";
  EXPECT_NE(run_on_terminal("TERM=xterm " + cmd).out.find("\033[1;31merror:"), std::string::npos);
  EXPECT_EQ(run_on_terminal("TERM=xterm NO_COLOR=1 " + cmd).out.find('\033'), std::string::npos);
  EXPECT_EQ(run_on_terminal("TERM=dumb " + cmd).out.find('\033'), std::string::npos);
  EXPECT_NE(run_on_terminal("TERM=xterm NO_COLOR= " + cmd).out.find('\033'), std::string::npos)
      << "an empty NO_COLOR does not count (no-color.org)";
  EXPECT_NE(run_env({"NO_COLOR=1"}, {"lower", "shaders/bad.frag", "--color", "always"}).err.find("\033[1;31m"),
            std::string::npos)
      << "--color always overrides NO_COLOR";
}

TEST_F(Tool, HelpShowsExamples) {
  ProcessResult top = run({"--help"});
  EXPECT_EQ(top.exit_code, 0);
  EXPECT_NE(top.out.find("Examples:"), std::string::npos) << top.out;
  ProcessResult lower = run({"lower", "--help"});
  for (const char* s : {"Examples:", "--out-dir", "-MD", "-MF", "NO_COLOR", "-j"})
    EXPECT_NE(lower.out.find(s), std::string::npos) << s << "\n" << lower.out;
}

TEST(Depfile, EscapesLikeMake) {
  EXPECT_EQ(doublet::cli::make_depfile("out dir/a$b.vert", {"in#1.vert", "in#1.vert", "x.glsl"}),
            "out\\ dir/a$$b.vert: \\\n  in\\#1.vert \\\n  x.glsl\n");
}

TEST(GccStyleArgs, RewritesDepfileOptionsOnly) {
  const char* argv[] = {"doublet", "lower", "-MD", "-MF", "x.d", "-MTt", "-M", "-o", "-MD.vert", "--", "-MD"};
  std::vector<char*> args;
  for (const char* a : argv) args.push_back(const_cast<char*>(a));
  std::vector<std::string> got = doublet::cli::rewrite_gcc_style_args(static_cast<int>(args.size()), args.data());
  EXPECT_EQ(got, (std::vector<std::string>{"doublet", "lower", "--MD", "--MF", "x.d", "--MT=t", "-M", "-o",
                                           "-MD.vert", "--", "-MD"}));
}

}  // namespace
}  // namespace doublet::cli_test

// End-to-end tests of the `doublet` executable.
//
// Exit codes: 0 ok, 1 usage error, 2 input error (unreadable/unwritable file
// or an error diagnostic). Tests marked [core] need the real compiler core
// (they check diagnostics positions, output contents, target/stage parsing).
#include <regex>
#include <string>
#include <vector>

#include <sys/stat.h>
#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "test_support.hpp"

namespace doublet::cli_test {
namespace {
namespace fs = std::filesystem;

const char* const kGoodVert = R"(#version 300 es
// relative-to-eye position
in dvec3 position;
uniform dvec3 eye;
uniform mat4 viewProj;
void main() {
  gl_Position = viewProj * vec4(vec3(position - eye), 1.0);
}
)";

// Line 5 has a syntax error (a dangling '+').
const char* const kBadVert = R"(#version 300 es
in dvec3 position;
uniform dvec3 eye;
void main() {
  vec3 p = vec3(position - eye) + ; // @@
  gl_Position = vec4(p, 1.0);
}
)";

// Valid only when OK is defined.
const char* const kNeedsDefineVert = R"(#version 300 es
in dvec3 position;
void main() {
#ifndef OK
  vec3 p = vec3(position) + ; // @@
#endif
  gl_Position = vec4(vec3(position), 1.0);
}
)";

class Cli : public ::testing::Test {
 protected:
  ProcessResult run(const std::vector<std::string>& args,
                    const std::optional<std::string>& stdin_data = std::nullopt) {
    ProcessResult r = run_process(DOUBLET_CLI_PATH, args, dir.path(), stdin_data);
    last_err = r.err;
    return r;
  }
  fs::path put(const std::string& name, const std::string& text) {
    write_file(dir / name, text);
    return dir / name;
  }
  ScratchDir dir;
  std::string last_err;
};

bool matches(const std::string& text, const std::string& re) {
  return std::regex_search(text, std::regex(re, std::regex::multiline));
}

std::string escape_regex(const std::string& s) {
  static const std::regex special(R"([.^$|()\[\]{}*+?\\])");
  return std::regex_replace(s, special, R"(\$&)");
}

// ---------------------------------------------------------------- usage (1)

TEST_F(Cli, NoArgumentsIsUsageError) {
  auto r = run({});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err, "");
}

TEST_F(Cli, UnknownSubcommandIsUsageError) {
  EXPECT_EQ(run({"frobnicate"}).exit_code, 1);
}

TEST_F(Cli, VersionPrintsVersion) {
  auto r = run({"--version"});
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_TRUE(matches(r.out, R"(^doublet \d+\.\d+\.\d+)")) << r.out;
}

TEST_F(Cli, HelpListsLower) {
  auto r = run({"--help"});
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("lower"), std::string::npos) << r.out;
  auto r2 = run({"lower", "--help"});
  EXPECT_EQ(r2.exit_code, 0);
  EXPECT_NE(r2.out.find("--target"), std::string::npos) << r2.out;
}

TEST_F(Cli, LowerWithoutInputIsUsageError) {
  auto r = run({"lower"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err, "");
}

TEST_F(Cli, UnknownOptionIsUsageError) {
  put("a.vert", kGoodVert);
  EXPECT_EQ(run({"lower", "a.vert", "--bogus"}).exit_code, 1);
}

TEST_F(Cli, UnknownTargetIsUsageError) {  // [core] needs the real parse_target
  put("a.vert", kGoodVert);
  auto r = run({"lower", "a.vert", "--target", "es999", "-o", "out.vert"});
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("es999"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "out.vert"));
}

TEST_F(Cli, UnknownStageIsUsageError) {  // [core] needs the real parse_stage
  put("a.vert", kGoodVert);
  auto r = run({"lower", "a.vert", "-S", "mesh"});
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("mesh"), std::string::npos) << r.err;
}

TEST_F(Cli, StdinWithoutStageIsUsageError) {
  auto r = run({"lower", "-"}, std::string(kGoodVert));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("-S"), std::string::npos) << r.err;
  EXPECT_EQ(r.out, "");
}

TEST_F(Cli, UnrecognisedExtensionNeedsStage) {  // [core] needs the real stage_from_path
  put("shader.glsl", kGoodVert);
  auto r = run({"lower", "shader.glsl"});
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("-S"), std::string::npos) << r.err;
}

TEST_F(Cli, UnknownGuardIsUsageError) {
  put("a.vert", kGoodVert);
  EXPECT_EQ(run({"lower", "a.vert", "--guard", "none"}).exit_code, 1);
}

TEST_F(Cli, BadMacroNameIsUsageError) {
  put("a.vert", kGoodVert);
  auto r = run({"lower", "a.vert", "-D", "1X=2"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("1X"), std::string::npos) << r.err;
}

TEST_F(Cli, EqualSuffixesAreUsageError) {
  put("a.vert", kGoodVert);
  EXPECT_EQ(run({"lower", "a.vert", "--hi-suffix", "_x", "--lo-suffix", "_x"}).exit_code, 1);
  EXPECT_EQ(run({"lower", "a.vert", "--hi-suffix", ""}).exit_code, 1);
  EXPECT_EQ(run({"lower", "a.vert", "--lo-suffix", "a-b"}).exit_code, 1);
  EXPECT_EQ(run({"lower", "a.vert", "--hi-suffix", "__h"}).exit_code, 1);  // GLSL reserves "__"
}

TEST_F(Cli, ManifestToStdoutNeedsOutputFile) {
  put("a.vert", kGoodVert);
  EXPECT_EQ(run({"lower", "a.vert", "--manifest", "-"}).exit_code, 1);
}

TEST_F(Cli, UsageErrorWinsOverMissingInput) {
  auto r = run({"lower", "-", "--guard", "bogus"});
  EXPECT_EQ(r.exit_code, 1);
}

// ---------------------------------------------------------------- input (2)

TEST_F(Cli, MissingInputFileIsInputError) {
  auto r = run({"lower", "missing.vert", "-o", "out.vert"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(matches(r.err, R"(^missing\.vert(:\d+(:\d+)?)?: error: .*No such file or directory)")) << r.err;
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(dir.entries(), std::vector<std::string>{});
}

TEST_F(Cli, DirectoryAsInputIsInputError) {
  fs::create_directory(dir / "dir.vert");
  auto r = run({"lower", "dir.vert"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("dir.vert"), std::string::npos) << r.err;
}

TEST_F(Cli, SyntaxErrorIsInputErrorWithPosition) {  // [core] positions come from the core
  put("bad.vert", kBadVert);
  auto r = run({"lower", "bad.vert", "-o", "out.vert", "--manifest", "out.json"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(matches(r.err, R"(^bad\.vert:\d+:\d+: error: )")) << r.err;
  EXPECT_TRUE(matches(r.err, R"(^bad\.vert:5:\d+: error: )")) << "error should be on line 5:\n" << r.err;
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"bad.vert"}) << "no output, no temporary left behind";
}

TEST_F(Cli, SyntaxErrorOnStdinNamesStdin) {  // [core]
  auto r = run({"lower", "-", "-S", "vert"}, std::string(kBadVert));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(matches(r.err, R"(^<stdin>:\d+:\d+: error: )")) << r.err;
  EXPECT_EQ(r.out, "");
}

TEST_F(Cli, SyntaxErrorInSubdirectoryKeepsPathAsGiven) {  // [core]
  fs::create_directory(dir / "sub");
  put("sub/bad.frag.glsl", kBadVert);
  auto r = run({"lower", "sub/bad.frag.glsl", "-S", "vert"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(matches(r.err, "^" + escape_regex("sub/bad.frag.glsl") + R"(:\d+:\d+: error: )")) << r.err;
}

// ------------------------------------------------------- atomicity on error

TEST_F(Cli, FailedRunLeavesExistingOutputsUntouched) {
  put("bad.vert", kBadVert);
  const std::string old_out = "previous output\n\x01\x02 bytes", old_manifest = "{\"old\": true}";
  put("out.vert", old_out);
  put("out.json", old_manifest);
  auto r = run({"lower", "bad.vert", "-o", "out.vert", "--manifest", "out.json"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(read_file(dir / "out.vert"), old_out);
  EXPECT_EQ(read_file(dir / "out.json"), old_manifest);
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"bad.vert", "out.json", "out.vert"}));
}

TEST_F(Cli, MissingInputLeavesExistingOutputUntouched) {
  put("out.vert", "keep me");
  EXPECT_EQ(run({"lower", "missing.vert", "-o", "out.vert"}).exit_code, 2);
  EXPECT_EQ(read_file(dir / "out.vert"), "keep me");
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"out.vert"});
}

TEST_F(Cli, UnwritableOutputDirectoryIsInputError) {  // [core] must get past lowering first
  put("a.vert", kGoodVert);
  auto r = run({"lower", "a.vert", "-o", "nodir/out.vert"});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("nodir/out.vert"), std::string::npos) << r.err;
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"a.vert"});
}

TEST_F(Cli, OutputThatIsADirectoryIsInputError) {  // [core]
  put("a.vert", kGoodVert);
  fs::create_directory(dir / "out.vert");
  auto r = run({"lower", "a.vert", "-o", "out.vert"});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_TRUE(fs::is_directory(dir / "out.vert"));
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"a.vert", "out.vert"}));
}

TEST_F(Cli, ManifestFailureWritesNeitherFile) {  // [core]
  put("a.vert", kGoodVert);
  put("out.vert", "keep me");
  auto r = run({"lower", "a.vert", "-o", "out.vert", "--manifest", "nodir/m.json"});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(read_file(dir / "out.vert"), "keep me");
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"a.vert", "out.vert"}));
}

TEST_F(Cli, ReadOnlyDirectoryLeavesNoFiles) {  // [core]
  if (::geteuid() == 0) GTEST_SKIP() << "root ignores directory permissions";
  put("a.vert", kGoodVert);
  fs::create_directory(dir / "ro");
  fs::permissions(dir / "ro", fs::perms::owner_read | fs::perms::owner_exec);
  auto r = run({"lower", "a.vert", "-o", "ro/out.vert"});
  fs::permissions(dir / "ro", fs::perms::owner_all);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_TRUE(fs::is_empty(dir / "ro"));
}

// ---------------------------------------------------------------- success [core]

void expect_lowered(const std::string& glsl, const std::string& version_line) {
  EXPECT_NE(glsl.find(version_line), std::string::npos) << glsl;
  std::string code = strip_comments(glsl);
  EXPECT_FALSE(matches(code, R"(\b(double|dvec[234]|dmat[234](x[234])?)\b)")) << "doubles left:\n" << glsl;
}

TEST_F(Cli, LowersToFileAndManifest) {
  put("a.vert", kGoodVert);
  auto r = run({"lower", "a.vert", "-o", "out.vert", "--manifest", "out.json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, "");
  expect_lowered(read_file(dir / "out.vert"), "#version 300 es");
  auto m = nlohmann::json::parse(read_file(dir / "out.json"));
  EXPECT_EQ(m.value("stage", ""), "vert");
  EXPECT_EQ(m.value("target", ""), "es300");
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"a.vert", "out.json", "out.vert"}));
}

TEST_F(Cli, WritesStdoutWithoutOutputOrWithDash) {
  put("a.vert", kGoodVert);
  auto to_file = run({"lower", "a.vert", "-o", "out.vert"});
  ASSERT_EQ(to_file.exit_code, 0) << to_file.err;
  auto plain = run({"lower", "a.vert"});
  auto dash = run({"lower", "a.vert", "-o", "-"});
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  ASSERT_EQ(dash.exit_code, 0) << dash.err;
  EXPECT_EQ(plain.out, read_file(dir / "out.vert"));
  EXPECT_EQ(dash.out, plain.out);
}

TEST_F(Cli, ManifestToStdoutWithOutputFile) {
  put("a.vert", kGoodVert);
  auto r = run({"lower", "a.vert", "-o", "out.vert", "--manifest", "-"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out).value("stage", ""), "vert");
}

TEST_F(Cli, ReadsStdinWithStage) {
  auto r = run({"lower", "-", "-S", "vert"}, std::string(kGoodVert));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  expect_lowered(r.out, "#version 300 es");
}

TEST_F(Cli, TargetsSelectTheVersion) {
  put("a.vert", kGoodVert);
  const std::pair<const char*, const char*> cases[] = {
      {"es300", "#version 300 es"}, {"es310", "#version 310 es"}, {"es320", "#version 320 es"},
      {"glsl330", "#version 330"},  {"glsl450", "#version 450"},  {"es100", "#version 100"}};
  for (auto [target, version] : cases) {
    SCOPED_TRACE(target);
    auto r = run({"lower", "a.vert", "--target", target});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    expect_lowered(r.out, version);
  }
}

TEST_F(Cli, StageFromDoubleExtensionAndOverride) {
  put("a.vert.glsl", kGoodVert);
  auto r = run({"lower", "a.vert.glsl"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  put("really_vertex.frag", kGoodVert);  // gl_Position is vertex-only
  auto r2 = run({"lower", "really_vertex.frag", "-S", "vert"});
  EXPECT_EQ(r2.exit_code, 0) << r2.err;
}

TEST_F(Cli, DefinesReachThePreprocessor) {
  put("d.vert", kNeedsDefineVert);
  EXPECT_EQ(run({"lower", "d.vert"}).exit_code, 2);
  EXPECT_EQ(run({"lower", "d.vert", "-D", "OK"}).exit_code, 0) << last_err;
  EXPECT_EQ(run({"lower", "d.vert", "-DOK=1"}).exit_code, 0) << last_err;
  EXPECT_EQ(run({"lower", "d.vert", "-D", "OTHER", "-D", "OK", "-o", "o.vert"}).exit_code, 0) << last_err;
}

TEST_F(Cli, SuffixesAreUsed) {
  put("a.vert", kGoodVert);
  auto r = run({"lower", "a.vert", "--hi-suffix", "_H", "--lo-suffix", "_L"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("position_H"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("position_L"), std::string::npos) << r.out;
}

TEST_F(Cli, ReplacesExistingOutputKeepingItsMode) {
  put("a.vert", kGoodVert);
  put("out.vert", "old");
  fs::permissions(dir / "out.vert", fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  auto r = run({"lower", "a.vert", "-o", "out.vert"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(read_file(dir / "out.vert"), "old");
  EXPECT_EQ(fs::status(dir / "out.vert").permissions() & fs::perms::all,
            fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"a.vert", "out.vert"}));
}

TEST_F(Cli, WritesThroughSymlink) {
  put("a.vert", kGoodVert);
  put("real.vert", "old");
  fs::create_symlink("real.vert", dir / "link.vert");
  auto r = run({"lower", "a.vert", "-o", "link.vert"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::is_symlink(dir / "link.vert"));
  EXPECT_NE(read_file(dir / "real.vert"), "old");
}

}  // namespace
}  // namespace doublet::cli_test

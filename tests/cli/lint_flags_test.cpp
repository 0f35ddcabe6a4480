// `doublet lower -W...`: lint warnings on stderr, -Wno-NAME silences one, -Wno-all all,
// -WNAME turns one back on, -Werror fails the run without writing, unknown names are usage
// errors (docs/robustness.md "Lints").
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "test_support.hpp"

namespace doublet::cli_test {
namespace {
namespace fs = std::filesystem;

// Line 4: a float literal meets a double (col 25); line 5: float(double(...)) (col 13).
const char* const kShader = R"(#version 310 es
layout(local_size_x = 1) in;
layout(std430, binding = 0) buffer B { double o; double din; float fin; };
void main() { o = din * 0.1;
  float a = float(double(fin));
  o += double(a);
}
)";

class LintFlags : public ::testing::Test {
 protected:
  void SetUp() override { write_file(dir / "l.comp", kShader); }
  ProcessResult lower(std::vector<std::string> extra) {
    std::vector<std::string> args{"lower", "l.comp", "--target", "es310", "-o", "out.comp"};
    args.insert(args.end(), extra.begin(), extra.end());
    return run_process(DOUBLET_CLI_PATH, args, dir.path());
  }
  static bool has(const ProcessResult& r, const std::string& s) { return r.err.find(s) != std::string::npos; }
  ScratchDir dir;
};

TEST_F(LintFlags, WarningsByDefault) {
  ProcessResult r = lower({});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(has(r, "l.comp:4:25: warning: float literal 0.1 becomes 0.100000001490116 as a double; write 0.1lf"))
      << r.err;
  EXPECT_TRUE(has(r, "[-Wfloat-literal]")) << r.err;
  EXPECT_TRUE(has(r, "l.comp:5:13: warning: float(double(...)) converts to double and straight back")) << r.err;
  EXPECT_TRUE(fs::is_regular_file(dir / "out.comp"));
}

TEST_F(LintFlags, NoNameSilencesThatLintOnly) {
  ASSERT_EQ(lower({}).exit_code, 0);
  const std::string loud = read_file(dir / "out.comp");
  ProcessResult r = lower({"-Wno-float-literal"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_FALSE(has(r, "float-literal")) << r.err;
  EXPECT_TRUE(has(r, "[-Wwasted-double]")) << r.err;
  EXPECT_EQ(read_file(dir / "out.comp"), loud) << "silencing changes no code";
  r = lower({"-W", "no-wasted-double", "-Wno-float-literal"});
  EXPECT_EQ(r.err, "");
}

TEST_F(LintFlags, NoAllThenOneBack) {
  ProcessResult r = lower({"-Wno-all"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  r = lower({"-Wno-all", "-Wwasted-double"});
  EXPECT_TRUE(has(r, "[-Wwasted-double]")) << r.err;
  EXPECT_FALSE(has(r, "float-literal")) << r.err;
}

TEST_F(LintFlags, WerrorFailsWithoutWriting) {
  ProcessResult r = lower({"-Werror"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(has(r, "l.comp:4:25: error: float literal 0.1")) << r.err;
  EXPECT_FALSE(fs::exists(dir / "out.comp"));
  r = lower({"-Werror", "-Wno-error"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  r = lower({"-Werror", "-Wno-all"});
  EXPECT_EQ(r.exit_code, 0) << "silenced lints are not errors: " << r.err;
}

TEST_F(LintFlags, UnknownNameIsAUsageError) {
  ProcessResult r = lower({"-Wno-float-literals"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_TRUE(has(r, "-Wno-float-literals: unknown warning")) << r.err;
  EXPECT_FALSE(fs::exists(dir / "out.comp"));
}

}  // namespace
}  // namespace doublet::cli_test

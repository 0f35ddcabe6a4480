// Input size (docs/robustness.md, "Input size"): doublet::kMaxSourceBytes bounds the shader
// source with its #includes, in the library and in the CLI, which stops reading one byte past
// it. Before the limit, `/dev/zero`, `yes |` or a sparse 3 GB file was read whole (bad_alloc,
// exit 3, or the machine's memory).
#include <string>
#include <vector>

#include <unistd.h>

#include <gtest/gtest.h>

#include "doublet/doublet.hpp"
#include "test_support.hpp"

namespace doublet::cli_test {
namespace {
namespace fs = std::filesystem;

const char* const kShader = "#version 300 es\nuniform float u;\nvoid main() { gl_Position = vec4(u); }\n";
const char* const kLimitMessage = "is larger than the 64 MiB limit on shader source";

Options vertex_options() {
  Options o;
  o.stage = Stage::Vertex;
  o.file_name = "big.vert";
  return o;
}

void expect_size_refusal(const Result& r, const std::string& what) {
  EXPECT_FALSE(r.ok);
  ASSERT_FALSE(r.diagnostics.empty());
  const Diagnostic& d = r.diagnostics.front();
  EXPECT_EQ(format_diagnostic(d).rfind("big.vert:1:1: error: " + what + " " + kLimitMessage, 0), 0u)
      << format_diagnostic(d);
}

// A sparse file of `bytes` (no disk space used).
void make_sparse_file(const fs::path& p, std::uintmax_t bytes) {
  write_file(p, "");
  fs::resize_file(p, bytes);
}

TEST(InputLimit, IsSixtyFourMebibytes) { EXPECT_EQ(kMaxSourceBytes, 64u * 1024 * 1024); }

TEST(InputLimit, LibraryRefusesASourceOverTheLimit) {
  std::string source = kShader;
  source.resize(kMaxSourceBytes + 1, ' ');
  expect_size_refusal(lower(source, vertex_options()), "input");
}

// Hands out `size` bytes of blank lines for any #include.
class BlankIncluder : public Includer {
 public:
  explicit BlankIncluder(std::size_t size) : size_(size) {}
  std::optional<IncludeResult> include(std::string_view requested, std::string_view) override {
    return IncludeResult{std::string(requested), std::string(size_, '\n')};
  }

 private:
  std::size_t size_;
};

TEST(InputLimit, LibraryRefusesAnIncludeOverTheLimit) {
  BlankIncluder includer(kMaxSourceBytes + 1);
  Options o = vertex_options();
  o.includer = &includer;
  expect_size_refusal(lower("#version 300 es\n#include \"huge.glsl\"\nvoid main() {}\n", o), "#include \"huge.glsl\"");
}

TEST(InputLimit, TheSourceAndItsIncludesShareTheLimit) {
  // Each include alone fits; together with the main source they do not.
  BlankIncluder includer(kMaxSourceBytes / 2);
  Options o = vertex_options();
  o.includer = &includer;
  expect_size_refusal(lower("#version 300 es\n#include \"a.glsl\"\n#include \"b.glsl\"\nvoid main() {}\n", o),
                      "#include \"b.glsl\"");
}

TEST(InputLimit, LibraryRefusesAnIncludedFileOverTheLimitUnread) {
  ScratchDir dir;
  make_sparse_file(dir / "huge.glsl", std::uintmax_t{3} << 30);
  Options o = vertex_options();
  o.include_dirs = {dir.path().string()};
  expect_size_refusal(lower("#version 300 es\n#include \"huge.glsl\"\nvoid main() {}\n", o), "#include \"huge.glsl\"");
}

// The front end's line scans once used std::regex, which recursed once per character of a line:
// a line of 4 MiB (spaces, or a generated #define) overflowed the stack (SIGSEGV). The scanners
// are hand-written now (src/frontend/text_scan.*), so long lines are simply lowered.
TEST(LongLines, AreLoweredNotACrash) {
  const Result blanks = lower(std::string(kShader) + std::string(4u << 20, ' ') + "\n", vertex_options());
  EXPECT_TRUE(blanks.ok) << (blanks.diagnostics.empty() ? "" : format_diagnostic(blanks.diagnostics.front()));
  // A 4-million-digit number is glslang's own error at its line, not a stack overflow.
  const Result number = lower(std::string(kShader) + "#define T " + std::string(4u << 20, '1') + "\n", vertex_options());
  EXPECT_FALSE(number.ok);
  ASSERT_FALSE(number.diagnostics.empty());
  EXPECT_EQ(format_diagnostic(number.diagnostics.front()), "big.vert:4:1: error: numeric literal too long");
}

class InputLimitCli : public ::testing::Test {
 protected:
  ProcessResult run_shell(const std::string& command) {
    return run_process("/bin/sh", {"-c", command}, dir.path());
  }
  void expect_refusal(const ProcessResult& r, const std::string& file) {
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(r.err.rfind(file + ":1:1: error: input " + kLimitMessage, 0), 0u) << r.err;
    EXPECT_EQ(r.out, "");
  }
  const std::string cli = std::string("'") + DOUBLET_CLI_PATH + "'";
  ScratchDir dir;
};

// `plan` and `verify` scanned the user's lines with std::regex too (declaration lines, #version and
// #include of the native reference); a 4 MiB line would overflow the stack there as well.
TEST_F(InputLimitCli, PlanAndVerifyTakeFourMegabyteLines) {
  const std::string scenes = std::string(DOUBLET_SOURCE_DIR) + "/examples/scenes/";
  write_file(dir / "long.comp", read_file(scenes + "globe_rte.comp") + "\n" + std::string(4u << 20, ' ') + "\n");
  const std::string scene = " --scene '" + scenes + "globe_compute.scene.json'";
  const ProcessResult plan = run_shell("exec " + cli + " plan long.comp" + scene);
  EXPECT_EQ(plan.exit_code, 0) << plan.err;
  EXPECT_NE(plan.out.find("double flops per invocation"), std::string::npos) << plan.out;
  const ProcessResult verify = run_shell("exec " + cli + " verify long.comp --backend gles --samples 2" + scene);
  EXPECT_EQ(verify.exit_code, 0) << verify.err;
  EXPECT_NE(verify.out.find("result: PASS"), std::string::npos) << verify.out;
}

TEST_F(InputLimitCli, DevZeroIsRefused) {
  expect_refusal(run_shell("exec " + cli + " lower /dev/zero -S vert -o out.vert"), "/dev/zero");
  EXPECT_EQ(dir.entries(), std::vector<std::string>{});
}

TEST_F(InputLimitCli, EndlessStdinIsRefused) {
  expect_refusal(run_shell("yes | " + cli + " lower - -S vert"), "<stdin>");
}

TEST_F(InputLimitCli, SparseThreeGigabyteFileIsRefused) {
  make_sparse_file(dir / "sparse.vert", std::uintmax_t{3} << 30);
  write_file(dir / "out.vert", "previous output\n");
  expect_refusal(run_shell("exec " + cli + " lower sparse.vert -o out.vert"), "sparse.vert");
  EXPECT_EQ(read_file(dir / "out.vert"), "previous output\n");
}

TEST_F(InputLimitCli, OtherInputFilesAreBoundedToo) {
  make_sparse_file(dir / "sparse.vert", std::uintmax_t{3} << 30);
  write_file(dir / "a.vert", kShader);
  const std::string too_large = "larger than the 64 MiB limit on input files";
  for (const std::string& command : {cli + " verify sparse.vert", cli + " plan sparse.vert --scene none.json",
                                     cli + " lower a.vert --plan /dev/zero"}) {
    ProcessResult r = run_shell("exec " + command);
    EXPECT_EQ(r.exit_code, 2) << command << "\n" << r.err;
    EXPECT_NE(r.err.find(too_large), std::string::npos) << command << "\n" << r.err;
  }
}

TEST_F(InputLimitCli, AFourMebibyteLineIsLoweredNotACrash) {
  write_file(dir / "wide.vert", std::string(kShader) + std::string(4u << 20, ' ') + "\n");
  ProcessResult r = run_shell("exec " + cli + " lower wide.vert -o out.vert");
  EXPECT_EQ(r.exit_code, 0) << "139: the stack overflowed\n" << r.err;
  EXPECT_TRUE(fs::exists(dir / "out.vert"));
}

TEST_F(InputLimitCli, AShaderJustUnderTheLimitIsRead) {
  std::string source = kShader;  // then comment lines of 64 KiB: quick to parse
  while (source.size() < kMaxSourceBytes) source += "//" + std::string(65534 - 3, 'x') + "\n";
  source.resize(kMaxSourceBytes - 1);
  write_file(dir / "big.vert", source + "\n");
  ProcessResult r = run_shell("exec " + cli + " lower big.vert -o out.vert");
  EXPECT_EQ(r.exit_code, 0) << r.err.substr(0, 500);
  EXPECT_TRUE(fs::exists(dir / "out.vert"));
}

}  // namespace
}  // namespace doublet::cli_test

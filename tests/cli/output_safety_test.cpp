// Output safety (docs/robustness.md, "Outputs never destroy what is not theirs"): outputs
// that are not regular files are written in place, outputs that alias another output or an
// input are refused before anything is written, a 250-byte output name works, closed
// standard descriptors and SIGTERM mid-batch leave no stray or corrupted file.
#include <chrono>
#include <string>
#include <thread>
#include <vector>

#include <csignal>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "test_support.hpp"

namespace doublet::cli_test {
namespace {
namespace fs = std::filesystem;

// A vertex shader with a float-literal warning, so that a run prints on stderr.
const char* const kWarningVert = R"(#version 300 es
in dvec3 position;
uniform dvec3 eye;
void main() {
  double scale = 0.1;
  gl_Position = vec4(vec3((position - eye) * scale), 1.0);
}
)";

// Starts `program args...` in `cwd` with stdin from /dev/null; does not wait.
pid_t spawn(const std::string& program, const std::vector<std::string>& args, const fs::path& cwd) {
  ExecArgs exec_args(program, args);
  pid_t pid = ::fork();
  if (pid == 0) {
    if (::chdir(cwd.c_str()) != 0) ::_exit(126);
    ::execv(program.c_str(), exec_args.argv());
    ::_exit(127);
  }
  return pid;
}

int wait_status(pid_t pid) {
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  return status;
}

mode_t file_type(const fs::path& p) {
  struct stat st {};
  return ::lstat(p.c_str(), &st) == 0 ? (st.st_mode & S_IFMT) : 0;
}

class OutputSafety : public ::testing::Test {
 protected:
  void SetUp() override { write_file(dir / "a.vert", kWarningVert); }
  ProcessResult run(const std::vector<std::string>& args) { return run_process(DOUBLET_CLI_PATH, args, dir.path()); }
  ProcessResult run_shell(const std::string& command) { return run_process("/bin/sh", {"-c", command}, dir.path()); }
  void expect_refused(const ProcessResult& r, int exit_code, const std::string& message) {
    EXPECT_EQ(r.exit_code, exit_code) << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
  }
  const std::string cli = std::string("'") + DOUBLET_CLI_PATH + "'";
  ScratchDir dir;
};

// ------------------------------------------------------- outputs that are not regular files

TEST_F(OutputSafety, FifoAndDevNullAreWrittenInPlace) {
  ASSERT_EQ(::mkfifo((dir / "out.fifo").c_str(), 0644), 0);
  pid_t reader = spawn("/bin/sh", {"-c", "timeout 20 cat out.fifo > got.txt"}, dir.path());
  ProcessResult r = run({"lower", "a.vert", "-o", "out.fifo"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  wait_status(reader);
  ASSERT_EQ(file_type(dir / "out.fifo"), S_IFIFO) << "the FIFO was replaced by a file";
  EXPECT_NE(read_file(dir / "got.txt").find("void main()"), std::string::npos) << "the reader got nothing";

  // Only now that a FIFO is known to survive: the real /dev/null, three outputs at once.
  ASSERT_EQ(file_type("/dev/null"), S_IFCHR);
  r = run({"lower", "a.vert", "-o", "/dev/null", "--manifest", "/dev/null", "-MF", "/dev/null"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(file_type("/dev/null"), S_IFCHR) << "/dev/null is no longer a character device";
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"a.vert", "got.txt", "out.fifo"}));
}

// `-o /dev/stdout` with stdout a pipe, through a link of our own to /proc/self/fd/1 (what
// /dev/stdout is): before the fix the link was replaced by a regular file, which must never
// be tried on the machine's /dev/stdout.
TEST_F(OutputSafety, StdoutLinkIntoAPipe) {
  fs::create_symlink("/proc/self/fd/1", dir / "stdout");
  ProcessResult r = run_shell(cli + " lower a.vert -o stdout | cat > got.txt");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(read_file(dir / "got.txt").find("void main()"), std::string::npos) << r.err;
  EXPECT_EQ(file_type(dir / "stdout"), S_IFLNK) << "the link was replaced";
}

TEST_F(OutputSafety, OutputNameOf250Bytes) {
  const std::string name(246, 'x');
  ProcessResult r = run({"lower", "a.vert", "-o", name + ".vert"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"a.vert", name + ".vert"}));
}

// ------------------------------------------------------- outputs naming other files

TEST_F(OutputSafety, ManifestSpelledDifferentlyFromTheOutputIsRefused) {
  expect_refused(run({"lower", "a.vert", "-o", "out.vert", "--manifest", "./out.vert"}), 1,
                 "-o 'out.vert' and --manifest './out.vert' are the same file: give each output its own name");
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"a.vert"});
}

TEST_F(OutputSafety, DepfileNamingTheOutputIsRefused) {
  expect_refused(run({"lower", "a.vert", "-o", "out.vert", "-MF", "sub/../out.vert"}), 1, "are the same file");
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"a.vert"});
}

TEST_F(OutputSafety, DepfileNamingTheInputIsRefused) {
  expect_refused(run({"lower", "a.vert", "-o", "out.vert", "-MF", "a.vert"}), 1,
                 "-MF 'a.vert' is the input 'a.vert' itself: writing it would destroy the input");
  EXPECT_EQ(read_file(dir / "a.vert"), kWarningVert);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"a.vert"});
}

TEST_F(OutputSafety, OutputThroughASymlinkOrHardLinkToTheInputIsRefused) {
  fs::create_symlink("a.vert", dir / "soft.vert");
  fs::create_hard_link(dir / "a.vert", dir / "hard.vert");
  for (const char* alias : {"soft.vert", "hard.vert"}) {
    expect_refused(run({"lower", "a.vert", "-o", alias}), 1, "is the input 'a.vert' itself");
    expect_refused(run({"lower", "a.vert", "-o", "out.vert", "--manifest", alias}), 1, "is the input 'a.vert' itself");
  }
  EXPECT_EQ(read_file(dir / "a.vert"), kWarningVert);
  EXPECT_EQ(file_type(dir / "soft.vert"), S_IFLNK);
  EXPECT_FALSE(fs::exists(dir / "out.vert"));
}

TEST_F(OutputSafety, OutputNamingAnIncludedFileIsRefused) {
  write_file(dir / "scale.glsl", "double scale_of(double x) { return x * 2.0lf; }\n");
  write_file(dir / "i.vert", "#version 300 es\n#include \"scale.glsl\"\nin dvec3 p;\n"
                             "void main() { gl_Position = vec4(vec3(p * scale_of(1.0lf)), 1.0); }\n");
  expect_refused(run({"lower", "i.vert", "-o", "out.vert", "--manifest", "./scale.glsl"}), 2,
                 "the manifest './scale.glsl' is the #include'd file 'scale.glsl' itself");
  EXPECT_EQ(read_file(dir / "scale.glsl"), "double scale_of(double x) { return x * 2.0lf; }\n");
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"a.vert", "i.vert", "scale.glsl"}));
}

TEST_F(OutputSafety, BatchManifestCollidingWithAnotherInputsOutputIsRefused) {
  write_file(dir / "a.vert.json", kWarningVert);  // its output out/a.vert.json is a.vert's manifest
  expect_refused(run({"lower", "-S", "vert", "a.vert", "a.vert.json", "--out-dir", "out"}), 1,
                 "the manifest 'out/a.vert.json' of 'a.vert' and the output 'out/a.vert.json' of 'a.vert.json' are "
                 "the same file");
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"a.vert", "a.vert.json"}));
}

TEST_F(OutputSafety, BatchInputsWithOneBasenameAreRefused) {
  fs::create_directory(dir / "other");
  write_file(dir / "other/a.vert", kWarningVert);
  expect_refused(run({"lower", "a.vert", "other/a.vert", "--out-dir", "out"}), 1,
                 "the output 'out/a.vert' of 'a.vert' and the output 'out/a.vert' of 'other/a.vert' are the same file");
  EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST_F(OutputSafety, OutDirHoldingTheInputsIsRefused) {
  write_file(dir / "b.vert", kWarningVert);
  for (const char* out_dir : {".", "../" /* then the scratch dir's own name */}) {
    std::string d = out_dir == std::string(".") ? "." : "../" + dir.path().filename().string();
    expect_refused(run({"lower", "a.vert", "b.vert", "--out-dir", d}), 1,
                   "is the input 'a.vert' itself: writing it would destroy the input; use an --out-dir that holds no input");
  }
  EXPECT_EQ(read_file(dir / "a.vert"), kWarningVert);
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"a.vert", "b.vert"}));
}

// ------------------------------------------------------- the process around the outputs

// With stderr closed, the first file opened would get descriptor 2 and the warnings of
// other jobs (printed on "stderr") would land inside it.
TEST_F(OutputSafety, ClosedStderrKeepsWarningsOutOfOutputs) {
  // Timing decides where the warnings went (a job's files are open while another job's
  // warnings are printed), so many jobs at once: before the fix most runs had some.
  std::string inputs;
  for (int i = 0; i < 64; ++i) {
    write_file(dir / ("s" + std::to_string(i) + ".vert"), kWarningVert);
    inputs += " s" + std::to_string(i) + ".vert";
  }
  ProcessResult r = run_shell("exec " + cli + " lower" + inputs + " --out-dir out -j 8 2>&-");
  EXPECT_EQ(r.exit_code, 0);
  for (const auto& entry : fs::directory_iterator(dir / "out"))
    EXPECT_EQ(read_file(entry.path()).find("warning:"), std::string::npos) << entry.path() << " holds a warning";
}

bool has_hidden_file(const fs::path& d) {
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(d, ec))
    if (entry.path().filename().string()[0] == '.') return true;
  return false;
}

TEST_F(OutputSafety, SigtermMidBatchLeavesNoTemporaryFile) {
  // Big shaders, so that each output takes a while to write.
  std::string big = "#version 300 es\nin dvec3 position;\nuniform dvec3 eye;\nvoid main() {\n  dvec3 p = position;\n";
  for (int i = 0; i < 400; ++i) big += "  p = p * eye + dvec3(" + std::to_string(i) + ".5lf);\n";
  big += "  gl_Position = vec4(vec3(p), 1.0);\n}\n";
  std::vector<std::string> args{"lower", "--out-dir", "out", "-j", "2", "-MD"};
  for (int i = 0; i < 200; ++i) {
    write_file(dir / ("s" + std::to_string(i) + ".vert"), big);
    args.push_back("s" + std::to_string(i) + ".vert");
  }
  fs::create_directory(dir / "out");
  pid_t pid = spawn(DOUBLET_CLI_PATH, args, dir.path());
  // Strike while a temporary file exists (polled), so the signal lands mid-write.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!has_hidden_file(dir / "out") && std::chrono::steady_clock::now() < deadline) std::this_thread::yield();
  ::kill(pid, SIGTERM);
  int status = wait_status(pid);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM) << "status " << status;
  EXPECT_FALSE(has_hidden_file(dir / "out")) << "a temporary file survived SIGTERM";
}

}  // namespace
}  // namespace doublet::cli_test

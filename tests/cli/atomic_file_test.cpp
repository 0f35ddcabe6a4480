// Unit tests of the CLI's atomic file replacement (independent of the core), and of the
// guard on closed standard descriptors.
#include <csignal>

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "atomic_file.hpp"
#include "standard_fds.hpp"
#include "test_support.hpp"

namespace doublet::cli_test {
namespace {
namespace fs = std::filesystem;
using doublet::cli::AtomicFile;
using doublet::cli::write_file_atomically;

TEST(AtomicFile, CreatesFile) {
  ScratchDir d;
  EXPECT_EQ(write_file_atomically((d / "f").string(), "hello"), "");
  EXPECT_EQ(read_file(d / "f"), "hello");
  EXPECT_EQ(d.entries(), std::vector<std::string>{"f"});
}

TEST(AtomicFile, NewFileHonoursUmask) {
  ScratchDir d;
  mode_t old = ::umask(027);
  std::string err = write_file_atomically((d / "f").string(), "x");
  ::umask(old);
  ASSERT_EQ(err, "");
  EXPECT_EQ(fs::status(d / "f").permissions() & fs::perms::all,
            fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
}

TEST(AtomicFile, NothingVisibleBeforeCommit) {
  ScratchDir d;
  write_file(d / "f", "old");
  AtomicFile f;
  ASSERT_TRUE(f.prepare((d / "f").string(), "new")) << f.error();
  EXPECT_EQ(read_file(d / "f"), "old");
  ASSERT_TRUE(f.commit()) << f.error();
  EXPECT_EQ(read_file(d / "f"), "new");
  EXPECT_EQ(d.entries(), std::vector<std::string>{"f"});
}

TEST(AtomicFile, DestructorWithoutCommitLeavesOldFile) {
  ScratchDir d;
  write_file(d / "f", "old");
  {
    AtomicFile f;
    ASSERT_TRUE(f.prepare((d / "f").string(), "new"));
  }
  EXPECT_EQ(read_file(d / "f"), "old");
  EXPECT_EQ(d.entries(), std::vector<std::string>{"f"});
}

TEST(AtomicFile, DiscardWithoutExistingCreatesNothing) {
  ScratchDir d;
  AtomicFile f;
  ASSERT_TRUE(f.prepare((d / "f").string(), "new"));
  f.discard();
  EXPECT_EQ(d.entries(), std::vector<std::string>{});
  EXPECT_FALSE(f.commit());
}

TEST(AtomicFile, MissingDirectoryFails) {
  ScratchDir d;
  std::string err = write_file_atomically((d / "no" / "f").string(), "x");
  EXPECT_NE(err.find("No such file or directory"), std::string::npos) << err;
  EXPECT_EQ(d.entries(), std::vector<std::string>{});
}

TEST(AtomicFile, DirectoryDestinationFails) {
  ScratchDir d;
  fs::create_directory(d / "f");
  EXPECT_NE(write_file_atomically((d / "f").string(), "x"), "");
  EXPECT_TRUE(fs::is_directory(d / "f"));
  EXPECT_EQ(d.entries(), std::vector<std::string>{"f"});
}

TEST(AtomicFile, KeepsExistingMode) {
  ScratchDir d;
  write_file(d / "f", "old");
  fs::permissions(d / "f", fs::perms::owner_read | fs::perms::owner_write | fs::perms::others_read);
  ASSERT_EQ(write_file_atomically((d / "f").string(), "new"), "");
  EXPECT_EQ(fs::status(d / "f").permissions() & fs::perms::all,
            fs::perms::owner_read | fs::perms::owner_write | fs::perms::others_read);
}

TEST(AtomicFile, ReplacesSymlinkTarget) {
  ScratchDir d;
  write_file(d / "real", "old");
  fs::create_symlink("real", d / "link");
  ASSERT_EQ(write_file_atomically((d / "link").string(), "new"), "");
  EXPECT_TRUE(fs::is_symlink(d / "link"));
  EXPECT_EQ(read_file(d / "real"), "new");
}

TEST(AtomicFile, RelativePathInCurrentDirectory) {
  ScratchDir d;
  fs::path old = fs::current_path();
  fs::current_path(d.path());
  std::string err = write_file_atomically("f", "x");
  fs::current_path(old);
  EXPECT_EQ(err, "");
  EXPECT_EQ(read_file(d / "f"), "x");
}

TEST(AtomicFile, MovedFromOwnsNothing) {
  ScratchDir d;
  AtomicFile a;
  ASSERT_TRUE(a.prepare((d / "f").string(), "x"));
  AtomicFile b(std::move(a));
  EXPECT_FALSE(a.commit());
  EXPECT_TRUE(b.commit()) << b.error();
  EXPECT_EQ(read_file(d / "f"), "x");
}

TEST(AtomicFile, ShortTemporaryNameFitsBesideA255ByteName) {
  ScratchDir d;
  const std::string name(255, 'n');  // NAME_MAX: ".NAME.tmp.XXXXXX" would not fit
  EXPECT_EQ(write_file_atomically((d / name).string(), "x"), "");
  EXPECT_EQ(d.entries(), std::vector<std::string>{name});
}

TEST(AtomicFile, FifoIsWrittenInPlace) {
  ScratchDir d;
  ASSERT_EQ(::mkfifo((d / "fifo").c_str(), 0644), 0);
  int reader = ::open((d / "fifo").c_str(), O_RDONLY | O_NONBLOCK);  // so that opening for writing does not block
  ASSERT_GE(reader, 0);
  EXPECT_EQ(write_file_atomically((d / "fifo").string(), "through"), "");
  char buf[16] = {};
  EXPECT_EQ(::read(reader, buf, sizeof buf), 7);
  EXPECT_EQ(std::string(buf), "through");
  ::close(reader);
  struct stat st {};
  ASSERT_EQ(::lstat((d / "fifo").c_str(), &st), 0);
  EXPECT_TRUE(S_ISFIFO(st.st_mode));
  EXPECT_EQ(d.entries(), std::vector<std::string>{"fifo"});
}

TEST(AtomicFile, NewFileUnderDevIsCreated) {  // /dev/shm is a place for files too
  if (!fs::is_directory("/dev/shm")) GTEST_SKIP() << "no /dev/shm";
  const std::string path = "/dev/shm/doublet-atomic-test-" + std::to_string(::getpid());
  EXPECT_EQ(write_file_atomically(path, "x"), "");
  EXPECT_EQ(read_file(path), "x");
  fs::remove(path);
}

// Runs `body` in a child process and returns its wait status.
template <typename Body>
int in_child(Body body) {
  pid_t pid = ::fork();
  if (pid == 0) {
    body();
    ::_exit(0);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  return status;
}

TEST(AtomicFile, FatalSignalRemovesTemporaryFiles) {
  ScratchDir d;
  int status = in_child([&] {
    doublet::cli::remove_temp_files_on_fatal_signals();
    AtomicFile a, b;
    if (!a.prepare((d / "a").string(), "x") || !b.prepare((d / "b").string(), "y")) ::_exit(1);
    ::raise(SIGTERM);
    ::_exit(2);  // not reached: the signal ends the process
  });
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM) << "status " << status;
  EXPECT_EQ(d.entries(), std::vector<std::string>{}) << "a temporary file survived SIGTERM";
}

TEST(AtomicFile, IgnoredSignalStaysIgnored) {  // nohup, or `doublet ... &` in a script
  ScratchDir d;
  int status = in_child([&] {
    ::signal(SIGHUP, SIG_IGN);
    doublet::cli::remove_temp_files_on_fatal_signals();
    ::raise(SIGHUP);
    ::_exit(write_file_atomically((d / "f").string(), "x").empty() ? 0 : 1);
  });
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "status " << status;
  EXPECT_EQ(read_file(d / "f"), "x");
}

TEST(StandardFds, ClosedOnesAreOpenedOnDevNull) {
  int status = in_child([] {
    ::close(0);
    ::close(2);
    doublet::cli::open_closed_standard_fds();
    int fd = ::open("/dev/zero", O_RDONLY);  // must not become stdin or stderr
    ::_exit(fd > 2 && ::fcntl(0, F_GETFD) != -1 && ::fcntl(2, F_GETFD) != -1 ? 0 : 1);
  });
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "status " << status;
}

}  // namespace
}  // namespace doublet::cli_test

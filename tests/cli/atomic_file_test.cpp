// Unit tests of the CLI's atomic file replacement (independent of the core).
#include <sys/stat.h>

#include <gtest/gtest.h>

#include "atomic_file.hpp"
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

}  // namespace
}  // namespace doublet::cli_test

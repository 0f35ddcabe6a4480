// Helpers for the CLI tests: run a program with captured I/O, scratch
// directories and small file utilities.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace doublet::cli_test {

struct ProcessResult {
  int exit_code = -1;  // -1 when the process did not exit normally
  std::string out;
  std::string err;
};

// Runs `program args...` in `cwd` with `stdin_data` on stdin (/dev/null when
// nullopt) and returns its exit status, stdout and stderr.
// `program` followed by `args`, as the null-terminated argument array execv takes (the strings
// stay owned here, so the object must outlive the exec).
class ExecArgs {
 public:
  ExecArgs(const std::string& program, const std::vector<std::string>& args);
  ExecArgs(const ExecArgs&) = delete;
  ExecArgs& operator=(const ExecArgs&) = delete;
  char* const* argv() { return pointers_.data(); }

 private:
  std::vector<std::string> strings_;
  std::vector<char*> pointers_;
};

ProcessResult run_process(const std::string& program, const std::vector<std::string>& args,
                          const std::filesystem::path& cwd,
                          const std::optional<std::string>& stdin_data = std::nullopt);

// A fresh directory, removed with its contents on destruction.
class ScratchDir {
 public:
  ScratchDir();
  ~ScratchDir();
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }
  // Names of all entries (recursively, relative), sorted.
  std::vector<std::string> entries() const;

 private:
  std::filesystem::path path_;
};

std::string read_file(const std::filesystem::path& p);
void write_file(const std::filesystem::path& p, const std::string& contents);
// The text with // and /* */ comments removed (for token checks).
std::string strip_comments(const std::string& glsl);

}  // namespace doublet::cli_test

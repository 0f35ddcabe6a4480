#include "test_support.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace doublet::cli_test {
namespace fs = std::filesystem;

ExecArgs::ExecArgs(const std::string& program, const std::vector<std::string>& args) : strings_{program} {
  strings_.insert(strings_.end(), args.begin(), args.end());
  for (std::string& s : strings_) pointers_.push_back(s.data());
  pointers_.push_back(nullptr);
}

ProcessResult run_process(const std::string& program, const std::vector<std::string>& args,
                          const fs::path& cwd, const std::optional<std::string>& stdin_data) {
  // Route everything through files: no pipe deadlocks, no threads.
  ScratchDir io;
  fs::path in = io / "stdin", out = io / "stdout", err = io / "stderr";
  write_file(in, stdin_data.value_or(""));

  ExecArgs exec_args(program, args);

  pid_t pid = ::fork();
  if (pid < 0) throw std::runtime_error(std::string("fork: ") + std::strerror(errno));
  if (pid == 0) {
    int fin = stdin_data ? ::open(in.c_str(), O_RDONLY) : ::open("/dev/null", O_RDONLY);
    int fout = ::open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    int ferr = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fin < 0 || fout < 0 || ferr < 0 || ::dup2(fin, 0) < 0 || ::dup2(fout, 1) < 0 ||
        ::dup2(ferr, 2) < 0 || ::chdir(cwd.c_str()) != 0)
      ::_exit(126);
    ::execv(program.c_str(), exec_args.argv());
    ::_exit(127);
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) throw std::runtime_error(std::string("waitpid: ") + std::strerror(errno));

  ProcessResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = read_file(out);
  r.err = read_file(err);
  return r;
}

ScratchDir::ScratchDir() {
  std::string templ = (fs::temp_directory_path() / "doublet-cli-test-XXXXXX").string();
  if (::mkdtemp(templ.data()) == nullptr)
    throw std::runtime_error(std::string("mkdtemp: ") + std::strerror(errno));
  path_ = templ;
}

ScratchDir::~ScratchDir() {
  std::error_code ec;
  fs::remove_all(path_, ec);
}

std::vector<std::string> ScratchDir::entries() const {
  std::vector<std::string> names;
  for (const auto& e : fs::recursive_directory_iterator(path_))
    names.push_back(fs::relative(e.path(), path_).string());
  std::sort(names.begin(), names.end());
  return names;
}

std::string read_file(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  if (!f) throw std::runtime_error("cannot read " + p.string());
  std::ostringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

void write_file(const fs::path& p, const std::string& contents) {
  std::ofstream f(p, std::ios::binary | std::ios::trunc);
  f << contents;
  if (!f) throw std::runtime_error("cannot write " + p.string());
}

std::string strip_comments(const std::string& s) {
  std::string out;
  for (size_t i = 0; i < s.size();) {
    if (s.compare(i, 2, "//") == 0) {
      while (i < s.size() && s[i] != '\n') ++i;
    } else if (s.compare(i, 2, "/*") == 0) {
      size_t end = s.find("*/", i + 2);
      i = end == std::string::npos ? s.size() : end + 2;
      out += ' ';
    } else {
      out += s[i++];
    }
  }
  return out;
}

}  // namespace doublet::cli_test

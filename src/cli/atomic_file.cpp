#include "atomic_file.hpp"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <system_error>
#include <utility>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace doublet::cli {
namespace fs = std::filesystem;

namespace {

std::string errno_message(int err) { return std::strerror(err); }

// Mode for the new file: keep an existing destination's permissions,
// otherwise what open(O_CREAT, 0666) would give under the current umask.
mode_t target_mode(const std::string& real_path) {
  struct stat st {};
  if (::stat(real_path.c_str(), &st) == 0 && S_ISREG(st.st_mode)) return st.st_mode & 07777;
  mode_t mask = ::umask(0);
  ::umask(mask);
  return 0666 & ~mask;
}

bool write_all(int fd, std::string_view data, int& err) {
  while (!data.empty()) {
    ssize_t n = ::write(fd, data.data(), data.size());
    if (n < 0) {
      if (errno == EINTR) continue;
      err = errno;
      return false;
    }
    data.remove_prefix(static_cast<size_t>(n));
  }
  return true;
}

}  // namespace

AtomicFile::AtomicFile(AtomicFile&& other) noexcept
    : path_(std::move(other.path_)),
      real_path_(std::move(other.real_path_)),
      temp_path_(std::exchange(other.temp_path_, {})),
      error_(std::move(other.error_)) {}

AtomicFile& AtomicFile::operator=(AtomicFile&& other) noexcept {
  if (this != &other) {
    discard();
    path_ = std::move(other.path_);
    real_path_ = std::move(other.real_path_);
    temp_path_ = std::exchange(other.temp_path_, {});
    error_ = std::move(other.error_);
  }
  return *this;
}

AtomicFile::~AtomicFile() { discard(); }

void AtomicFile::discard() noexcept {
  if (!temp_path_.empty()) {
    ::unlink(temp_path_.c_str());
    temp_path_.clear();
  }
}

bool AtomicFile::prepare(const std::string& path, std::string_view contents) {
  discard();
  path_ = path;
  error_.clear();
  if (path.empty()) {
    error_ = "cannot write '': empty file name";
    return false;
  }

  // Replace what a symlink points to rather than the link itself.
  real_path_ = path;
  std::error_code ec;
  if (fs::is_symlink(fs::symlink_status(path, ec))) {
    fs::path resolved = fs::weakly_canonical(path, ec);
    if (!ec) real_path_ = resolved.string();
  }
  if (fs::is_directory(real_path_, ec)) {
    error_ = "cannot write '" + path + "': " + errno_message(EISDIR);
    return false;
  }

  fs::path dir = fs::path(real_path_).parent_path();
  std::string name = fs::path(real_path_).filename().string();
  std::string templ = (dir.empty() ? fs::path(".") : dir).string() + "/." + name + ".tmp.XXXXXX";
  std::vector<char> buf(templ.begin(), templ.end());
  buf.push_back('\0');

  int fd = ::mkstemp(buf.data());
  if (fd < 0) {
    error_ = "cannot write '" + path + "': " + errno_message(errno);
    return false;
  }
  temp_path_.assign(buf.data());

  int err = 0;
  bool ok = write_all(fd, contents, err);
  if (ok && ::fchmod(fd, target_mode(real_path_)) != 0) ok = false, err = errno;
  if (ok && ::fsync(fd) != 0) ok = false, err = errno;
  if (::close(fd) != 0 && ok) ok = false, err = errno;
  if (!ok) {
    error_ = "cannot write '" + path + "': " + errno_message(err);
    discard();
    return false;
  }
  return true;
}

bool AtomicFile::commit() {
  if (temp_path_.empty()) {
    if (error_.empty()) error_ = "cannot write '" + path_ + "': nothing prepared";
    return false;
  }
  if (::rename(temp_path_.c_str(), real_path_.c_str()) != 0) {
    error_ = "cannot write '" + path_ + "': " + errno_message(errno);
    discard();
    return false;
  }
  temp_path_.clear();
  return true;
}

std::string write_file_atomically(const std::string& path, std::string_view contents) {
  AtomicFile file;
  if (!file.prepare(path, contents) || !file.commit()) return file.error();
  return {};
}

}  // namespace doublet::cli

#include "atomic_file.hpp"

#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <system_error>
#include <utility>
#include <vector>

#include <fcntl.h>
#include <pthread.h>
#include <sys/stat.h>
#include <unistd.h>

namespace doublet::cli {
namespace fs = std::filesystem;

namespace {

constexpr int kFatalSignals[] = {SIGINT, SIGTERM, SIGHUP};

// Live temporary files, for the fatal-signal handler. A handler may only call
// async-signal-safe functions, so the table is fixed and lock-free: a slot holds
// a heap copy of one path. Whoever exchanges a non-null pointer out owns it: the
// handler (which unlinks it and never frees it: the process is dying) or the
// AtomicFile giving the slot up (which frees it).
constexpr std::size_t kTempSlots = 1024;  // 3 files in each of 341 parallel lowering jobs
std::array<std::atomic<char*>, kTempSlots> g_temp_files{};
static_assert(std::atomic<char*>::is_always_lock_free);

// The slot now listing `path`, or kTempSlots when the table is full (the file is
// then not removed by a signal; it is still removed by discard()).
std::size_t list_temp_file(const std::string& path) {
  char* copy = new char[path.size() + 1];
  std::memcpy(copy, path.c_str(), path.size() + 1);
  for (std::size_t i = 0; i < kTempSlots; ++i) {
    char* empty = nullptr;
    if (g_temp_files[i].compare_exchange_strong(empty, copy)) return i;
  }
  delete[] copy;
  return kTempSlots;
}

void unlist_temp_file(std::size_t slot) {
  if (slot < kTempSlots) delete[] g_temp_files[slot].exchange(nullptr);
}

// The handler runs on one thread while the others go on: a job on another thread may be
// between mkstemp() and listing its file. So a creator announces itself (g_creating)
// before it looks at g_dying, and the handler sets g_dying before it waits for the
// creators to finish: with sequentially consistent atomics, either the creator sees
// g_dying and creates nothing, or the handler sees the creator and waits for its listing.
std::atomic<bool> g_dying{false};
std::atomic<int> g_creating{0};
static_assert(std::atomic<bool>::is_always_lock_free && std::atomic<int>::is_always_lock_free);

extern "C" void remove_temp_files_and_die(int sig) {
  g_dying.store(true);
  while (g_creating.load() != 0) {
  }
  for (auto& slot : g_temp_files)
    if (char* path = slot.exchange(nullptr)) ::unlink(path);
  ::signal(sig, SIG_DFL);
  ::raise(sig);  // delivered when this handler returns: the process ends as the signal says
}

// Blocks the fatal signals on this thread for its lifetime, so that a temporary
// file cannot be created and then missed by the handler before it is listed.
class FatalSignalsBlocked {
 public:
  FatalSignalsBlocked() {
    sigset_t set;
    sigemptyset(&set);
    for (int sig : kFatalSignals) sigaddset(&set, sig);
    pthread_sigmask(SIG_BLOCK, &set, &old_);
  }
  ~FatalSignalsBlocked() { pthread_sigmask(SIG_SETMASK, &old_, nullptr); }
  FatalSignalsBlocked(const FatalSignalsBlocked&) = delete;
  FatalSignalsBlocked& operator=(const FatalSignalsBlocked&) = delete;

 private:
  sigset_t old_;
};

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

// An existing FIFO or device is written in place: renaming a regular file over /dev/null
// (or a FIFO someone reads) would destroy what is not ours. So is an existing regular file
// reached through /dev/ or /proc/ (/dev/stdout redirected to a file): it is a descriptor's.
// A new file, wherever it is, is created by the rename.
bool written_in_place(const std::string& path, const std::string& real_path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return false;
  if (!S_ISREG(st.st_mode)) return true;
  for (const std::string* p : {&path, &real_path})
    if (p->rfind("/dev/", 0) == 0 || p->rfind("/proc/", 0) == 0) return true;
  return false;
}

}  // namespace

void remove_temp_files_on_fatal_signals() {
  for (int sig : kFatalSignals) {
    struct sigaction old {};
    if (::sigaction(sig, nullptr, &old) != 0 || old.sa_handler == SIG_IGN) continue;  // nohup, `cmd &`
    struct sigaction action {};
    action.sa_handler = remove_temp_files_and_die;
    sigemptyset(&action.sa_mask);
    for (int other : kFatalSignals) sigaddset(&action.sa_mask, other);
    ::sigaction(sig, &action, nullptr);
  }
}

AtomicFile::AtomicFile(AtomicFile&& other) noexcept
    : path_(std::move(other.path_)),
      real_path_(std::move(other.real_path_)),
      temp_path_(std::exchange(other.temp_path_, {})),
      temp_slot_(other.temp_slot_),
      in_place_(std::exchange(other.in_place_, false)),
      pending_(std::move(other.pending_)),
      error_(std::move(other.error_)) {}

AtomicFile& AtomicFile::operator=(AtomicFile&& other) noexcept {
  if (this != &other) {
    discard();
    path_ = std::move(other.path_);
    real_path_ = std::move(other.real_path_);
    temp_path_ = std::exchange(other.temp_path_, {});
    temp_slot_ = other.temp_slot_;
    in_place_ = std::exchange(other.in_place_, false);
    pending_ = std::move(other.pending_);
    error_ = std::move(other.error_);
  }
  return *this;
}

AtomicFile::~AtomicFile() { discard(); }

void AtomicFile::discard() noexcept {
  if (!temp_path_.empty()) {
    ::unlink(temp_path_.c_str());
    unlist_temp_file(temp_slot_);
    temp_path_.clear();
  }
  in_place_ = false;
  pending_.clear();
}

void AtomicFile::fail(int err) {
  error_ = "cannot write '" + path_ + "': " + errno_message(err);
  discard();
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
    fail(EISDIR);
    return false;
  }
  return written_in_place(path, real_path_) ? prepare_in_place(contents) : prepare_temporary(contents);
}

bool AtomicFile::prepare_in_place(std::string_view contents) {
  if (::access(path_.c_str(), W_OK) != 0) {
    fail(errno);
    return false;
  }
  in_place_ = true;
  pending_.assign(contents);
  return true;
}

bool AtomicFile::prepare_temporary(std::string_view contents) {
  fs::path dir = fs::path(real_path_).parent_path();
  std::string templ = (dir.empty() ? fs::path(".") : dir).string() + "/.dbl-XXXXXX";
  int fd = -1;
  {
    FatalSignalsBlocked blocked;  // the handler cannot run here, on this thread, and wait for itself
    g_creating.fetch_add(1);
    if (g_dying.load()) {
      g_creating.fetch_sub(1);
      for (;;) ::pause();  // the handler, on another thread, is ending the process
    }
    fd = ::mkstemp(templ.data());
    if (fd >= 0) {
      temp_path_ = templ;
      temp_slot_ = list_temp_file(temp_path_);
    }
    g_creating.fetch_sub(1);
    if (fd < 0) {
      fail(errno);
      return false;
    }
  }

  int err = 0;
  bool ok = write_all(fd, contents, err);
  if (ok && ::fchmod(fd, target_mode(real_path_)) != 0) ok = false, err = errno;
  if (ok && ::fsync(fd) != 0) ok = false, err = errno;
  if (::close(fd) != 0 && ok) ok = false, err = errno;
  if (!ok) {
    fail(err);
    return false;
  }
  return true;
}

bool AtomicFile::commit_in_place() {
  int fd = ::open(path_.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC | O_NOCTTY);
  int err = 0;
  bool ok = fd >= 0 && write_all(fd, pending_, err);
  if (fd < 0) err = errno;
  if (fd >= 0 && ::close(fd) != 0 && ok) ok = false, err = errno;
  in_place_ = false;
  pending_.clear();
  if (!ok) error_ = "cannot write '" + path_ + "': " + errno_message(err);
  return ok;
}

bool AtomicFile::commit() {
  if (in_place_) return commit_in_place();
  if (temp_path_.empty()) {
    if (error_.empty()) error_ = "cannot write '" + path_ + "': nothing prepared";
    return false;
  }
  if (::rename(temp_path_.c_str(), real_path_.c_str()) != 0) {
    fail(errno);
    return false;
  }
  unlist_temp_file(temp_slot_);
  temp_path_.clear();
  return true;
}

std::string write_file_atomically(const std::string& path, std::string_view contents) {
  AtomicFile file;
  if (!file.prepare(path, contents) || !file.commit()) return file.error();
  return {};
}

}  // namespace doublet::cli

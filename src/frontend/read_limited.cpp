#include "frontend/read_limited.hpp"

#include "doublet/doublet.hpp"

#include <cerrno>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace doublet::frontend {

ReadResult read_limited(int fd, std::size_t limit, std::string& out) {
  struct stat st {};
  if (::fstat(fd, &st) == 0) {
    if (S_ISDIR(st.st_mode)) return {ReadStatus::Failed, EISDIR};
    // A regular file's size is known: no need to read a sparse 3 GB file to refuse it.
    if (S_ISREG(st.st_mode) && static_cast<unsigned long long>(st.st_size) > limit) return {ReadStatus::TooLarge, 0};
  }
  const std::size_t start = out.size();
  char buf[1 << 16];
  for (;;) {
    const std::size_t room = limit + 1 - (out.size() - start);  // one byte past the limit tells "too large"
    ssize_t n = ::read(fd, buf, room < sizeof buf ? room : sizeof buf);
    if (n == 0) return {};
    if (n < 0) {
      if (errno == EINTR) continue;
      return {ReadStatus::Failed, errno};
    }
    out.append(buf, static_cast<std::size_t>(n));
    if (out.size() - start > limit) return {ReadStatus::TooLarge, 0};
  }
}

ReadResult read_file_limited(const std::string& path, std::size_t limit, std::string& out) {
  int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return {ReadStatus::Failed, errno};
  ReadResult r = read_limited(fd, limit, out);
  ::close(fd);
  return r;
}

std::string source_too_large_message(const std::string& what) {
  static_assert(kMaxSourceBytes % (1 << 20) == 0, "the message says MiB");
  return what + " is larger than the " + std::to_string(kMaxSourceBytes >> 20) +
         " MiB limit on shader source (the shader with all its #includes); is it the right file?";
}

}  // namespace doublet::frontend

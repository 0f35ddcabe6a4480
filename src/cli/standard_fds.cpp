#include "standard_fds.hpp"

#include <cerrno>

#include <fcntl.h>
#include <unistd.h>

namespace doublet::cli {

void open_closed_standard_fds() {
  for (int fd = 0; fd <= 2; ++fd) {
    if (::fcntl(fd, F_GETFD) != -1 || errno != EBADF) continue;
    // open() returns the lowest free descriptor: `fd` itself, as every lower one is open.
    const int opened = ::open("/dev/null", fd == 0 ? O_RDONLY : O_WRONLY);
    if (opened >= 0 && opened != fd) ::close(opened);  // cannot happen; never leak one
  }
}

}  // namespace doublet::cli

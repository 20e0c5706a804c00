#include "sys/process.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>

namespace tumble::sys {

void set_up_process() {
  for (int stream = 0; stream <= 2; ++stream) {
    if (::fcntl(stream, F_GETFD) == -1 && errno == EBADF) {
      // open() returns the lowest free number: this one, as the lower ones are open.
      const int opened = ::open("/dev/null", stream == 0 ? O_RDONLY : O_WRONLY);
      if (opened != stream && opened >= 0) ::close(opened);
    }
  }
  std::signal(SIGXFSZ, SIG_IGN);
  std::signal(SIGPIPE, SIG_IGN);
}

}  // namespace tumble::sys

// An output the command could not write (a full disk, a device that refuses it): exit code 1
// with one line naming the flag and the reason, not an internal error. Standard output whose
// reader has gone (`mdrsim sweep | head`) is no failure: the command ends quietly.
#pragma once

#include <poll.h>
#include <unistd.h>

#include <stdexcept>

namespace mdrsim::cli {

class WriteError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Standard output's reader closed it: main() exits 141 (128 + SIGPIPE) with no message, as
/// `seq 1 1000000 | head` ends, and as SIGINT and SIGTERM give 130 and 143.
class StandardOutputClosed : public WriteError {
 public:
  StandardOutputClosed() : WriteError("standard output closed by its reader") {}
};

/// Whether standard output is a pipe or socket whose reader has gone: a write there fails with
/// EPIPE, and poll() says POLLERR (a stream's failed flush leaves no reliable errno).
inline bool standard_output_reader_gone() {
  pollfd fd{STDOUT_FILENO, POLLOUT, 0};
  return poll(&fd, 1, 0) == 1 && (fd.revents & (POLLERR | POLLHUP)) != 0;
}

}  // namespace mdrsim::cli

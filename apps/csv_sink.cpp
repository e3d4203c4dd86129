// The --csv target written line by line in place.
#include "apps/csv_sink.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fmt/format.h>

#include <cerrno>

#include "apps/write_error.hpp"
#include "engine/base/text.hpp"
#include "engine/scene/scene_error.hpp"
#include "engine/sweep/usage_error.hpp"

namespace mdrsim::cli {

CsvSink::~CsvSink() {
  if (fd_ > 1) close(fd_);
}

void CsvSink::open_fresh(const std::string& head) {
  if (path_ == "-") {
    fd_ = STDOUT_FILENO;
  } else {
    struct stat st {};
    if (stat(path_.c_str(), &st) == 0 && S_ISDIR(st.st_mode)) cannot_write("it is a directory");
    fd_ = open(path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (fd_ < 0) cannot_write(system_reason(errno));
  }
  write_all(head);
}

void CsvSink::open_resumed(std::uint64_t keep) {
  fd_ = open(path_.c_str(), O_WRONLY | O_CLOEXEC);
  if (fd_ < 0) cannot_write(system_reason(errno));
  if (ftruncate(fd_, static_cast<off_t>(keep)) != 0 || lseek(fd_, 0, SEEK_END) < 0) {
    cannot_write(system_reason(errno));
  }
}

void CsvSink::write_all(std::string_view text) {
  while (!text.empty()) {
    const ssize_t n = write(fd_, text.data(), text.size());
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      if (n < 0 && errno == EPIPE && path_ == "-") throw StandardOutputClosed();
      throw WriteError(path_ == "-" ? fmt::format("--csv: writing standard output failed ({})",
                                                  system_reason(errno))
                                    : fmt::format("--csv: writing '{}' failed ({})",
                                                  printable(path_), system_reason(errno)));
    }
    text.remove_prefix(static_cast<std::size_t>(n));
  }
}

void CsvSink::cannot_write(const std::string& why) const {
  throw UsageError(fmt::format("--csv: cannot write '{}' ({})", printable(path_), why));
}

}  // namespace mdrsim::cli

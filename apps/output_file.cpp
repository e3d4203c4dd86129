// Outputs appear whole or not at all: written beside the target, renamed when complete.
#include "apps/output_file.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cstring>
#include <iostream>

#include "apps/usage_error.hpp"

namespace mdrsim::cli {

OutputFile::OutputFile(std::string flag, const std::string& path)
    : flag_(std::move(flag)), to_stdout_(path == "-"), path_(path) {
  if (to_stdout_) return;
  if (path.empty()) throw UsageError(fmt::format("{}: needs a file path or -", flag_));
  std::error_code ec;
  if (std::filesystem::is_directory(path_, ec)) {
    throw UsageError(fmt::format("{}: cannot write '{}' (it is a directory)", flag_, path));
  }
  partial_ = path_;
  partial_ += ".partial";
  file_.open(partial_, std::ios::binary | std::ios::trunc);
  if (!file_) {
    throw UsageError(fmt::format("{}: cannot write '{}' ({})", flag_, path, std::strerror(errno)));
  }
}

OutputFile::~OutputFile() {
  if (!to_stdout_ && !committed_) {
    file_.close();
    std::error_code ec;
    std::filesystem::remove(partial_, ec);
  }
}

std::ostream& OutputFile::stream() { return to_stdout_ ? std::cout : file_; }

void OutputFile::commit() {
  if (to_stdout_) {
    std::cout.flush();
    return;
  }
  file_.close();
  if (!file_)
    throw std::runtime_error(fmt::format("{}: writing '{}' failed", flag_, path_.string()));
  std::filesystem::rename(partial_, path_);
  committed_ = true;
}

}  // namespace mdrsim::cli
